// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/machine/consolecheck.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include <QList>

#include "model/gcode/gcodewords.h"
#include "serial/machine/machinecontroller.h"

using namespace Qt::StringLiterals;

namespace Toffee {

ConsoleCheck ConsoleCheck::refuse(const QString &reason)
{
    ConsoleCheck c;
    c.verdict = Verdict::Refuse;
    c.reason = reason;
    return c;
}

ConsoleCheck ConsoleCheck::confirm(const QString &reason)
{
    ConsoleCheck c;
    c.verdict = Verdict::Confirm;
    c.reason = reason;
    return c;
}

ConsoleCheck ConsoleCheck::check(const QString &line, bool halted, ConsoleRules rules)
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
    if (rules) {
        if (auto c = rules(block, trimmed, halted))
            return *c;
    }
    if (halted)
        return refuse(tr("The machine is halted: it refuses \"%1\" until it is unlocked. Check the machine, "
                         "then use Machine ▸ Unlock ($X).")
                          .arg(trimmed));
    if (block.has('G', 20))
        return refuse(
            tr("Toffee works in millimetres: after G20 the controller would read every later line in "
               "inches while Toffee shows millimetres. Use G21."));
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

// A tool change needs a tool word that is a tool number.
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
    if (!block.has('M', 6))
        return std::nullopt;
    const GCodeWord *t = block.find('T');
    if (const QString problem = toolProblem(t, tr("M6 needs a tool (M6 T2).")); !problem.isEmpty())
        return refuse(problem);
    ConsoleCheck c = confirm(tr("M6 T%1 changes the tool.").arg(int(t->value)));
    c.tool = int(t->value);
    return c;
}

// The spindle, an offset written, and any axis word: a question first.
ConsoleCheck ConsoleCheck::checkMotion(const GCodeBlock &block, const QString &trimmed)
{
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
