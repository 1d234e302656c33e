// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/interrupt.h"

#include <csignal>
#include <initializer_list>
#include <unistd.h>

namespace Toffee::Cli {

namespace {

volatile std::sig_atomic_t g_depth = 0; // inside a critical section
volatile std::sig_atomic_t g_pending = 0; // the signal that came meanwhile

// Only what is safe in a signal handler: write(2) and _exit(2).
[[noreturn]] void stop(int signal)
{
    static const char kSaid[] = "toffee-cli: interrupted; what the machine measured before now is kept.\n";
    (void)!::write(STDERR_FILENO, kSaid, sizeof kSaid - 1);
    ::_exit(128 + signal);
}

void onSignal(int signal)
{
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
