// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QCoreApplication>
#include <QVariant>

#include "model/library/historyevent.h"
#include "model/library/storedtable.h"
#include "model/result.h"
#include "model/units.h"

namespace Toffee {

// A library's rows are input, like a file's: anyone may have written them (another program, an older
// Toffee, a hand in psql), so every value is checked as it is read, by type and by range, and a row that
// fails says which row and why. Pure functions over the values a query returned, so that they are tested
// and fuzzed without a database.
class RowReader
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::RowReader)

public:
    // No tool's JSON comes near this (a description of 255 and notes of 10,000 characters): a longer row's
    // data is not even fetched (the query returns its length instead).
    static constexpr qint64 kMaxToolDataChars = 256 * 1024;

    // The columns of a tools row as the query returns them: number, version, deleted, data (NULL when it is
    // longer than kMaxToolDataChars), the data's length, updated_by, updated_at.
    struct ToolRow
    {
        QVariant number;
        QVariant version;
        QVariant deleted;
        QVariant data;
        QVariant dataChars;
        QVariant updatedBy;
        QVariant updatedAt;
    };
    [[nodiscard]] static Result<StoredTool> tool(const ToolRow &row, Units units);

    // The events table's columns, in the order of docs/LIBRARY.md (id, machine, tool, measured_at, kind, tlo,
    // reference_mz, current_mz, tolerance, old_tlo, new_tlo, failed).
    static constexpr int kEventColumns = 14;
    [[nodiscard]] static Result<HistoryEvent> event(const QVariantList &row);
    // An event as Toffee would write it: what is read back from a row, an outbox, or a file is held to it.
    [[nodiscard]] static Result<void> checkEvent(const HistoryEvent &event);

    // tool_use's columns: id, machine, tool, recorded_at, program, cutting_seconds, feed_path_mm.
    [[nodiscard]] static Result<ToolUse> use(const QVariantList &row);

    // A whole number of an integer column: an integer, or a real that is whole; text, blobs and NULL are not.
    [[nodiscard]] static std::optional<qint64> wholeNumber(const QVariant &value);
    // A finite number of a real column (an integer is one too); text, blobs and non-finite values are not.
    [[nodiscard]] static std::optional<double> finiteNumber(const QVariant &value);
    // How a message shows a value read from a row: short, and saying NULL or what kind of value it is.
    [[nodiscard]] static QString shown(const QVariant &value);
};

} // namespace Toffee
