// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QCoreApplication>
#include <QDateTime>
#include <QList>
#include <QString>

#include "model/gcode/dialect.h"
#include "model/tool.h"

namespace Toffee {

enum class Severity : quint8 { Warning, Error };

// What a job check can find, each with its severity (jobFindingSeverity).
enum class FindingKind : quint8 {
    MissingTool, // the program loads a tool the table lacks (error)
    NotMeasured, // the tool has no measured TLO (or, for G43 controllers, no length at all) (warning)
    StaleTlo, // its TLO is older than the stale limit (warning)
    BrokenTool, // its last break test failed and it was not measured since (error)
    ManualChange, // the machine's rack cannot hold the tool: a manual change (warning)
    LengthOffsetMismatch, // G43 with an H other than the loaded tool (warning)
    NoLengthCompensation, // a feed move after a tool change with no length compensation (warning)
    NoToolLoaded, // a feed move before any tool change: the tool in the spindle is not known (warning)
    UnitsMismatch, // the program's units are not the table's (error)
    InchOnCarvera, // G20 on the Carvera, which halts (error)
    ProgramError, // what the controller would refuse or alarm on (error)
    BelowFloor, // a feed move below the Z floor (error)
    ProgramSetsTlo, // the Carvera program sets a tool's TLO to another value than the table's (warning)
    ControllerTableDiffers, // grblHAL's own table holds another TLO for the tool than the file (warning)
    LifeExceeded, // the program takes the tool past its life limit (minutes of cutting or uses) (warning)
    SpreadExceeded, // its last measurement's edges lay further apart than its spread limit (warning)
};

[[nodiscard]] Severity findingSeverity(FindingKind kind);
// As --json writes it: "missing_tool", "not_measured", …
[[nodiscard]] QString findingKey(FindingKind kind);
[[nodiscard]] QString severityName(Severity severity); // "error", "warning"

// The first lines of something that happened `count` times: "12, 14, 19", and ", …" when there were more.
[[nodiscard]] QString linesListed(const QList<int> &lines, qint64 count);

// One finding: where (the first line it happened on), which tool (-1: none), what, and, for one that repeats
// (a feed below the floor on every pass), the first lines and how often in all.
struct Finding
{
    FindingKind kind = FindingKind::ProgramError;
    int line = 0;
    int tool = -1;
    QString message;
    QList<int> lines; // the first few lines it happened on
    qint64 count = 1;
    // A summary of the tools beyond the report's list (JobReport::kMaxListedTools): how many distinct tools
    // it stands for, with no tool of its own; 0 for every other finding.
    qint64 moreTools = 0;

    [[nodiscard]] Severity severity() const { return findingSeverity(kind); }
    // "12, 14, 19", with ", …" when it happened on more lines than are kept.
    [[nodiscard]] QString linesText() const { return linesListed(lines, count); }
    friend bool operator==(const Finding &, const Finding &) = default;
};

// A tool the program loads, in the order of first use, and what it does.
struct JobTool
{
    int number = 0;
    QList<int> loadLines; // the first lines that load it
    qint64 loads = 0;
    bool inTable = false;
    std::optional<double> tlo; // the table's (Carvera: measured; others: total length)
    QDateTime measuredAt; // of the TLO, from the table or the library, whichever is newer
    bool setByHand = false; // the TLO was set on the machine by hand, not measured on the setter
    double cuttingSeconds = 0.0; // feed moves at their F; no override assumed
    double feedPathMm = 0.0;
    std::optional<double> lowestZ; // the lowest work Z of its feed moves
};

// What a check of one program found. Findings are in line order.
struct JobReport
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::JobReport)

public:
    QString program; // the file's name
    Dialect dialect = Dialect::Carvera;
    qint64 lines = 0; // lines read
    bool cancelled = false; // stopped before the end: what is here covers `lines` only
    // A real program loads a handful of tools; one that loads thousands is wrong or hostile. The first
    // kMaxListedTools are listed with everything known of them; the rest are counted (moreTools, moreLoads),
    // their findings summed up in one finding per kind (Finding::moreTools), and the history library is not
    // read for them: their facts are the table's.
    static constexpr int kMaxListedTools = 1000;
    QList<JobTool> tools; // the first kMaxListedTools, in the order of first use
    qint64 moreTools = 0; // distinct tools loaded beyond those
    qint64 moreLoads = 0; // and how often they were loaded
    int moreFromLine = 0; // the line that loads the first of them
    QList<Finding> findings;
    double cuttingSeconds = 0.0;
    double rapidMm = 0.0;

    // Every distinct tool the program loads, listed or counted.
    [[nodiscard]] qint64 distinctTools() const { return tools.size() + moreTools; }
    // A summary finding counts once for each tool it stands for.
    [[nodiscard]] int errors() const;
    [[nodiscard]] int warnings() const;
    // toffee-cli job check's exit code: 0 clean, 1 warnings only, 4 errors.
    [[nodiscard]] int exitCode() const;
    [[nodiscard]] const JobTool *tool(int number) const;
    // "2 errors, 1 warning" or "no findings".
    [[nodiscard]] QString summary() const;
};

} // namespace Toffee
