// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/interrupt.h"

#include <csignal>
#include <fcntl.h>
#include <initializer_list>
#include <unistd.h>

#include <QSocketNotifier>

namespace Toffee::Cli {

namespace {

volatile std::sig_atomic_t g_depth = 0; // inside a critical section
volatile std::sig_atomic_t g_pending = 0; // the signal that came meanwhile
volatile std::sig_atomic_t g_hooked = 0; // an InterruptHook takes the first signal
int g_hookPipe[2] = { -1, -1 }; // the handler writes the signal here; the event loop reads it

// Only what is safe in a signal handler: write(2) and _exit(2).
[[noreturn]] void stop(int signal)
{
    static const char kSaid[] = "toffee-cli: interrupted; what the machine measured before now is kept.\n";
    (void)!::write(STDERR_FILENO, kSaid, sizeof kSaid - 1);
    ::_exit(128 + signal);
}

void onSignal(int signal)
{
    if (g_hooked != 0 && g_hookPipe[1] >= 0) {
        g_hooked = 0; // the next one ends at once
        const char byte = char(signal);
        (void)!::write(g_hookPipe[1], &byte, 1);
        return;
    }
    if (g_depth > 0) {
        g_pending = signal;
        return;
    }
    stop(signal);
}

} // namespace

void installInterruptHandlers()
{
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    for (int signal : { SIGINT, SIGTERM })
        ::sigaction(signal, &action, nullptr);
}

InterruptHook::InterruptHook(std::function<void()> hook)
    : m_hook(std::move(hook))
{
    if (g_hookPipe[0] < 0 && ::pipe2(g_hookPipe, O_CLOEXEC | O_NONBLOCK) != 0)
        return; // without the pipe, Ctrl-C ends toffee-cli at once, as before
    m_notifier = new QSocketNotifier(g_hookPipe[0], QSocketNotifier::Read);
    QObject::connect(m_notifier, &QSocketNotifier::activated, m_notifier, [this] {
        char byte = 0;
        while (::read(g_hookPipe[0], &byte, 1) == 1) { }
        if (m_hook)
            m_hook();
    });
    g_hooked = 1;
}

InterruptHook::~InterruptHook()
{
    g_hooked = 0;
    delete m_notifier;
}

CriticalSection::CriticalSection()
{
    g_depth = g_depth + 1; // volatile: no ++ (deprecated in C++20)
}

CriticalSection::~CriticalSection()
{
    g_depth = g_depth - 1;
    if (g_depth == 0 && g_pending != 0)
        stop(g_pending);
}

} // namespace Toffee::Cli
