// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QDateTime>
#include <QList>

#include "model/clock.h"
#include "model/tool.h"

namespace Toffee {

// What kind of operation a recording comes from: the history library keeps them apart.
// Pulled: a TLO read from the controller's own table (grblHAL's), which Toffee did not measure.
// NewCutter: another cutter in the tool's pocket: the old cutter's TLO (in oldTlo), wear and break mark end.
enum class RecordingKind : quint8 { Probe, ManualSet, Restore, BreakTest, Pulled, NewCutter };

// What an operation on the machine means for the tool table and its history, carried by its result so that
// the window and the CLI record it with one call (ToolTable::record, ToolDocument::record): a tool's new TLO
// (probed or set by hand) with the reference it is measured against, a break test's verdict, or a stored TLO
// restored. Every length is the machine's, in millimetres, as the history keeps it; the table converts to its
// own units when it records one (ToolTable::recordMeasurement).
struct Recording
{
    int tool = -1;
    std::optional<double> tlo; // a TLO to store, with where it came from and its reference
    TloSource source = TloSource::Probe;
    std::optional<double> referenceMz;
    std::optional<bool> breakTestFailed; // a break test's verdict (no TLO)
    QDateTime at; // UTC
    RecordingKind kind = RecordingKind::Probe;
    // What the machine reported, for the history: the tool's MCS Z, and a break test's numbers.
    std::optional<double> currentMz = std::nullopt;
    std::optional<double> tolerance = std::nullopt;
    std::optional<double> oldTlo = std::nullopt;
    std::optional<double> newTlo = std::nullopt;
    // Each touch's machine Z when the tool was touched more than once (one per cutting edge): the TLO is the
    // highest's, and how far they lie apart is the spread the history trends.
    QList<double> touches = {};

    // Another cutter went into `tool` now: the old cutter's TLO and the reference it was measured against.
    [[nodiscard]] static Recording newCutter(
        int tool, std::optional<double> oldTlo, std::optional<double> oldReferenceMz)
    {
        Recording r;
        r.tool = tool;
        r.at = Clock::now();
        r.kind = RecordingKind::NewCutter;
        r.oldTlo = oldTlo;
        r.referenceMz = oldReferenceMz;
        return r;
    }
};

} // namespace Toffee
