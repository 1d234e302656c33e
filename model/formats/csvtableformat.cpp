// SPDX-License-Identifier: GPL-3.0-or-later
// CSV with a header row naming the columns (any order; only "number" is required), RFC 4180 quoting.
// A spreadsheet saved with ';' between fields and decimal commas (as German Excel does) reads too.
#include "model/formats/tablefile.h"

#include <list>

#include <QCoreApplication>

#include "model/formats/tablereading.h"
#include "model/textparsing.h"
#include "model/toolvalidation.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

enum Column {
    Number,
    Pocket,
    Description,
    LengthGeometry,
    LengthWear,
    RadiusGeometry,
    RadiusWear,
    MeasuredTlo,
    MeasuredAt,
    Notes,
    TloSourceColumn,
    BreakTestColumn,
    ReferenceMzColumn,
    UnitsColumn,
    LinuxCnc,
    ColumnCount
};

constexpr const char *kColumnNames[ColumnCount] = {
    "number",
    "pocket",
    "description",
    "length_geometry",
    "length_wear",
    "radius_geometry",
    "radius_wear",
    "measured_tlo",
    "measured_at",
    "notes",
    "tlo_source",
    "break_test",
    "reference_mz",
    "units",
    "linuxcnc",
};

// One row: each field a view into the file, or into `unescaped` for a quoted field with doubled quotes.
struct Record
{
    QList<QByteArrayView> fields;
    std::list<QByteArray> unescaped; // std::list: views into it stay valid as it grows
    int line = 0;

    void clear()
    {
        fields.clear();
        unescaped.clear();
    }
};

QByteArrayView trimmed(QByteArrayView v)
{
    while (!v.isEmpty() && (v.front() == ' ' || v.front() == '\t'))
        v = v.sliced(1);
    while (!v.isEmpty() && (v.back() == ' ' || v.back() == '\t'))
        v.chop(1);
    return v;
}

// No field of a tool table holds more (notes: 10,000 characters); a longer one is refused as it is read.
constexpr qsizetype kMaxFieldBytes = 64 * 1024;

Error fieldTooLong(QByteArrayView field, int line)
{
    return Error { tr("the field \"%1\" is longer than %2 KB; no column of a tool table holds that much.")
                       .arg(excerpt(field))
                       .arg(kMaxFieldBytes / 1024),
        line };
}

// Splits the next record off `data` at `pos`; quoted fields may hold separators, quotes ("") and line breaks.
// A record of more than `maxFields` fields is refused at the first field too many, before it is all split.
Result<void> nextRecord(QByteArrayView data, qsizetype &pos, int &line, char separator, Record &record,
    qsizetype maxFields, bool header = false)
{
    record.clear();
    record.line = line;
    const qsizetype size = data.size();
    while (true) {
        // Leading blanks, then either a quoted field or a plain one.
        qsizetype start = pos;
        while (pos < size && (data.at(pos) == ' ' || data.at(pos) == '\t'))
            ++pos;
        if (pos < size && data.at(pos) == '"') {
            ++pos;
            const qsizetype inner = pos;
            bool doubled = false;
            while (true) {
                if (pos >= size)
                    return Error { tr("a quoted field is never closed; add the closing quote (\")."),
                        record.line };
                const char c = data.at(pos);
                if (c == '"') {
                    if (pos + 1 < size && data.at(pos + 1) == '"') {
                        doubled = true;
                        pos += 2;
                        continue;
                    }
                    break;
                }
                if (c == '\n')
                    ++line;
                ++pos;
            }
            const QByteArrayView content = data.sliced(inner, pos - inner);
            if (content.size() > kMaxFieldBytes)
                return fieldTooLong(content, record.line);
            ++pos; // the closing quote
            if (doubled) {
                record.unescaped.push_back(content.toByteArray().replace("\"\"", "\""));
                record.fields.append(record.unescaped.back());
            } else {
                record.fields.append(content);
            }
            while (pos < size && (data.at(pos) == ' ' || data.at(pos) == '\t' || data.at(pos) == '\r'))
                ++pos;
            if (pos < size && data.at(pos) != separator && data.at(pos) != '\n')
                return Error { tr("text after a closing quote; put the whole field in quotes."), line };
        } else {
            start = pos;
            while (pos < size && data.at(pos) != separator && data.at(pos) != '\n') {
                if (data.at(pos) == '"')
                    return Error {
                        tr("a quote (\") inside an unquoted field; put the whole field in quotes and "
                           "double the quote."),
                        line
                    };
                ++pos;
            }
            QByteArrayView field = data.sliced(start, pos - start);
            if (field.size() > kMaxFieldBytes)
                return fieldTooLong(field, line);
            if (field.endsWith('\r'))
                field.chop(1);
            record.fields.append(trimmed(field));
        }
        if (pos >= size)
            return {};
        if (data.at(pos++) == '\n') {
            ++line;
            return {};
        }
        if (record.fields.size() >= maxFields)
            return Error { header
                    ? tr("the header has more than %1 columns, more than a tool table has.").arg(maxFields)
                    : tr("this row has more fields than the header's %1.").arg(maxFields),
                record.line };
    }
}

bool isBlank(const Record &record)
{
    return record.fields.size() == 1 && record.fields.front().isEmpty();
}

QString fromUtf8(QByteArrayView v)
{
    return QString::fromUtf8(v); // the whole file was checked to be UTF-8 up front
}

// A field as RFC 4180 wants it: quoted (quotes doubled) when it holds a separator, a quote, a line break, or
// blanks at either end that a reader would otherwise trim.
void appendField(QByteArray &out, const QString &text)
{
    if (text.isEmpty())
        return;
    bool needsQuotes
        = text.front() == u' ' || text.back() == u' ' || text.front() == u'\t' || text.back() == u'\t';
    for (QChar c : text) {
        if (c == u',' || c == u'"' || c == u'\n' || c == u'\r' || c == u';') {
            needsQuotes = true;
            break;
        }
    }
    if (!needsQuotes) {
        appendUtf8(out, text);
        return;
    }
    out += '"';
    appendUtf8(out, QString(text).replace(u'"', u"\"\""_s));
    out += '"';
}

} // namespace

Result<ToolTable> readCsvTable(const QByteArray &data)
{
    QByteArrayView all(data);
    if (all.startsWith("\xEF\xBB\xBF"))
        all = all.sliced(3); // the byte-order mark spreadsheets write
    if (const qsizetype bad = firstInvalidUtf8(all); bad >= 0) {
        if (all.at(bad) == '\0')
            return Error { tr("the file holds binary data; it is not a CSV table."), lineAt(all, bad) };
        return Error { tr("the file is not UTF-8 text; save it from the spreadsheet as \"CSV UTF-8\"."),
            lineAt(all, bad) };
    }

    qsizetype pos = 0;
    int line = 1;
    const qsizetype firstBreak = all.indexOf('\n');
    const QByteArrayView headerLine = firstBreak < 0 ? all : all.first(firstBreak);
    const char separator = !headerLine.contains(',') && headerLine.contains(';') ? ';' : ',';

    Record header;
    do {
        if (auto r = nextRecord(all, pos, line, separator, header, ColumnCount, true); !r)
            return r.error();
    } while (isBlank(header) && pos < all.size());
    if (isBlank(header))
        return Error { tr("the file is empty; a CSV tool table starts with a header row such as "
                          "\"number,pocket,description,...\"."),
            1 };

    int columnOf[ColumnCount];
    std::fill(std::begin(columnOf), std::end(columnOf), -1);
    for (int i = 0; i < header.fields.size(); ++i) {
        const QByteArray name = header.fields.at(i).toByteArray().toLower();
        const auto found = std::find_if(
            std::begin(kColumnNames), std::end(kColumnNames), [&name](const char *n) { return name == n; });
        if (found == std::end(kColumnNames))
            return Error {
                tr("unknown column \"%1\" in the header; the columns are number, pocket, description, "
                   "length_geometry, length_wear, radius_geometry, radius_wear, measured_tlo, "
                   "measured_at, notes, tlo_source, break_test, reference_mz, units and linuxcnc.")
                    .arg(excerpt(header.fields.at(i))),
                header.line
            };
        const auto column = found - std::begin(kColumnNames);
        if (columnOf[column] >= 0)
            return Error {
                tr("the column \"%1\" appears twice in the header.").arg(QLatin1StringView(*found)),
                header.line
            };
        columnOf[column] = i;
    }
    if (columnOf[Number] < 0)
        return Error { tr("the header has no \"number\" column."), header.line };

    std::optional<Units> units;
    ToolCollector tools(all);
    Record record;
    QByteArray commaDecimal;
    while (pos < all.size()) {
        if (auto r = nextRecord(all, pos, line, separator, record, header.fields.size()); !r)
            return r.error();
        if (isBlank(record))
            continue;
        if (record.fields.size() != header.fields.size())
            return Error { tr("this row has %1 fields but the header has %2.")
                               .arg(record.fields.size())
                               .arg(header.fields.size()),
                record.line };

        auto cell = [&](Column c) {
            return columnOf[c] < 0 ? QByteArrayView() : record.fields.at(columnOf[c]);
        };
        auto text = [&](Column c) {
            return fromUtf8(cell(c));
        };
        QString problem;
        auto decimal = [&](Column c, double fallback) -> double {
            QByteArrayView s = cell(c);
            if (s.isEmpty())
                return fallback;
            if (separator == ';' && s.contains(',')) {
                commaDecimal = s.toByteArray().replace(',', '.');
                s = commaDecimal;
            }
            const auto v = parseDecimal(s);
            if (!v && problem.isEmpty())
                problem = tr("%1 \"%2\" is not a number.")
                              .arg(QLatin1StringView(kColumnNames[c]), excerpt(cell(c)));
            return v.value_or(fallback);
        };
        auto integer = [&](Column c, int fallback) -> int {
            const QByteArrayView s = cell(c);
            if (s.isEmpty())
                return fallback;
            const auto v = parseInteger(s);
            const bool fits = v && *v >= INT_MIN && *v <= INT_MAX;
            if (!fits && problem.isEmpty()) {
                // A whole number too large for any tool or pocket says so, not "not a whole number".
                problem = isIntegerText(s)
                    ? (c == Number ? tr("tool number %1 is out of range; use %2 to %3.")
                                         .arg(excerpt(s))
                                         .arg(Limits::kMinToolNumber)
                                         .arg(Limits::kMaxToolNumber)
                                   : tr("pocket %1 is out of range; use %2 to %3.")
                                         .arg(excerpt(s))
                                         .arg(Limits::kMinPocket)
                                         .arg(Limits::kMaxPocket))
                    : tr("%1 \"%2\" is not a whole number.")
                          .arg(QLatin1StringView(kColumnNames[c]), excerpt(s));
            }
            return fits ? int(*v) : fallback;
        };

        if (cell(Number).isEmpty())
            return Error { tr("the row has no tool number."), record.line };
        Tool tool;
        tool.number = integer(Number, 0);
        tool.pocket = integer(Pocket, defaultPocket(tool.number));
        tool.description = text(Description);
        tool.lengthGeometry = decimal(LengthGeometry, 0.0);
        tool.lengthWear = decimal(LengthWear, 0.0);
        tool.radiusGeometry = decimal(RadiusGeometry, 0.0);
        tool.radiusWear = decimal(RadiusWear, 0.0);
        if (!cell(MeasuredTlo).isEmpty())
            tool.measuredTlo = decimal(MeasuredTlo, 0.0);
        if (!cell(MeasuredAt).isEmpty()) {
            tool.measuredAt = parseIsoDateTime(cell(MeasuredAt));
            if (!tool.measuredAt.isValid() && problem.isEmpty())
                problem = tr(
                    "measured_at \"%1\" is not a date and time (use ISO 8601, e.g. 2026-11-22T10:15:00Z).")
                              .arg(excerpt(cell(MeasuredAt)));
        }
        tool.notes = text(Notes);
        if (const QByteArrayView source = cell(TloSourceColumn); source == "manual")
            tool.tloSource = TloSource::Manual;
        else if (!source.isEmpty() && source != "probe" && problem.isEmpty())
            problem = tr("tlo_source \"%1\" must be probe, manual or empty.").arg(excerpt(source));
        if (const QByteArrayView test = cell(BreakTestColumn); test == "failed")
            tool.breakTestFailed = true;
        else if (!test.isEmpty() && test != "passed" && problem.isEmpty())
            problem = tr("break_test \"%1\" must be failed, passed or empty.").arg(excerpt(test));
        if (!cell(ReferenceMzColumn).isEmpty())
            tool.referenceMz = decimal(ReferenceMzColumn, 0.0);
        tool.linuxCncExtra = text(LinuxCnc);
        if (const QByteArrayView u = cell(UnitsColumn); !u.isEmpty()) {
            const auto rowUnits = u == "mm" ? Units::Millimetre
                : u == "in"                 ? Units::Inch
                                            : unitsFromSymbol(text(UnitsColumn));
            if (!rowUnits)
                return Error { tr("units \"%1\" must be mm or in.").arg(excerpt(cell(UnitsColumn))),
                    record.line };
            if (units && *units != *rowUnits)
                return Error { tr("this row is in %1 but the rows above are in %2; a table has one unit.")
                                   .arg(unitsSymbol(*rowUnits), unitsSymbol(*units)),
                    record.line };
            units = rowUnits;
        }
        if (!problem.isEmpty())
            return Error { problem, record.line };
        if (auto added = tools.add(std::move(tool), record.line, units.value_or(Units::Millimetre)); !added)
            return added.error();
    }
    return tools.build(units.value_or(Units::Millimetre));
}

bool writeCsvTable(const ToolTable &table, const ByteSink &sink)
{
    ChunkedWriter w(sink);
    QByteArray &out = w.out;
    for (int c = 0; c < ColumnCount; ++c) {
        out += kColumnNames[c];
        out += c + 1 < ColumnCount ? ',' : '\n';
    }
    const QByteArray units = unitsSymbol(table.units()).toLatin1();
    for (const Tool &tool : table.tools()) {
        out += QByteArray::number(tool.number);
        out += ',';
        out += QByteArray::number(tool.pocket);
        out += ',';
        appendField(out, tool.description);
        for (double v : { tool.lengthGeometry, tool.lengthWear, tool.radiusGeometry, tool.radiusWear }) {
            out += ',';
            appendNumber(out, v);
        }
        out += ',';
        if (tool.measuredTlo)
            appendNumber(out, *tool.measuredTlo);
        out += ',';
        if (tool.measuredAt.isValid())
            appendIsoUtc(out, tool.measuredAt);
        out += ',';
        appendField(out, tool.notes);
        out += ',';
        if (tool.measuredTlo)
            out += tool.tloSource == TloSource::Manual ? "manual" : "probe";
        out += ',';
        if (tool.breakTestFailed)
            out += "failed";
        out += ',';
        if (tool.referenceMz)
            appendNumber(out, *tool.referenceMz);
        out += ',';
        out += units;
        out += ',';
        appendField(out, tool.linuxCncExtra);
        out += '\n';
        if (!w.next())
            return false;
    }
    return w.finish();
}

QByteArray writeCsvTable(const ToolTable &table)
{
    return collect(table, [](const ToolTable &t, const ByteSink &s) { return writeCsvTable(t, s); });
}

} // namespace Toffee
