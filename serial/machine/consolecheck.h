// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace Toffee {

struct GCodeBlock;
struct GCodeWord;
struct ConsoleCheck;

// A controller family's own rules for a typed line (the Carvera's M491, M493, its inches and what it runs
// while halted), asked before the neutral ones: a verdict, or nothing to leave the line to them.
using ConsoleRules
    = std::optional<ConsoleCheck> (*)(const GCodeBlock &block, const QString &trimmed, bool halted);

// What the console does with a line an operator typed, before it reaches the machine: the same checks the
// panels make (an offset or a tolerance out of range, a tool change with no tool, inches, anything but Unlock
// while halted), and a question before anything that moves the machine. Every controller's rules are here; a
// family's own (MachineController::consoleRules) come first.
struct ConsoleCheck
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::ConsoleCheck)

public:
    enum class Verdict { Send, Confirm, Refuse };
    Verdict verdict = Verdict::Send;
    QString reason; // Refuse: why and what to do; Confirm: what the command will do

    // Whether the line sets the TLO in force (the Carvera's M493.3): the console records what the machine
    // then holds.
    bool setsTlo = false;
    // Whether the line measures the tool on the setter (the Carvera's M491, or its M6 without H): the console
    // records the probe, as the panels do.
    bool measures = false;
    // The tool a tool change or a selection names.
    std::optional<int> tool;

    // `rules`: the connected controller's own, or none.
    [[nodiscard]] static ConsoleCheck check(const QString &line, bool halted, ConsoleRules rules);

    [[nodiscard]] static ConsoleCheck refuse(const QString &reason);
    [[nodiscard]] static ConsoleCheck confirm(const QString &reason);
    // Why `t` is not a tool number this controller takes (`missing` when there is no T word); empty when it
    // is.
    [[nodiscard]] static QString toolProblem(const GCodeWord *t, const QString &missing);

private:
    [[nodiscard]] static ConsoleCheck checkSystem(const QString &trimmed, bool halted);
    [[nodiscard]] static std::optional<ConsoleCheck> checkToolChange(const GCodeBlock &block);
    [[nodiscard]] static ConsoleCheck checkMotion(const GCodeBlock &block, const QString &trimmed);
};

} // namespace Toffee
