// SPDX-License-Identifier: GPL-3.0-or-later
// CSV with a header row naming the columns (any order; only "number" is required), RFC 4180 quoting.
// A spreadsheet saved with ';' between fields and decimal commas (as German Excel does) reads too.
#include "tablefile.h"

#include <QCoreApplication>
#include <QHash>

#include "textparsing.h"
#include "toolvalidation.h"

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
    UnitsColumn,
    LinuxCnc,
    ColumnCount
};

constexpr const char *kColumnNames[ColumnCount] = {
    "number",      "pocket",      "description", "length_geometry", "length_wear", "radius_geometry",
    "radius_wear", "measured_tlo", "measured_at", "notes",           "units",       "linuxcnc",
};

QString tr(const char *text)
{
    return QCoreApplication::translate("Toffee::CsvFormat", text);
}

struct Record
{
    QList<QByteArray> fields;
    int line = 0;
};

// Splits the next record off `data` at `pos`; quoted fields may hold separators, quotes ("") and line breaks.
Result<Record> nextRecord(QByteArrayView data, qsizetype &pos, int &line, char separator)
{
    Record record;
    record.line = line;
    QByteArray field;
    bool quoted = false;
    bool wasQuoted = false;
    while (pos < data.size()) {
        const char c = data.at(pos++);
        if (quoted) {
            if (c == '"') {
                if (pos < data.size() && data.at(pos) == '"') {
                    field += '"';
                    ++pos;
                } else {
                    quoted = false;
                }
            } else {
                if (c == '\n')
                    ++line;
                field += c;
            }
            continue;
        }
        if (c == '"') {
            if (!field.trimmed().isEmpty() || wasQuoted)
                return Error { tr("a quote (\") inside an unquoted field; put the whole field in quotes and double "
                                  "the quote."),
                               line };
            field.clear();
            quoted = true;
            wasQuoted = true;
        } else if (c == separator) {
            record.fields.append(wasQuoted ? field : field.trimmed());
            field.clear();
            wasQuoted = false;
        } else if (c == '\n') {
            ++line;
            break;
        } else if (c == '\r') {
            continue;
        } else if (wasQuoted) {
            if (c != ' ' && c != '\t')
                return Error { tr("text after a closing quote; put the whole field in quotes."), line };
        } else {
            field += c;
        }
    }
    if (quoted)
        return Error { tr("a quoted field is never closed; add the closing quote (\")."), record.line };
    record.fields.append(wasQuoted ? field : field.trimmed());
    return record;
}

bool isBlank(const Record &record)
{
    return record.fields.size() == 1 && record.fields.front().isEmpty();
}

QByteArray quoted(const QString &text)
{
    QByteArray bytes = text.toUtf8();
    if (!bytes.contains(',') && !bytes.contains('"') && !bytes.contains('\n') && !bytes.contains('\r')
        && bytes.trimmed() == bytes)
        return bytes;
    bytes.replace("\"", "\"\"");
    return '"' + bytes + '"';
}

} // namespace

Result<ToolTable> readCsvTable(const QByteArray &data)
{
    QByteArrayView all(data);
    if (all.startsWith("\xEF\xBB\xBF"))
        all = all.sliced(3); // the byte-order mark spreadsheets write
    if (all.contains('\0'))
        return Error { tr("the file holds binary data; it is not a CSV table."), 1 };
    if (!decodeUtf8(all))
        return Error { tr("the file is not UTF-8 text; save it from the spreadsheet as \"CSV UTF-8\"."), 1 };

    qsizetype pos = 0;
    int line = 1;
    const qsizetype firstBreak = all.indexOf('\n');
    const QByteArrayView headerLine = firstBreak < 0 ? all : all.first(firstBreak);
    const char separator = !headerLine.contains(',') && headerLine.contains(';') ? ';' : ',';

    Record header;
    do {
        auto r = nextRecord(all, pos, line, separator);
        if (!r)
            return r.error();
        header = r.takeValue();
    } while (isBlank(header) && pos < all.size());
    if (isBlank(header))
        return Error { tr("the file is empty; a CSV tool table starts with a header row such as "
                          "\"number,pocket,description,...\"."),
                       1 };

    int columnOf[ColumnCount];
    std::fill(std::begin(columnOf), std::end(columnOf), -1);
    for (int i = 0; i < header.fields.size(); ++i) {
        const QByteArray name = header.fields.at(i).toLower();
        const auto found = std::find_if(std::begin(kColumnNames), std::end(kColumnNames),
                                        [&name](const char *n) { return name == n; });
        if (found == std::end(kColumnNames))
            return Error { tr("unknown column \"%1\" in the header; the columns are number, pocket, description, "
                              "length_geometry, length_wear, radius_geometry, radius_wear, measured_tlo, "
                              "measured_at, notes, units and linuxcnc.")
                               .arg(QString::fromUtf8(header.fields.at(i))),
                           header.line };
        const auto column = found - std::begin(kColumnNames);
        if (columnOf[column] >= 0)
            return Error { tr("the column \"%1\" appears twice in the header.").arg(QLatin1StringView(*found)),
                           header.line };
        columnOf[column] = i;
    }
    if (columnOf[Number] < 0)
        return Error { tr("the header has no \"number\" column."), header.line };

    std::optional<Units> units;
    QList<Tool> tools;
    QList<int> lines;
    QHash<int, int> firstLine;
    while (pos < all.size()) {
        auto r = nextRecord(all, pos, line, separator);
        if (!r)
            return r.error();
        const Record &record = r.value();
        if (isBlank(record))
            continue;
        if (record.fields.size() != header.fields.size())
            return Error { tr("this row has %1 fields but the header has %2.")
                               .arg(record.fields.size())
                               .arg(header.fields.size()),
                           record.line };

        auto cell = [&](Column c) -> QByteArray { return columnOf[c] < 0 ? QByteArray() : record.fields.at(columnOf[c]); };
        auto text = [&](Column c) -> QString { return QString::fromUtf8(cell(c)); };
        QString problem;
        auto decimal = [&](Column c, double fallback) -> double {
            QByteArray s = cell(c);
            if (s.isEmpty())
                return fallback;
            if (separator == ';')
                s.replace(',', '.');
            const auto v = parseDecimal(s);
            if (!v && problem.isEmpty())
                problem = tr("%1 \"%2\" is not a number.").arg(QLatin1StringView(kColumnNames[c]), text(c));
            return v.value_or(fallback);
        };
        auto integer = [&](Column c, int fallback) -> int {
            const QByteArray s = cell(c);
            if (s.isEmpty())
                return fallback;
            const auto v = parseInteger(s);
            if ((!v || *v < INT_MIN || *v > INT_MAX) && problem.isEmpty())
                problem = tr("%1 \"%2\" is not a whole number.").arg(QLatin1StringView(kColumnNames[c]), text(c));
            return v && *v >= INT_MIN && *v <= INT_MAX ? int(*v) : fallback;
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
            tool.measuredAt = QDateTime::fromString(text(MeasuredAt), Qt::ISODateWithMs).toUTC();
            if (!tool.measuredAt.isValid() && problem.isEmpty())
                problem = tr("measured_at \"%1\" is not a date and time (use ISO 8601, e.g. 2026-11-22T10:15:00Z).")
                              .arg(text(MeasuredAt));
        }
        tool.notes = text(Notes);
        tool.linuxCncExtra = text(LinuxCnc);
        if (!cell(UnitsColumn).isEmpty()) {
            const auto rowUnits = unitsFromSymbol(text(UnitsColumn));
            if (!rowUnits)
                return Error { tr("units \"%1\" must be mm or in.").arg(text(UnitsColumn)), record.line };
            if (units && *units != *rowUnits)
                return Error { tr("this row is in %1 but the rows above are in %2; a table has one unit.")
                                   .arg(unitsSymbol(*rowUnits), unitsSymbol(*units)),
                               record.line };
            units = rowUnits;
        }
        if (!problem.isEmpty())
            return Error { problem, record.line };
        if (const int previous = firstLine.value(tool.number); previous > 0)
            return Error { tr("tool %1 is already on line %2; tool numbers must be unique.").arg(tool.number).arg(previous),
                           record.line };
        firstLine.insert(tool.number, record.line);
        tools.append(std::move(tool));
        lines.append(record.line);
    }

    qsizetype bad = -1;
    auto table = ToolTable::fromTools(std::move(tools), units.value_or(Units::Millimetre), &bad);
    if (!table)
        return Error { table.error().message, bad >= 0 ? lines.at(bad) : 0 };
    return table;
}

QByteArray writeCsvTable(const ToolTable &table)
{
    QByteArray out;
    out.reserve(128 + table.size() * 80);
    for (int c = 0; c < ColumnCount; ++c) {
        out += kColumnNames[c];
        out += c + 1 < ColumnCount ? ',' : '\n';
    }
    const QByteArray units = unitsSymbol(table.units()).toLatin1();
    for (const Tool &tool : table.tools()) {
        out += QByteArray::number(tool.number) + ',' + QByteArray::number(tool.pocket) + ','
            + quoted(tool.description) + ',' + formatNumber(tool.lengthGeometry).toLatin1() + ','
            + formatNumber(tool.lengthWear).toLatin1() + ',' + formatNumber(tool.radiusGeometry).toLatin1() + ','
            + formatNumber(tool.radiusWear).toLatin1() + ',';
        if (tool.measuredTlo)
            out += formatNumber(*tool.measuredTlo).toLatin1();
        out += ',';
        if (tool.measuredAt.isValid())
            out += tool.measuredAt.toUTC().toString(Qt::ISODateWithMs).toLatin1();
        out += ',' + quoted(tool.notes) + ',' + units + ',' + quoted(tool.linuxCncExtra) + '\n';
    }
    return out;
}

} // namespace Toffee
