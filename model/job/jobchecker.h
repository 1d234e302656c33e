// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include <QCoreApplication>
#include <QHash>
#include <QList>

#include "model/gcode/gcodeinterpreter.h"
#include "model/job/jobreport.h"
#include "model/job/toolfacts.h"
#include "model/units.h"

namespace Toffee {

class ToolTable;

// Adds what is known of the program's tools beyond the table (the history library), once they are known.
using JobFactSource = std::function<Result<void>(QHash<int, ToolFacts> &facts, const QList<int> &tools)>;

// What a program is checked against: the controller, the table (its units, offsets and what it knows of each
// tool), the machine's rack, and the limits.
struct JobCheckSetup
{
    Dialect dialect = Dialect::Carvera;
    bool hasTable = false;
    Units tableUnits = Units::Millimetre;
    OffsetTable offsets; // what the controller holds, from the table
    QHash<int, ToolFacts> facts; // from the table; the library's are added once the program's tools are known
    std::optional<double> zFloor; // work Z no feed move may go below
    int staleDays = 7;
    // The tools the machine's rack holds: every other is a manual change. Empty: it has no rack; nothing: not
    // known (no finding either way).
    std::optional<QList<int>> rack;
    QDateTime now = QDateTime::currentDateTimeUtc();

    // Everything `table` says, for `dialect`.
    void useTable(const ToolTable &table);
};

// The tools a Carvera C1's rack holds (docs/CARVERA.md § 7): T1 to T6.
[[nodiscard]] QList<int> carveraRack();
// A rack as an operator writes it: "none", or tool numbers and ranges ("1-6", "1,2,5-8"); and back.
[[nodiscard]] Result<QList<int>> parseRack(const QString &text);
[[nodiscard]] QString rackText(const QList<int> &rack);
// The Carvera's probes (T0 wireless, T999990-999999 3-axis) and its empty spindle (T-1): loaded, but not
// cutters to look up in a table.
[[nodiscard]] bool isCarveraNonCutter(int tool);

// Checks a program against the table as it is read, one line at a time, in memory that does not grow with the
// program: findings that repeat (a feed below the floor on every pass) are kept once per tool with their
// first lines and a count, and the controller's refusals after the first 100 are counted.
class JobChecker
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::JobChecker)
    Q_DISABLE_COPY_MOVE(JobChecker)

public:
    static constexpr int kMaxLinesPerFinding = 10;
    static constexpr int kMaxProgramErrors = 100;

    explicit JobChecker(JobCheckSetup setup);

    void feed(QByteArrayView line, int lineNumber);
    // The program ended (M2, M30): the controller runs nothing after it.
    [[nodiscard]] bool ended() const { return m_interpreter.ended(); }
    // The tools loaded so far, in the order of first use.
    [[nodiscard]] QList<int> toolNumbers() const;
    [[nodiscard]] const QHash<int, ToolFacts> &facts() const { return m_setup.facts; }
    // Adds what `source` knows of the tools loaded so far (the library's facts, once the program is read).
    [[nodiscard]] Result<void> addFacts(const JobFactSource &source);
    [[nodiscard]] JobReport finish(const QString &program, bool cancelled);

private:
    void toolChanged(int line);
    void feedMove(int line, const BlockEffect &effect);
    void unitsChanged(int line);
    void tloSet(int line);
    void checkCompensation(int line);
    void programError(const Error &error);
    // Notes a finding, once per kind and tool: again, only its line and count.
    template<typename Message> void note(FindingKind kind, int tool, int line, Message message);
    void toolFindings(const JobTool &tool);
    void noteForTool(FindingKind kind, const JobTool &tool, const QString &message);
    [[nodiscard]] bool hasLengthCompensation() const;

    JobCheckSetup m_setup;
    GCodeInterpreter m_interpreter;
    qint64 m_lines = 0;
    QList<JobTool> m_tools;
    QHash<int, qsizetype> m_toolIndex;
    qsizetype m_current = -1; // the loaded tool's index in m_tools
    QList<Finding> m_findings;
    QHash<quint64, qsizetype> m_findingIndex; // (kind, tool) -> index in m_findings
    qint64 m_moreProgramErrors = 0;
    int m_firstUncountedError = 0;
    int m_programErrors = 0;
    bool m_compensationDue = false; // a tool was loaded: check its length compensation at the next feed move
    int m_checkedRegister = -2;
    bool m_checkedActive = false;
    qint64 m_callsAtChange = 0; // the program's length calls when the tool in the spindle was loaded
};

} // namespace Toffee
