// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QDateTime>
#include <QList>
#include <QString>

#include "model/recording.h"
#include "model/result.h"

namespace Toffee {

// What happened to a tool's length: measured on the tool setter, break-tested, set by hand, restored from the
// table, or imported from elsewhere. Stored by these names (docs/LIBRARY.md).
// Import: a TLO read in from elsewhere, as from a controller's own table (grblHAL's, pull-offsets), set there
// by someone else and not measured by Toffee.
// NewCutter: another cutter went into the tool's number: the events before it are the old cutter's (its TLO
// in old_tlo), and its trend, uses and break mark end there.
enum class EventKind { Probe, BreakTest, ManualSet, Restore, Import, NewCutter };

[[nodiscard]] QString eventKindName(
    EventKind kind); // "probe", "break_test", "manual_set", "restore", "import", "new_cutter"
[[nodiscard]] std::optional<EventKind> eventKindFromName(QStringView name);

// One measurement event, as the history library keeps it. Lengths in millimetres; what the machine did not
// report stays empty.
struct HistoryEvent
{
    QString id; // a UUID made where the event happened: written twice, it is still one row
    QString machine;
    int tool = 0;
    QDateTime at; // UTC, to the millisecond
    EventKind kind = EventKind::Probe;
    std::optional<double> tlo; // the TLO the tool has after the event
    std::optional<double> referenceMz;
    std::optional<double> currentMz;
    std::optional<double> tolerance; // a break test's
    std::optional<double> oldTlo; // a break test's: what it compared against ...
    std::optional<double> newTlo; // ... and what it measured
    std::optional<bool> failed; // a break test's verdict
    // Each touch's machine Z when the tool was touched more than once (one per cutting edge): tlo is the
    // highest's. Empty for one touch.
    QList<double> touches = {};

    // How far the touches lie apart (the longest edge from the shortest); none for one touch.
    [[nodiscard]] std::optional<double> spread() const;

    [[nodiscard]] static QString newId();
    friend bool operator==(const HistoryEvent &, const HistoryEvent &) = default;
};

// Whether the history can take `event`: a tool number, lengths a machine can hold (a TLO within the one
// range, isMachineTlo; machine positions within kMaxMachineMillimetres), a time. A value refused anywhere
// else is refused here too, so that no station's event (an older Toffee's, a damaged outbox file) reaches the
// history with it.
[[nodiscard]] Result<void> validateEvent(const HistoryEvent &event);

// When the cutter in the tool's pocket went in: the newest NewCutter among one tool's `events`; invalid when
// none (the cutter the history began with).
[[nodiscard]] QDateTime cutterSince(const QList<HistoryEvent> &events);

// The history's view of an operation the window or toffee-cli recorded, on `machine`.
[[nodiscard]] HistoryEvent historyEvent(const Recording &recording, const QString &machine);

// Touches as the library keeps them: each machine Z, space-separated ("-80 -79.972"); and back, nothing when
// the text is not such a list of at most ProbeSettings::kMaxTouches numbers a machine reads.
[[nodiscard]] QString touchesText(const QList<double> &touches);
[[nodiscard]] std::optional<QList<double>> touchesFromText(const QString &text);

// Events as CSV, a header line and a row each, every column of the library's events table (docs/LIBRARY.md).
[[nodiscard]] QByteArray eventsAsCsv(const QList<HistoryEvent> &events);

// A program that ran on a machine, and what each tool did in it.
struct ToolUse
{
    QString id;
    QString machine;
    int tool = 0;
    QDateTime at; // when the operator said it ran (UTC)
    QString program; // the program's file name, for people
    double cuttingSeconds = 0.0; // feed moves at their F
    double feedPathMm = 0.0;
    friend bool operator==(const ToolUse &, const ToolUse &) = default;
};

// The machine's name when none is given (toffee-cli --machine, the window's setting).
inline const QString kDefaultMachineName = QStringLiteral("Carvera");

// A machine the library knows: its name (the key), its controller dialect, and how Toffee reaches it.
struct MachineRecord
{
    QString name;
    QString dialect; // as toffee-cli names it: carvera, fanuc, …
    QString connection; // "emulator", "/dev/ttyUSB0 115200", …
    friend bool operator==(const MachineRecord &, const MachineRecord &) = default;
};

// How well a machine's tool setter repeats (toffee-cli measure-repeatability): one tool touched several times
// on the same edge, each touch's machine Z. Its spread is the smallest difference a break test can trust.
struct SetterRepeatability
{
    int tool = 0;
    QDateTime at; // UTC
    QList<double> touches;
    [[nodiscard]] double spread() const;
    friend bool operator==(const SetterRepeatability &, const SetterRepeatability &) = default;
};

// Which events to read: all of them, or one machine's, one tool's, since a time.
struct HistoryQuery
{
    QString machine; // empty: every machine
    std::optional<int> tool;
    QDateTime since; // invalid: from the start
    int limit = 0; // 0: no limit; else the newest `limit`, still returned oldest first
    QList<EventKind> kinds = {}; // empty: every kind
};

} // namespace Toffee
