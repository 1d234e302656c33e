// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>

class QSocketNotifier;

namespace Toffee::Cli {

// Ctrl-C (SIGINT) and SIGTERM end toffee-cli at once, as a script expects, except while it is keeping what
// the machine measured (the table's save and the measurement's copy on this computer): then it finishes that
// first, which takes no more than a file's save. A wait on the library is not such a moment: the measurement
// is already kept, so toffee-cli ends and sends it another time.
void installInterruptHandlers();

// While one lives, the first Ctrl-C (or SIGTERM) does not end toffee-cli at once: `hook` is called from the
// event loop instead, to end what waits for a person on the machine first (a manual tool change), and
// toffee-cli then ends as the operation does. A second one ends it at once.
class InterruptHook
{
public:
    explicit InterruptHook(std::function<void()> hook);
    ~InterruptHook();
    InterruptHook(const InterruptHook &) = delete;
    InterruptHook &operator=(const InterruptHook &) = delete;

private:
    std::function<void()> m_hook;
    QSocketNotifier *m_notifier = nullptr;
};

class CriticalSection
{
public:
    CriticalSection();
    ~CriticalSection();
    CriticalSection(const CriticalSection &) = delete;
    CriticalSection &operator=(const CriticalSection &) = delete;
};

} // namespace Toffee::Cli
