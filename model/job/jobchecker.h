// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <functional>
#include <optional>

#include <QCoreApplication>
#include <QHash>
#include <QList>

#include "model/clock.h"
#include "model/gcode/gcodeinterpreter.h"
#include "model/job/jobreport.h"
#include "model/job/toolbits.h"
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
    QDateTime now = Clock::now();
    // What the controller's own table holds (grblHAL's, read with $# on a connected machine): each tool's
    // TLO by number. Nothing: not read (no finding either way).
    std::optional<QHash<int, double>> controllerTlos;

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
// first lines and a count, and the controller's refusals after the first 100 are counted. Nor does it grow
// with the tools a program loads: the first kMaxListedTools are kept whole; each one after them is a bit in a
// set and a count, its findings summed up in one per kind, and only the listed ones are looked up in the
// history library. Each line costs the same whatever came before it.
class JobChecker
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::JobChecker)
    Q_DISABLE_COPY_MOVE(JobChecker)

public:
    static constexpr int kMaxLinesPerFinding = 10;
    static constexpr int kMaxProgramErrors = 100;
    static constexpr int kMaxListedTools = JobReport::kMaxListedTools;

    explicit JobChecker(JobCheckSetup setup);

    void feed(QByteArrayView line, int lineNumber);
    // The program ended (M2, M30): the controller runs nothing after it.
    [[nodiscard]] bool ended() const { return m_interpreter.ended(); }
    // The tools loaded so far and listed (at most kMaxListedTools), in the order of first use.
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
    // Notes a finding, once per kind and tool: again, only its line and count. For the loaded tool when it is
    // beyond the list, once per kind for all of them (noteMore).
    template<typename Message> void note(FindingKind kind, int tool, int line, Message message);
    // A finding of a tool beyond the list: counted in its kind's summary, `newTool` when this tool was not
    // counted in it before.
    void noteMore(FindingKind kind, int tool, int line, bool newTool);
    // What the table and the library say of a tool, each finding's message made only when `found` asks for
    // it.
    template<typename Found> void judgeTool(int number, const ToolFacts &facts, Found found) const;
    void toolFindings(const JobTool &tool);
    void lifeFinding(const JobTool &tool, const ToolFacts &facts);
    // A tool beyond the list loaded at `line`: its findings from the table, counted.
    void countMoreTool(int number, int line, bool first);
    void noteForTool(FindingKind kind, const JobTool &tool, const QString &message);
    [[nodiscard]] QString moreMessage(const Finding &summary) const;
    [[nodiscard]] bool inRack(int tool) const { return m_rack.contains(tool); }

    // m_current when the loaded tool is beyond the list.
    static constexpr qsizetype kBeyondList = -2;

    JobCheckSetup m_setup;
    GCodeInterpreter m_interpreter;
    ToolBits m_rack; // the setup's, for a lookup that does not grow with it
    qint64 m_lines = 0;
    QList<JobTool> m_tools; // the listed ones
    QHash<int, qsizetype> m_toolIndex;
    qsizetype m_current = -1; // the loaded tool's index in m_tools; -1 none; kBeyondList
    ToolBits m_moreSeen; // the tools beyond the list loaded so far
    qint64 m_moreTools = 0;
    qint64 m_moreLoads = 0;
    int m_moreFromLine = 0;
    // For each kind of finding, the tools beyond the list it was counted for.
    std::array<ToolBits, 16> m_moreCounted;
    double m_cuttingSeconds = 0.0;
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
