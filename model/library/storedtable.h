// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QCoreApplication>
#include <QDateTime>
#include <QHash>
#include <QList>
#include <QString>

#include "model/recording.h"
#include "model/result.h"
#include "model/tooltable.h"

namespace Toffee {

struct HistoryEvent;

// A tool as a library's machine table holds it: its row's version goes up by one at every write, and a
// removed tool stays as a deleted row, so that its removal has a version too.
struct StoredTool
{
    int number = 0;
    std::optional<Tool> tool; // empty: removed
    qint64 version = 0;
    QString updatedBy; // the station that wrote it last
    QDateTime updatedAt;
    friend bool operator==(const StoredTool &, const StoredTool &) = default;
};

struct StoredTable
{
    QString machine;
    Units units = Units::Millimetre;
    QList<StoredTool> rows; // by number, removed ones included

    // The tools that are not removed.
    [[nodiscard]] ToolTable table() const;
    [[nodiscard]] const StoredTool *row(int number) const;
};

// One tool to write: the tool (or its removal), and the row the station last read: its version (0 when it
// read none, a new tool) and what it held, so that a change made meanwhile to other fields merges. Without
// `base`, a tool changed meanwhile is always a conflict.
struct ToolWrite
{
    int number = 0;
    std::optional<Tool> tool;
    qint64 baseVersion = 0;
    std::optional<Tool> base = std::nullopt;
    friend bool operator==(const ToolWrite &, const ToolWrite &) = default;
};

// A tool another station changed since this one read it: both sides, for the operator to choose.
struct ToolConflict
{
    int number = 0;
    std::optional<Tool> theirs; // empty: they removed it
    std::optional<Tool> mine; // empty: this station removed it
    qint64 theirVersion = 0;
    QString theirStation;
};

struct WriteOutcome
{
    QHash<int, qint64> written; // each written tool's new version
    // The tools another station had changed in other fields: what was written, theirs and mine merged.
    QHash<int, std::optional<Tool>> merged;
    QList<ToolConflict> conflicts;
    bool queued = false; // the shared library was out of reach: the writes wait in the outbox
};

// What a station keeps for a shared library it cannot reach: events, or a table's tool writes.
struct OutboxEntry
{
    QString id; // unique: the entry is removed by it once written
    QString library; // the shared library's identity (LibraryLocation::identity; older: its text)
    QString kind; // "events" or "tools"
    QByteArray payload; // JSON (outboxjson.cpp)
    QDateTime at;
};

// A tool as its row's data: the native JSON format's tool object. Read back with its units.
[[nodiscard]] QByteArray toolData(const Tool &tool, Units units);
[[nodiscard]] Result<Tool> toolFromData(const QByteArray &data, Units units);

// What the event does to the table's tool, as the document records it (ToolTable::record).
[[nodiscard]] std::optional<Recording> recordingOf(const HistoryEvent &event);

// Three-way merge of one tool: each field takes the side that changed it from `base`. Empty when both sides
// changed the same field to different values (or one removed the tool the other changed).
[[nodiscard]] std::optional<std::optional<Tool>> mergeTool(
    const std::optional<Tool> &base, const std::optional<Tool> &theirs, const std::optional<Tool> &mine);

} // namespace Toffee
