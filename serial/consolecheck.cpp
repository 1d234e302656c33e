// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/consolecheck.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include <QList>

#include "model/gcode/carvera.h"
#include "model/gcode/gcodewords.h"
#include "serial/machinesession.h"

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
    if (trimmed.startsWith(u'$')) {
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
    if (trimmed == u"?")
        return refuse(
            tr("Toffee asks the machine for its status several times a second: the strip at the top shows "
               "it."));
    const QByteArray bytes = trimmed.toLatin1();
    const auto read = GCodeBlock::read(bytes);
    if (!read)
        return refuse(
            tr("\"%1\" is not a G-code line Toffee can read: %2").arg(trimmed, read.error().message));
    if (std::any_of(read.value().words.cbegin(), read.value().words.cend(),
            [](const GCodeWord &w) { return w.bare; }))
        return refuse(
            tr("\"%1\" is not a G-code line Toffee can read; check it for a letter without a number.")
                .arg(trimmed));
    const GCodeBlock &block = read.value();
    const auto &ws = block.words;
    auto find = [&block](char letter) {
        return block.find(letter);
    };
    auto has = [&block](char letter, double value) {
        return block.has(letter, value);
    };

    if (halted) {
        // What the firmware still takes while halted; everything else would get "Alarm lock". The firmware
        // looks at the first word only; the console asks that every word be one, so nothing else rides along.
        if (block.isEmpty() || !std::all_of(ws.cbegin(), ws.cend(), [](const GCodeWord &w) {
                return carveraRunsWhileHalted(w);
            }))
            return refuse(
                tr("The machine is halted: it refuses \"%1\" until it is unlocked. Check the machine, "
                   "then use Machine ▸ Unlock ($X).")
                    .arg(trimmed));
        return {};
    }
    if (has('G', 20))
        return refuse(tr("The Carvera works in millimetres only: G20 (inches) halts it. Use G21."));
    if (has('M', 491.1)) {
        const GCodeWord *h = find('H');
        const double tolerance = h ? h->value : MachineSession::kDefaultTolerance;
        if (auto r = MachineSession::validateTolerance(tolerance); !r)
            return refuse(r.error().message);
        return confirm(
            tr("M491.1 runs a break test: the machine moves to the tool setter and probes the tool. "
               "Use Machine ▸ Break Test to have the result recorded in the table."));
    }
    if (has('M', 493.3)) {
        const GCodeWord *z = find('Z');
        const GCodeWord *h = find('H');
        if (!z && !h)
            return refuse(tr("M493.3 needs Z (the TLO) or H (the tool tip's height above Z0)."));
        if (auto r = MachineSession::validateOffset(
                z ? tr("The tool length offset") : tr("The height above Z0"), (z ? z : h)->value);
            !r)
            return refuse(r.error().message);
        ConsoleCheck c = confirm(
            tr("%1 changes the tool length offset the next cut uses. The table records it as set by hand.")
                .arg(trimmed));
        c.setsTlo = true;
        return c;
    }
    // M493.2 and M6 need a tool word that is a tool number; either halts the machine without one.
    auto toolProblem = [](const GCodeWord *t, const QString &missing) -> QString {
        if (!t)
            return missing;
        if (t->value != std::floor(t->value) || t->value < Limits::kEmptySpindle
            || t->value > Limits::kMaxToolNumber || !MachineSession::validateToolNumber(int(t->value)))
            return tr("%1 is not a tool number; use %2 to %3 (%4 for an empty spindle).")
                .arg(QString::fromLatin1(t->text).toUpper())
                .arg(Limits::kMinToolNumber)
                .arg(Limits::kMaxToolNumber)
                .arg(Limits::kEmptySpindle);
        return {};
    };
    if (has('M', 493.2)) {
        const GCodeWord *t = find('T');
        if (const QString problem
            = toolProblem(t, tr("M493.2 needs a tool (M493.2 T2): without one the machine halts."));
            !problem.isEmpty())
            return refuse(problem);
        ConsoleCheck c
            = confirm(tr("M493.2 makes T%1 the active tool but keeps the current TLO, which belongs "
                         "to the tool measured before. Probe T%1 or restore its TLO before cutting.")
                          .arg(int(t->value)));
        c.tool = int(t->value);
        return c;
    }
    if (has('M', 6)) {
        const GCodeWord *t = find('T');
        if (const QString problem = toolProblem(t, tr("M6 needs a tool (M6 T2).")); !problem.isEmpty())
            return refuse(problem);
        ConsoleCheck c = confirm(
            tr("M6 T%1 changes the tool: the machine moves, and then probes T%1 on the tool setter.")
                .arg(int(t->value)));
        c.tool = int(t->value);
        return c;
    }
    if (has('M', 491) || has('M', 491.2))
        return confirm(
            tr("%1 probes the tool: the machine moves to the tool setter. Use Machine ▸ Probe to have "
               "the result recorded in the table.")
                .arg(trimmed));
    if (has('M', 3) || has('M', 4))
        return confirm(tr("%1 starts the spindle.").arg(trimmed));
    const bool motion = std::any_of(ws.cbegin(), ws.cend(),
                            [](const GCodeWord &w) {
                                return w.letter == 'X' || w.letter == 'Y' || w.letter == 'Z'
                                    || w.letter == 'A' || w.letter == 'B' || w.letter == 'C';
                            })
        || has('G', 28) || has('G', 30);
    if (motion)
        return confirm(tr("%1 moves the machine.").arg(trimmed));
    return {};
}

} // namespace Toffee
