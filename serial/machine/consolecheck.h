// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace Toffee {

struct GCodeBlock;
struct GCodeWord;

// What the console does with a line an operator typed, before it reaches the machine: the same checks the
// panels make (a tolerance under 0.02, an offset out of range, a tool change with no tool, inches on the
// Carvera, anything but Unlock while halted), and a question before anything that moves the machine.
struct ConsoleCheck
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::ConsoleCheck)

public:
    enum class Verdict { Send, Confirm, Refuse };
    Verdict verdict = Verdict::Send;
    QString reason; // Refuse: why and what to do; Confirm: what the command will do

    // Whether the line is M493.3, which sets the TLO: the console records what the machine then holds.
    bool setsTlo = false;
    // Whether the line measures the tool on the setter (M491, or M6 without H): the console records the
    // probe, as the panels do.
    bool measures = false;
    // The tool an M6 or M493.2 names.
    std::optional<int> tool;

    [[nodiscard]] static ConsoleCheck check(const QString &line, bool halted);

private:
    [[nodiscard]] static ConsoleCheck checkSystem(const QString &trimmed, bool halted);
    [[nodiscard]] static ConsoleCheck checkHalted(const GCodeBlock &block, const QString &trimmed);
    [[nodiscard]] static std::optional<ConsoleCheck> checkOffsets(
        const GCodeBlock &block, const QString &trimmed);
    [[nodiscard]] static std::optional<ConsoleCheck> checkToolChange(const GCodeBlock &block);
    [[nodiscard]] static ConsoleCheck checkMotion(const GCodeBlock &block, const QString &trimmed);
    [[nodiscard]] static QString toolProblem(const GCodeWord *t, const QString &missing);
};

} // namespace Toffee
