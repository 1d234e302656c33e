// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/consolecheck.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include <QList>

#include "model/gcode/carvera.h"
#include "model/gcode/gcodewords.h"
#include "serial/machine/machinecontroller.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

ConsoleCheck refuse(const QString &reason)
{
    ConsoleCheck c;
    c.verdict = ConsoleCheck::Verdict::Refuse;
    c.reason = reason;
    return c;
}

ConsoleCheck confirm(const QString &reason)
{
    ConsoleCheck c;
    c.verdict = ConsoleCheck::Verdict::Confirm;
    c.reason = reason;
    return c;
}

} // namespace

ConsoleCheck ConsoleCheck::check(const QString &line, bool halted)
{
    const QString trimmed = line.trimmed();
    if (trimmed.startsWith(u'$'))
        return checkSystem(trimmed, halted);
    if (trimmed == u"?")
        return refuse(
            tr("Toffee asks the machine for its status several times a second: the strip at the top shows "
               "it."));
    const QByteArray bytes = trimmed.toLatin1();
    const auto read = GCodeBlock::read(bytes);
    if (!read)
        return refuse(
            tr("\"%1\" is not a G-code line Toffee can read: %2").arg(trimmed, read.error().message));
    const GCodeBlock &block = read.value();
    if (std::any_of(block.words.cbegin(), block.words.cend(), [](const GCodeWord &w) { return w.bare; }))
        return refuse(
            tr("\"%1\" is not a G-code line Toffee can read; check it for a letter without a number.")
                .arg(trimmed));
    if (halted)
        return checkHalted(block, trimmed);
    if (auto c = checkOffsets(block, trimmed))
        return *c;
    if (auto c = checkToolChange(block))
        return *c;
    return checkMotion(block, trimmed);
}

ConsoleCheck ConsoleCheck::checkSystem(const QString &trimmed, bool halted)
{
    const QString upper = trimmed.toUpper();
    if (upper == u"$X")
        return {};
    if (halted)
        return refuse(tr("The machine is halted: only Unlock ($X) runs now. Check the machine, then use "
                         "Machine ▸ Unlock."));
    if (upper == u"$H")
        return confirm(tr("$H homes the machine: every axis moves to its limit switch."));
    if (upper.startsWith(u"$J="))
        return confirm(tr("%1 jogs the machine.").arg(trimmed));
    return {};
}

// What the firmware still takes while halted; everything else would get "Alarm lock". The firmware looks at
// the first word only; the console asks that every word be one, so nothing else rides along.
ConsoleCheck ConsoleCheck::checkHalted(const GCodeBlock &block, const QString &trimmed)
{
    const auto &ws = block.words;
    if (block.isEmpty()
        || !std::all_of(ws.cbegin(), ws.cend(), [](const GCodeWord &w) { return carveraRunsWhileHalted(w); }))
        return refuse(tr("The machine is halted: it refuses \"%1\" until it is unlocked. Check the machine, "
                         "then use Machine ▸ Unlock ($X).")
                          .arg(trimmed));
    return {};
}

// Inches, a break test's tolerance, an offset set by hand.
std::optional<ConsoleCheck> ConsoleCheck::checkOffsets(const GCodeBlock &block, const QString &trimmed)
{
    if (block.has('G', 20))
        return refuse(tr("The Carvera works in millimetres only: G20 (inches) halts it. Use G21."));
    if (block.has('M', 491.1)) {
        const double tolerance = block.value('H').value_or(MachineController::kDefaultTolerance);
        if (auto r = MachineController::validateTolerance(tolerance); !r)
            return refuse(r.error().message);
        return confirm(
            tr("M491.1 runs a break test: the machine moves to the tool setter and probes the tool. "
               "Use Machine ▸ Break Test to have the result recorded in the table."));
    }
    if (!block.has('M', 493.3))
        return std::nullopt;
    const auto z = block.value('Z');
    const auto h = block.value('H');
    if (!z && !h)
        return refuse(tr("M493.3 needs Z (the TLO) or H (the tool tip's height above Z0)."));
    // The community firmware adds H to its "current tool offset", which after any M493.3 Z is the TLO and
    // not the tool's MCS Z: the TLO it sets is then off by the reference, more than 100 mm on a C1.
    if (!z)
        return refuse(
            tr("Typed, M493.3 H can set a TLO more than 100 mm off: after an M493.3 Z the community "
               "firmware measures H from the TLO instead of the tool's height. Under \"Set the offset "
               "by hand\", choose Gauge height above Z0: Toffee works the TLO out from the position "
               "and sends it as M493.3 Z."));
    if (auto r = MachineController::validateOffset(tr("The tool length offset"), *z); !r)
        return refuse(r.error().message);
    ConsoleCheck c = confirm(
        tr("%1 changes the tool length offset the next cut uses. The table records it as set by hand.")
            .arg(trimmed));
    c.setsTlo = true;
    return c;
}

// M493.2 and M6 need a tool word that is a tool number; either halts the machine without one.
QString ConsoleCheck::toolProblem(const GCodeWord *t, const QString &missing)
{
    if (!t)
        return missing;
    if (t->value != std::floor(t->value) || t->value < Limits::kEmptySpindle
        || t->value > Limits::kMaxToolNumber || !MachineController::validateToolNumber(int(t->value)))
        return tr("%1 is not a tool number; use %2 to %3 (%4 for an empty spindle).")
            .arg(QString::fromLatin1(t->text).toUpper())
            .arg(Limits::kMinToolNumber)
            .arg(Limits::kMaxToolNumber)
            .arg(Limits::kEmptySpindle);
    return {};
}

std::optional<ConsoleCheck> ConsoleCheck::checkToolChange(const GCodeBlock &block)
{
    const bool select = block.has('M', 493.2);
    if (!select && !block.has('M', 6))
        return std::nullopt;
    const GCodeWord *t = block.find('T');
    const QString problem = toolProblem(t,
        select ? tr("M493.2 needs a tool (M493.2 T2): without one the machine halts.")
               : tr("M6 needs a tool (M6 T2)."));
    if (!problem.isEmpty())
        return refuse(problem);
    ConsoleCheck c = confirm(select
            ? tr("M493.2 makes T%1 the active tool but keeps the TLO in force now (another tool's, or "
                 "none): T%1's own is not set. Probe T%1 or restore its TLO before cutting.")
                  .arg(int(t->value))
            : tr("M6 T%1 changes the tool: the machine moves, and then probes T%1 on the tool setter.")
                  .arg(int(t->value)));
    c.tool = int(t->value);
    c.measures = !select && !block.find('H') && *c.tool >= 0;
    return c;
}

// Probing, the spindle, and any axis word: a question first.
ConsoleCheck ConsoleCheck::checkMotion(const GCodeBlock &block, const QString &trimmed)
{
    if (block.has('M', 491) || block.has('M', 491.2)) {
        ConsoleCheck c
            = confirm(tr("%1 probes the tool: the machine moves to the tool setter, and the TLO it "
                         "measures is recorded in the table.")
                          .arg(trimmed));
        c.measures = block.has('M', 491);
        return c;
    }
    if (block.has('M', 3) || block.has('M', 4))
        return confirm(tr("%1 starts the spindle.").arg(trimmed));
    // Axis words that set an offset rather than a position: asked about all the same (the offset is what the
    // machine cuts with next), in words that are true (it was "moves the machine").
    if (block.has('G', 10))
        return confirm(tr("%1 writes an offset into the controller (a tool's length or a work offset); "
                          "nothing moves, but the next moves use it.")
                           .arg(trimmed));
    if (block.has('G', 92))
        return confirm(
            tr("%1 shifts the work coordinates; nothing moves, but the next moves use them.").arg(trimmed));
    if (block.has('G', 43.1))
        return confirm(
            tr("%1 sets the tool length offset in force; nothing moves, but the next moves use it.")
                .arg(trimmed));
    const auto &ws = block.words;
    const bool motion = std::any_of(ws.cbegin(), ws.cend(),
                            [](const GCodeWord &w) { return QByteArrayView("XYZABC").contains(w.letter); })
        || block.has('G', 28) || block.has('G', 30);
    if (motion)
        return confirm(tr("%1 moves the machine.").arg(trimmed));
    return {};
}

} // namespace Toffee
