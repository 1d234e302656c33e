// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace Toffee::Cli {

// Ctrl-C (SIGINT) and SIGTERM end toffee-cli at once, as a script expects, except while it is keeping what
// the machine measured (the table's save and the measurement's copy on this computer): then it finishes that
// first, which takes no more than a file's save. A wait on the library is not such a moment: the measurement
// is already kept, so toffee-cli ends and sends it another time.
void installInterruptHandlers();

class CriticalSection
{
public:
    CriticalSection();
    ~CriticalSection();
    CriticalSection(const CriticalSection &) = delete;
    CriticalSection &operator=(const CriticalSection &) = delete;
};

} // namespace Toffee::Cli
