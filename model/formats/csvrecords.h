// SPDX-License-Identifier: GPL-3.0-or-later
// The CSV reader's first half, on its own so that the reader's file stays about what the columns mean: a file
// split into records (RFC 4180 quoting), each field a view into the file. Not part of the model's interface.
#pragma once

#include <list>

#include <QByteArray>
#include <QByteArrayView>
#include <QList>

#include "model/result.h"

namespace Toffee {

// One row: each field a view into the file, or into `unescaped` for a quoted field with doubled quotes.
struct CsvRecord
{
    QList<QByteArrayView> fields;
    std::list<QByteArray> unescaped; // std::list: views into it stay valid as it grows
    int line = 0;

    void clear()
    {
        fields.clear();
        unescaped.clear();
    }
    // An empty line, which the reader skips.
    [[nodiscard]] bool isBlank() const { return fields.size() == 1 && fields.front().isEmpty(); }
};

// Where the reader is in the file: the next byte to split, and the line it is on.
struct CsvCursor
{
    CsvCursor(QByteArrayView data, char separator)
        : data(data)
        , separator(separator)
    { }

    QByteArrayView data;
    char separator;
    qsizetype pos = 0;
    int line = 1;

    [[nodiscard]] bool atEnd() const { return pos >= data.size(); }
};

// Splits the next record off at `in`; quoted fields may hold separators, quotes ("") and line breaks.
// A record of more than `maxFields` fields is refused at the first field too many, before it is all split;
// `header` says whether the message speaks of the header's columns or of a row's fields.
[[nodiscard]] Result<void> nextCsvRecord(
    CsvCursor &in, CsvRecord &record, qsizetype maxFields, bool header = false);

// The header: the first record that is not an empty line, at most `maxFields` fields.
[[nodiscard]] Result<void> readCsvHeader(CsvCursor &in, CsvRecord &header, qsizetype maxFields);
// The file's text after the byte-order mark spreadsheets write, or why it is no text (binary, not UTF-8).
[[nodiscard]] Result<QByteArrayView> csvText(const QByteArray &data);
// ';' when the header has it and no ',': how a spreadsheet whose decimal mark is the comma saves.
[[nodiscard]] char separatorOf(QByteArrayView all);

} // namespace Toffee
