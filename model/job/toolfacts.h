// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include <QDateTime>
#include <QHash>
#include <QList>

#include "model/result.h"
#include "model/tool.h"
#include "model/toollife.h"

namespace Toffee {

class Library;
class ToolTable;

// What the table and the history library know of one tool, for the job check and its preparation.
struct ToolFacts
{
    bool inTable = false;
    // The table's TLO from the machine and its reference, in millimetres as the machine has them (like the
    // history's and the controller's), whatever the table's units.
    std::optional<double> measuredTlo;
    TloSource source = TloSource::Probe;
    std::optional<double> referenceMz;
    double sameWithin = 0.0005; // how far a machine's value may lie from these and still be them
    double length = 0.0; // the table's total length (what G43 applies on the other controllers), its units
    QDateTime measuredAt; // when the TLO above was measured
    // The library's newest measurement of the tool, when it differs from the TLO above (the table was not
    // saved after it).
    std::optional<double> libraryTlo;
    // The history says another cutter went in at this time, after the table's TLO was measured (the table
    // was not saved after the new cutter, or it was undone): that TLO is the old cutter's.
    QDateTime newCutterAt;
    QDateTime libraryMeasuredAt;
    // The last break test failed and the tool was not measured since (the table's mark, or the library's
    // newest break test when no probe came after it).
    bool broken = false;
    // Tool life: the table's limits, and what the cutter did since it went in (the history's program runs).
    std::optional<double> lifeLimitMinutes;
    std::optional<int> lifeLimitUses;
    UsedLife used;
    // The tool's spread limit (millimetres), and the spread of its newest measurement touched on each edge
    // (the history's probe or break test), when it has them.
    std::optional<double> spreadLimit;
    std::optional<double> lastSpread;

    // Measured within `staleDays` of `now`, and not after it (Clock::isInFuture: beyond the clocks' skew).
    [[nodiscard]] bool isFresh(const QDateTime &now, int staleDays) const;
};

// How a stored TLO's reference is checked: the TLO's own reference must be known either way; against the
// machine's when that is known too (a program prepared at a desk), or required to be known and equal (a
// change made now, on the machine).
enum class ReferenceCheck { IfKnown, Required };

// The TLO a change to `tool` may take instead of a probe: stored, measured (not set by hand), not failed in a
// break test, fresh, and measured against the machine's reference (as `check` says). Else why not, in words
// ("… it is measured at its change.").
[[nodiscard]] Result<double> restorableTlo(int tool, const ToolFacts &facts, const QDateTime &now,
    int staleDays, std::optional<double> machineReferenceMz, ReferenceCheck check = ReferenceCheck::IfKnown);

// Each tool of the table.
[[nodiscard]] QHash<int, ToolFacts> factsFromTable(const ToolTable &table);
// What the library holds for `machine`, as the job check asks for it; nothing without a library. The library
// must outlive what this returns.
[[nodiscard]] std::function<Result<void>(QHash<int, ToolFacts> &, const QList<int> &)> libraryFacts(
    const Library *library, const QString &machine);
// Adds what the library holds for `machine` of each of `tools` (its newest measurement and break test). A
// tool the table lacks takes its TLO from the library. Two indexed look-ups a tool (about 0.1 ms in all): the
// job check asks only for the tools it lists (JobReport::kMaxListedTools), never for a program's every tool.
[[nodiscard]] Result<void> addLibraryFacts(
    QHash<int, ToolFacts> &facts, const Library &library, const QString &machine, const QList<int> &tools);
// When the newest the history says of `tool` on `machine` is a failed break test: the TLO it compared with
// (millimetres), which an unlock sets back (the Carvera's firmware halts with the length it measured in
// force). Nothing when the tool was measured, set or given a new cutter since, or never failed.
[[nodiscard]] Result<std::optional<double>> tloBeforeFailedBreakTest(
    const Library &library, const QString &machine, int tool);

} // namespace Toffee
