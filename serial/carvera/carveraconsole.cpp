// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/carvera/carveraconsole.h"

#include <algorithm>

#include "model/gcode/carvera.h"
#include "model/gcode/gcodewords.h"
#include "serial/machine/machinecontroller.h"

namespace Toffee {

std::optional<ConsoleCheck> CarveraConsole::rules(
    const GCodeBlock &block, const QString &trimmed, bool halted)
{
    // What the firmware still takes while halted, sent; anything else would get "Alarm lock", and is refused
    // as on every controller. The firmware looks at the first word only; the console asks that every word be
    // one, so nothing else rides along.
    if (halted) {
        const auto &ws = block.words;
        const bool runs = !block.isEmpty() && std::all_of(ws.cbegin(), ws.cend(), [](const GCodeWord &w) {
            return carveraRunsWhileHalted(w);
        });
        return runs ? std::optional(ConsoleCheck {}) : std::nullopt;
    }
    if (auto c = offsets(block, trimmed))
        return c;
    if (auto c = toolChange(block))
        return c;
    if (block.has('M', 491) || block.has('M', 491.2)) {
        ConsoleCheck c
            = ConsoleCheck::confirm(tr("%1 probes the tool: the machine moves to the tool setter, and "
                                       "the TLO it measures is recorded in the table.")
                                        .arg(trimmed));
        c.measures = block.has('M', 491);
        return c;
    }
    return std::nullopt;
}

// Inches, a break test's tolerance, an offset set by hand.
std::optional<ConsoleCheck> CarveraConsole::offsets(const GCodeBlock &block, const QString &trimmed)
{
    if (block.has('G', 20))
        return ConsoleCheck::refuse(
            tr("The Carvera works in millimetres only: G20 (inches) halts it. Use G21."));
    if (block.has('M', 491.1)) {
        const double tolerance = block.value('H').value_or(MachineController::kDefaultTolerance);
        if (auto r = MachineController::validateTolerance(tolerance); !r)
            return ConsoleCheck::refuse(r.error().message);
        return ConsoleCheck::confirm(
            tr("M491.1 runs a break test: the machine moves to the tool setter and probes the tool. "
               "Use Machine ▸ Break Test to have the result recorded in the table."));
    }
    if (!block.has('M', 493.3))
        return std::nullopt;
    const auto z = block.value('Z');
    const auto h = block.value('H');
    if (!z && !h)
        return ConsoleCheck::refuse(tr("M493.3 needs Z (the TLO) or H (the tool tip's height above Z0)."));
    // The community firmware adds H to its "current tool offset", which after any M493.3 Z is the TLO and
    // not the tool's MCS Z: the TLO it sets is then off by the reference, more than 100 mm on a C1.
    if (!z)
        return ConsoleCheck::refuse(
            tr("Typed, M493.3 H can set a TLO more than 100 mm off: after an M493.3 Z the community "
               "firmware measures H from the TLO instead of the tool's height. Under \"Set the offset "
               "by hand\", choose Gauge height above Z0: Toffee works the TLO out from the position "
               "and sends it as M493.3 Z."));
    if (auto r = MachineController::validateOffset(tr("The tool length offset"), *z); !r)
        return ConsoleCheck::refuse(r.error().message);
    ConsoleCheck c = ConsoleCheck::confirm(
        tr("%1 changes the tool length offset the next cut uses. The table records it as set by hand.")
            .arg(trimmed));
    c.setsTlo = true;
    return c;
}

// M493.2 and M6 need a tool word that is a tool number; either halts the machine without one.
std::optional<ConsoleCheck> CarveraConsole::toolChange(const GCodeBlock &block)
{
    const bool select = block.has('M', 493.2);
    if (!select && !block.has('M', 6))
        return std::nullopt;
    const GCodeWord *t = block.find('T');
    const QString problem = ConsoleCheck::toolProblem(t,
        select ? tr("M493.2 needs a tool (M493.2 T2): without one the machine halts.")
               : ConsoleCheck::tr("M6 needs a tool (M6 T2)."));
    if (!problem.isEmpty())
        return ConsoleCheck::refuse(problem);
    ConsoleCheck c = ConsoleCheck::confirm(select
            ? tr("M493.2 makes T%1 the active tool but keeps the TLO in force now (another tool's, or "
                 "none): T%1's own is not set. Probe T%1 or restore its TLO before cutting.")
                  .arg(int(t->value))
            : tr("M6 T%1 changes the tool: the machine moves, and then probes T%1 on the tool setter.")
                  .arg(int(t->value)));
    c.tool = int(t->value);
    c.measures = !select && !block.find('H') && *c.tool >= 0;
    return c;
}

} // namespace Toffee
