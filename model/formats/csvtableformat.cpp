// SPDX-License-Identifier: GPL-3.0-or-later
// CSV with a header row naming the columns (any order; only "number" is required), RFC 4180 quoting.
// A spreadsheet saved with ';' between fields and decimal commas (as German Excel does) reads too.
#include "model/formats/tablefile.h"

#include <array>

#include <QCoreApplication>

#include "model/formats/csvrecords.h"
#include "model/formats/tablereading.h"
#include "model/numberformat.h"
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
    CutterTypeColumn,
    OverallLengthColumn,
    LifeLimitMinutesColumn,
    LifeLimitUsesColumn,
    FlutesColumn,
    ProbeXColumn,
    ProbeYColumn,
    ProbeTouchesColumn,
    ProbeTurnColumn,
    ProbeLatchFeedColumn,
    SpreadLimitColumn,
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
    "cutter_type",
    "overall_length",
    "life_limit_minutes",
    "life_limit_uses",
    "flutes",
    "probe_x",
    "probe_y",
    "probe_touches",
    "probe_turn",
    "probe_latch_feed",
    "spread_limit",
};

QString fromUtf8(QByteArrayView v)
{
    return QString::fromUtf8(v); // the whole file was checked to be UTF-8 up front
}

// Which field of a row holds each column; -1 for a column the file does not have.
using ColumnMap = std::array<int, ColumnCount>;

QString allColumnNames()
{
    QStringList names;
    for (const char *name : kColumnNames)
        names << QLatin1StringView(name);
    return names.join(u", "_s);
}

Result<ColumnMap> mapColumns(const CsvRecord &header)
{
    ColumnMap columnOf;
    columnOf.fill(-1);
    for (int i = 0; i < header.fields.size(); ++i) {
        const QByteArray name = header.fields.at(i).toByteArray().toLower();
        const auto found = std::find_if(
            std::begin(kColumnNames), std::end(kColumnNames), [&name](const char *n) { return name == n; });
        if (found == std::end(kColumnNames))
            return Error { tr("unknown column \"%1\" in the header; the columns are %2.")
                               .arg(excerpt(header.fields.at(i)), allColumnNames()),
                header.line };
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
    return columnOf;
}

// A row being read into a tool, and the first problem found in its fields: the row reports only that one,
// once every field is read.
struct Row
{
    Row(const CsvRecord &record, const ColumnMap &columnOf, char separator)
        : record(record)
        , columnOf(columnOf)
        , separator(separator)
    { }

    const CsvRecord &record;
    const ColumnMap &columnOf;
    const char separator;
    QString problem;
    QByteArray commaDecimal; // a number written with a decimal comma, as a number with a point

    QByteArrayView cell(Column c) const
    {
        return columnOf[c] < 0 ? QByteArrayView() : record.fields.at(columnOf[c]);
    }
    QString text(Column c) const { return fromUtf8(cell(c)); }
};

double decimal(Row &row, Column c, double fallback)
{
    QByteArrayView s = row.cell(c);
    if (s.isEmpty())
        return fallback;
    if (row.separator == ';' && s.contains(',')) {
        row.commaDecimal = s.toByteArray().replace(',', '.');
        s = row.commaDecimal;
    }
    const auto v = parseDecimal(s);
    if (!v && row.problem.isEmpty())
        row.problem
            = tr("%1 \"%2\" is not a number.").arg(QLatin1StringView(kColumnNames[c]), excerpt(row.cell(c)));
    return v.value_or(fallback);
}

// Why `s`, in the Number or Pocket column, is no tool or pocket number.
QString notAWholeNumber(Column c, QByteArrayView s)
{
    // A whole number too large for any tool or pocket says so, not "not a whole number".
    if (!isIntegerText(s))
        return tr("%1 \"%2\" is not a whole number.").arg(QLatin1StringView(kColumnNames[c]), excerpt(s));
    if (c == Number)
        return tr("tool number %1 is out of range; use %2 to %3.")
            .arg(excerpt(s))
            .arg(Limits::kMinToolNumber)
            .arg(Limits::kMaxToolNumber);
    return tr("pocket %1 is out of range; use %2 to %3.")
        .arg(excerpt(s))
        .arg(Limits::kMinPocket)
        .arg(Limits::kMaxPocket);
}

int integer(Row &row, Column c, int fallback)
{
    const QByteArrayView s = row.cell(c);
    if (s.isEmpty())
        return fallback;
    const auto v = parseInteger(s);
    const bool fits = v && *v >= INT_MIN && *v <= INT_MAX;
    if (!fits && row.problem.isEmpty())
        row.problem = notAWholeNumber(c, s);
    return fits ? int(*v) : fallback;
}

void readMeasurement(Row &row, Tool &tool)
{
    if (!row.cell(MeasuredTlo).isEmpty())
        tool.measuredTlo = decimal(row, MeasuredTlo, 0.0);
    if (const QByteArrayView at = row.cell(MeasuredAt); !at.isEmpty()) {
        tool.measuredAt = parseIsoDateTime(at);
        if (!tool.measuredAt.isValid() && row.problem.isEmpty())
            row.problem
                = tr("measured_at \"%1\" is not a date and time (use ISO 8601, e.g. 2026-11-22T10:15:00Z).")
                      .arg(excerpt(at));
    }
}

// How the TLO was set, the break test's mark and the reference it was measured against.
void readMarks(Row &row, Tool &tool)
{
    const QByteArrayView source = row.cell(TloSourceColumn);
    if (const auto known = tloSourceFromName(source))
        tool.tloSource = *known;
    else if (!source.isEmpty() && row.problem.isEmpty())
        row.problem = tr("tlo_source \"%1\" must be probe, manual, pulled or empty.").arg(excerpt(source));
    if (const QByteArrayView test = row.cell(BreakTestColumn); test == "failed")
        tool.breakTestFailed = true;
    else if (!test.isEmpty() && test != "passed" && row.problem.isEmpty())
        row.problem = tr("break_test \"%1\" must be failed, passed or empty.").arg(excerpt(test));
    if (!row.cell(ReferenceMzColumn).isEmpty())
        tool.referenceMz = decimal(row, ReferenceMzColumn, 0.0);
}

// How the tool is probed: empty cells are the defaults; probe_turn is "no" for touches on the same edge.
void readProbing(Row &row, Tool &tool)
{
    const auto optionalInteger = [&row](Column c) {
        return row.cell(c).isEmpty() ? std::nullopt : std::optional<int>(integer(row, c, 0));
    };
    const auto optionalDecimal = [&row](Column c) {
        return row.cell(c).isEmpty() ? std::nullopt : std::optional<double>(decimal(row, c, 0.0));
    };
    tool.flutes = optionalInteger(FlutesColumn);
    tool.probing.offsetX = decimal(row, ProbeXColumn, 0.0);
    tool.probing.offsetY = decimal(row, ProbeYColumn, 0.0);
    tool.probing.touches = optionalInteger(ProbeTouchesColumn);
    if (const QByteArrayView turn = row.cell(ProbeTurnColumn); turn == "no")
        tool.probing.turn = false;
    else if (!turn.isEmpty() && turn != "yes" && row.problem.isEmpty())
        row.problem = tr("probe_turn \"%1\" must be yes, no or empty.").arg(excerpt(turn));
    tool.probing.latchFeed = optionalDecimal(ProbeLatchFeedColumn);
    tool.probing.spreadLimit = optionalDecimal(SpreadLimitColumn);
}

// The fields are read in the order of the columns, so that a row with two faults reports the first.
Tool toolFrom(Row &row)
{
    Tool tool;
    tool.number = integer(row, Number, 0);
    tool.pocket = integer(row, Pocket, defaultPocket(tool.number));
    tool.description = row.text(Description);
    tool.lengthGeometry = decimal(row, LengthGeometry, 0.0);
    tool.lengthWear = decimal(row, LengthWear, 0.0);
    tool.radiusGeometry = decimal(row, RadiusGeometry, 0.0);
    tool.radiusWear = decimal(row, RadiusWear, 0.0);
    readMeasurement(row, tool);
    tool.notes = row.text(Notes);
    readMarks(row, tool);
    tool.linuxCncExtra = row.text(LinuxCnc);
    tool.cutterType = row.text(CutterTypeColumn);
    if (!row.cell(OverallLengthColumn).isEmpty())
        tool.overallLength = decimal(row, OverallLengthColumn, 0.0);
    if (!row.cell(LifeLimitMinutesColumn).isEmpty())
        tool.lifeLimitMinutes = decimal(row, LifeLimitMinutesColumn, 0.0);
    if (!row.cell(LifeLimitUsesColumn).isEmpty())
        tool.lifeLimitUses = integer(row, LifeLimitUsesColumn, 0);
    readProbing(row, tool);
    return tool;
}

// A row may name its units; every row that does must name the same.
Result<void> readUnits(const Row &row, std::optional<Units> &units)
{
    const QByteArrayView u = row.cell(UnitsColumn);
    if (u.isEmpty())
        return {};
    const auto rowUnits = u == "mm" ? Units::Millimetre
        : u == "in"                 ? Units::Inch
                                    : unitsFromSymbol(row.text(UnitsColumn));
    if (!rowUnits)
        return Error { tr("units \"%1\" must be mm or in.").arg(excerpt(u)), row.record.line };
    if (units && *units != *rowUnits)
        return Error { tr("this row is in %1 but the rows above are in %2; a table has one unit.")
                           .arg(unitsSymbol(*rowUnits), unitsSymbol(*units)),
            row.record.line };
    units = rowUnits;
    return {};
}

Result<ToolTable> readRows(CsvCursor &in, const CsvRecord &header, const ColumnMap &columnOf)
{
    std::optional<Units> units;
    ToolCollector tools(in.data);
    CsvRecord record;
    while (!in.atEnd()) {
        if (auto r = nextCsvRecord(in, record, header.fields.size()); !r)
            return r.error();
        if (record.isBlank())
            continue;
        if (record.fields.size() != header.fields.size())
            return Error { tr("this row has %1 fields but the header has %2.")
                               .arg(record.fields.size())
                               .arg(header.fields.size()),
                record.line };
        Row row(record, columnOf, in.separator);
        if (row.cell(Number).isEmpty())
            return Error { tr("the row has no tool number."), record.line };
        Tool tool = toolFrom(row);
        if (auto known = readUnits(row, units); !known)
            return known.error();
        if (!row.problem.isEmpty())
            return Error { row.problem, record.line };
        if (auto added = tools.add(std::move(tool), record.line, units.value_or(Units::Millimetre)); !added)
            return added.error();
    }
    return tools.build(units.value_or(Units::Millimetre));
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

// The probing columns, each empty at its default.
void appendProbing(QByteArray &out, const Tool &tool)
{
    const ProbeSettings &p = tool.probing;
    out += ',';
    if (tool.flutes)
        out += QByteArray::number(*tool.flutes);
    for (double v : { p.offsetX, p.offsetY }) {
        out += ',';
        if (v != 0.0)
            appendNumber(out, v);
    }
    out += ',';
    if (p.touches)
        out += QByteArray::number(*p.touches);
    out += p.turn ? "," : ",no";
    for (const std::optional<double> &v : { p.latchFeed, p.spreadLimit }) {
        out += ',';
        if (v)
            appendNumber(out, *v);
    }
}

} // namespace

Result<ToolTable> readCsvTable(const QByteArray &data)
{
    const auto text = csvText(data);
    if (!text)
        return text.error();
    CsvCursor in(text.value(), separatorOf(text.value()));
    CsvRecord header;
    if (auto r = readCsvHeader(in, header, ColumnCount); !r)
        return r.error();
    const auto columnOf = mapColumns(header);
    if (!columnOf)
        return columnOf.error();
    return readRows(in, header, columnOf.value());
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
            out.append(tloSourceName(tool.tloSource).data(), tloSourceName(tool.tloSource).size());
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
        out += ',';
        appendField(out, tool.cutterType);
        out += ',';
        if (tool.overallLength)
            appendNumber(out, *tool.overallLength);
        out += ',';
        if (tool.lifeLimitMinutes)
            appendNumber(out, *tool.lifeLimitMinutes);
        out += ',';
        if (tool.lifeLimitUses)
            out += QByteArray::number(*tool.lifeLimitUses);
        appendProbing(out, tool);
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
