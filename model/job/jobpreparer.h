// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QString>

#include "model/clock.h"
#include "model/gcode/gcodeinterpreter.h"
#include "model/job/toolbits.h"
#include "model/job/toolfacts.h"
#include "model/limits.h"
#include "model/result.h"

namespace Toffee {

class ToolTable;

struct PrepareOptions
{
    Dialect dialect = Dialect::Carvera;
    // Carvera: after a manual change, the tool's stored TLO instead of a probe, when it is fresh.
    bool useStoredTlo = false;
    // Carvera: M491.1 after each tool's last cut, before the next change or the end.
    bool breakTest = false;
    double tolerance = Limits::kDefaultBreakTolerance;
    int staleDays = 7;
    // The tools the machine's rack holds (it always measures those at a change); empty: no rack, every change
    // is manual.
    QList<int> rack;
    QDateTime now = Clock::now();
    // The machine's reference MCS Z, when it is known (the window, connected): a stored TLO measured against
    // another is not restored.
    std::optional<double> machineReferenceMz;
    std::optional<double> zFloor; // for the job check run beside the preparation
};

// One piece of the side-by-side preview: the lines around a change, original on the left, prepared on the
// right. A row with no original line (0) is inserted; one whose texts differ was changed.
struct PrepareRow
{
    int originalLine = 0;
    int preparedLine = 0;
    QString original;
    QString prepared;
    friend bool operator==(const PrepareRow &, const PrepareRow &) = default;
};
using PrepareHunk = QList<PrepareRow>;

// What a preparation did.
struct PrepareSummary
{
    qint64 originalLines = 0;
    qint64 preparedLines = 0;
    int inserted = 0;
    int changed = 0;
    int cuttingMoves = 0; // each checked: the same work position as the original, the tool's own offset
    QList<PrepareHunk> hunks; // the first kMaxHunks, each of at most kMaxHunkRows and its closing context
    int moreHunks = 0;
    // What was left as it was, and why ("T2 is in the rack: …"): once a tool, the first kMaxNotes, then how
    // many more.
    QStringList notes;
    // Tools the break test was asked for that the firmware cannot test (its wireless probe's numbers): the
    // preparation is then incomplete, and toffee-cli exits 1, never 0.
    int untestedTools = 0;
};

// Rewrites a program so that the machine restores stored offsets and break-tests each tool (the Carvera), or
// so that each tool change has its length compensation (the G43 controllers), a line at a time. Every
// inserted line carries a comment saying why. The prepared program is run beside the original through the
// interpreter as it is written: every cutting move must reach the same work position, with the tool's own
// offset where the original had none; anything else stops it (nothing is written). What it keeps does not
// grow with the program nor with the tools it loads: the preview and the notes are bounded, a tool noted is a
// bit.
class JobPreparer
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::JobPreparer)
    Q_DISABLE_COPY_MOVE(JobPreparer)

public:
    static constexpr int kMaxHunks = 200;
    // A run of changes longer than this (a change on every other line) goes on in the next hunk.
    static constexpr int kMaxHunkRows = 50;
    // A real program has a note or two; one that loads thousands of tools would have one each.
    static constexpr int kMaxNotes = 100;
    static constexpr int kContextLines = 3;
    // The loosest break test a preparation writes: a tool broken by more than this is not "within tolerance".
    static constexpr double kMaxPrepareTolerance = 5.0;
    using LineSink = std::function<bool(QByteArrayView line)>; // each prepared line, without its end

    JobPreparer(const ToolTable &table, PrepareOptions options);

    // What these options may do for this dialect; an error for a request the controller cannot take.
    [[nodiscard]] static Result<void> check(const PrepareOptions &options);

    [[nodiscard]] Result<void> feed(QByteArrayView line, int lineNumber, const LineSink &sink);
    // After the last line: what the end needs (a last break test), and the summary.
    [[nodiscard]] Result<PrepareSummary> finish(const LineSink &sink);

private:
    // An inserted line, run through the prepared program's interpreter and written.
    [[nodiscard]] Result<void> insertLine(const QString &line, const LineSink &sink, bool inserted);
    // An original line, as it is or rewritten (`prepared`), run and written.
    [[nodiscard]] Result<void> writeOriginal(
        QByteArrayView original, QByteArrayView prepared, int lineNumber, const LineSink &sink);
    [[nodiscard]] Result<void> breakTest(const LineSink &sink);
    [[nodiscard]] Result<void> restoreAfterChange(int tool, const LineSink &sink);
    // The stored TLO to set for `tool` after its change, or nothing (and a note why not, once a tool).
    [[nodiscard]] std::optional<double> restorable(int tool);
    // The change line rewritten to take the stored TLO instead of probing, or empty when it stays.
    [[nodiscard]] QString carveraChange(QByteArrayView line, int tool);
    // The original and the prepared program after the same original line: the same work position, and the
    // tool's own length offset where the original had none.
    [[nodiscard]] Result<void> compare(int lineNumber);
    [[nodiscard]] QString comment(const QString &why) const;
    // A number as a command to the machine writes it (NumberFormat::command()).
    [[nodiscard]] static QString commandNumber(double value);
    void addRow(const PrepareRow &row, bool changed);
    void closeHunk();
    void noteOnce(int tool, const QString &note);
    [[nodiscard]] Result<void> sameReference(int tool, const ToolFacts &facts);

    PrepareOptions m_options;
    OffsetTable m_offsets;
    QHash<int, ToolFacts> m_facts;
    GCodeInterpreter m_original;
    GCodeInterpreter m_prepared;
    PrepareSummary m_summary;
    int m_tool = -1; // the tool in the spindle, as the original loaded it
    int m_toolLine = 0; // the line that loaded it
    int m_lastCutLine = 0; // its last cutting move since it was loaded (0: none)
    bool m_compensationDue = false; // G43 controllers: a tool was loaded and no move of the length axis since
    qint64 m_callsAtChange = 0; // the original's length calls when the tool was loaded
    bool m_compensated = false; // a G43 was inserted for the tool in the spindle
    qint64 m_callsAtInsertion = 0; // the original's length calls then
    bool m_changedLine = false; // the current original line was rewritten
    bool m_afterEnd = false; // the current original line comes after the program's end: copied, not run
    ToolBits m_rack; // the options' rack, for a lookup that does not grow with it
    ToolBits m_noted; // tools a note was made for
    ToolBits m_notedReference; // tools whose TLO's unknown reference was noted
    ToolBits m_untested; // tools a break test was asked for but the firmware cannot give
    qint64 m_moreNotes = 0; // notes beyond kMaxNotes, counted
    int m_firstMoreNoted = 0; // the tool of the first of them
    std::optional<double> m_restoredReference; // the reference of the stored TLOs restored so far
    int m_restoredTool = -1; // the first tool restored
    // The preview: the last few unchanged rows, and the hunk being built.
    QList<PrepareRow> m_context;
    PrepareHunk m_hunk;
    int m_trailing = 0; // unchanged rows since the last change in m_hunk
};

} // namespace Toffee
