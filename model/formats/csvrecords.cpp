// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/formats/csvrecords.h"

#include <QCoreApplication>

#include "model/textparsing.h"
#include "model/translate.h"

namespace Toffee {

namespace {

// No field of a tool table holds more (notes: 10,000 characters); a longer one is refused as it is read.
constexpr qsizetype kMaxFieldBytes = 64 * 1024;

bool isBlankChar(char c)
{
    return c == ' ' || c == '\t';
}

QByteArrayView trimmed(QByteArrayView v)
{
    while (!v.isEmpty() && isBlankChar(v.front()))
        v = v.sliced(1);
    while (!v.isEmpty() && isBlankChar(v.back()))
        v.chop(1);
    return v;
}

Error fieldTooLong(QByteArrayView field, int line)
{
    return Error { tr("the field \"%1\" is longer than %2 KB; no column of a tool table holds that much.")
                       .arg(excerpt(field))
                       .arg(kMaxFieldBytes / 1024),
        line };
}

// From inside a quoted field to the quote that closes it, counting the line breaks in the field; false when
// the file ends first. `doubled`: a doubled quote was passed, so the field must be unescaped.
bool toClosingQuote(CsvCursor &in, bool &doubled)
{
    const QByteArrayView data = in.data;
    const qsizetype size = data.size();
    qsizetype &pos = in.pos;
    while (pos < size) {
        const char c = data.at(pos);
        if (c == '"') {
            if (pos + 1 < size && data.at(pos + 1) == '"') {
                doubled = true;
                pos += 2;
                continue;
            }
            return true;
        }
        if (c == '\n')
            ++in.line;
        ++pos;
    }
    return false;
}

// A quoted field, `in` at its opening quote; the blanks after the closing quote are passed too.
Result<void> readQuotedField(CsvCursor &in, CsvRecord &record)
{
    const qsizetype inner = ++in.pos;
    bool doubled = false;
    if (!toClosingQuote(in, doubled))
        return Error { tr("a quoted field is never closed; add the closing quote (\")."), record.line };
    const QByteArrayView content = in.data.sliced(inner, in.pos - inner);
    if (content.size() > kMaxFieldBytes)
        return fieldTooLong(content, record.line);
    ++in.pos; // the closing quote
    if (doubled) {
        record.unescaped.push_back(content.toByteArray().replace("\"\"", "\""));
        record.fields.append(record.unescaped.back());
    } else {
        record.fields.append(content);
    }
    const QByteArrayView data = in.data;
    qsizetype &pos = in.pos;
    while (pos < data.size() && (isBlankChar(data.at(pos)) || data.at(pos) == '\r'))
        ++pos;
    if (pos < data.size() && data.at(pos) != in.separator && data.at(pos) != '\n')
        return Error { tr("text after a closing quote; put the whole field in quotes."), in.line };
    return {};
}

// A field without quotes, trimmed of its blanks (and of the '\r' of a CRLF line end).
Result<void> readPlainField(CsvCursor &in, CsvRecord &record)
{
    const QByteArrayView data = in.data;
    const char separator = in.separator;
    qsizetype &pos = in.pos;
    const qsizetype start = pos;
    while (pos < data.size() && data.at(pos) != separator && data.at(pos) != '\n') {
        if (data.at(pos) == '"')
            return Error { tr("a quote (\") inside an unquoted field; put the whole field in quotes and "
                              "double the quote."),
                in.line };
        ++pos;
    }
    QByteArrayView field = data.sliced(start, pos - start);
    if (field.size() > kMaxFieldBytes)
        return fieldTooLong(field, in.line);
    if (field.endsWith('\r'))
        field.chop(1);
    record.fields.append(trimmed(field));
    return {};
}

} // namespace

Result<void> nextCsvRecord(CsvCursor &in, CsvRecord &record, qsizetype maxFields, bool header)
{
    record.clear();
    record.line = in.line;
    while (true) {
        while (!in.atEnd() && isBlankChar(in.data.at(in.pos)))
            ++in.pos;
        const bool quoted = !in.atEnd() && in.data.at(in.pos) == '"';
        if (auto field = quoted ? readQuotedField(in, record) : readPlainField(in, record); !field)
            return field;
        if (in.atEnd())
            return {};
        if (in.data.at(in.pos++) == '\n') {
            ++in.line;
            return {};
        }
        if (record.fields.size() >= maxFields)
            return Error { header
                    ? tr("the header has more than %1 columns, more than a tool table has.").arg(maxFields)
                    : tr("this row has more fields than the header's %1.").arg(maxFields),
                record.line };
    }
}

// The file's text after the byte-order mark spreadsheets write, once it is known to be UTF-8.
Result<QByteArrayView> csvText(const QByteArray &data)
{
    QByteArrayView all(data);
    if (all.startsWith("\xEF\xBB\xBF"))
        all = all.sliced(3);
    if (const qsizetype bad = firstInvalidUtf8(all); bad >= 0) {
        if (all.at(bad) == '\0')
            return Error { tr("the file holds binary data; it is not a CSV table."), lineAt(all, bad) };
        return Error { tr("the file is not UTF-8 text; save it from the spreadsheet as \"CSV UTF-8\"."),
            lineAt(all, bad) };
    }
    return all;
}

char separatorOf(QByteArrayView all)
{
    const qsizetype firstBreak = all.indexOf('\n');
    const QByteArrayView headerLine = firstBreak < 0 ? all : all.first(firstBreak);
    return !headerLine.contains(',') && headerLine.contains(';') ? ';' : ',';
}

Result<void> readCsvHeader(CsvCursor &in, CsvRecord &header, qsizetype maxFields)
{
    do {
        if (auto r = nextCsvRecord(in, header, maxFields, true); !r)
            return r;
    } while (header.isBlank() && !in.atEnd());
    if (header.isBlank())
        return Error { tr("the file is empty; a CSV tool table starts with a header row such as "
                          "\"number,pocket,description,...\"."),
            1 };
    return {};
}

} // namespace Toffee
