// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

#include <optional>

#include "serial/machine/consolecheck.h"

namespace Toffee {

// The Carvera's rules for a line typed in the console, before the neutral ones (ConsoleCheck): what its
// firmware still runs while halted, inches (G20 halts it), its break test's tolerance (M491.1), an offset set
// by hand (M493.3), a tool made active (M493.2), and its measuring M491 and M6. MachineSession::consoleRules.
struct CarveraConsole
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::CarveraConsole)

public:
    [[nodiscard]] static std::optional<ConsoleCheck> rules(
        const GCodeBlock &block, const QString &trimmed, bool halted);

private:
    [[nodiscard]] static std::optional<ConsoleCheck> offsets(const GCodeBlock &block, const QString &trimmed);
    [[nodiscard]] static std::optional<ConsoleCheck> toolChange(const GCodeBlock &block);
};

} // namespace Toffee
