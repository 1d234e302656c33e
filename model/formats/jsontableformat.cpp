// SPDX-License-Identifier: GPL-3.0-or-later
// The native format: a JSON object with a format name and version, the units, and one object per tool.
#include "model/formats/tablefile.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <QCoreApplication>

#include "model/formats/jsonscanner.h"
#include "model/formats/jsontool.h"
#include "model/formats/tablereading.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/toolvalidation.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// Version 2 added "tlo_source", "break_test_failed" and "reference_mz". A table without them is still written
// as version 1, so that an older Toffee keeps reading it; one with them is version 2, which an older Toffee
// refuses rather than silently dropping a broken tool's mark. Version 3 added the cutter ("cutter_type",
// "overall_length") and the tool life's limits ("life_limit_minutes", "life_limit_uses"); written only when a
// tool has one, for the same reason. Version 4 added "tlo_source": "pulled" (a TLO read from the controller's
// table); written only when a tool has one, so that an older Toffee says it is newer rather than refusing a
// word it does not know. Version 5 added how a tool is probed ("flutes", "probe_x", "probe_y",
// "probe_touches", "probe_turn", "probe_latch_feed", "spread_limit"); written only when a tool has one of
// them.
constexpr int kJsonVersion = 5;
const auto kFormatId = "toffee-tool-table"_L1;

// What the table's own fields said so far.
struct TableFields
{
    std::optional<Units> units;
    bool hasFormat = false;
    bool hasVersion = false;
    bool hasTools = false;
};

// The "tools" list, `json` after its key: each tool is checked as it is read, in the units known by then.
Result<void> readTools(JsonScanner &json, TableFields &table, ToolCollector &tools)
{
    if (!table.hasFormat)
        return Error { tr("this is not a Toffee tool table: \"format\" must be \"%1\", before \"tools\".")
                           .arg(kFormatId),
            json.line() };
    if (!table.hasVersion)
        return Error { tr("\"version\" must come before \"tools\"."), json.line() };
    table.hasTools = true;
    if (!json.consume('['))
        return Error { tr("\"tools\" must be a list of tools."), json.line() };
    if (json.consume(']'))
        return {};
    do {
        Tool tool;
        const int line = (json.peek(), json.line());
        if (!readJsonTool(json, tool))
            return json.error();
        if (auto added = tools.add(std::move(tool), line, table.units.value_or(Units::Millimetre)); !added)
            return added;
    } while (json.consume(','));
    if (!json.expect(']', "',' or ']' after a tool"))
        return json.error();
    return {};
}

Result<void> checkVersion(const Scalar &v, int line)
{
    if (v.kind != Scalar::Number || v.number != std::floor(v.number) || v.number < 1)
        return Error { tr("\"version\" must be a whole number from 1 up."), line };
    if (v.number > kJsonVersion)
        return Error { tr("this table was written by a newer Toffee (format version %1); this one "
                          "reads up to version %2. Update Toffee to open it.")
                           .arg(v.number)
                           .arg(kJsonVersion),
            line };
    return {};
}

// A field of the table other than "tools", whose value `v` begins on `line`.
Result<void> readTableField(const QString &key, const Scalar &v, int line, TableFields &table)
{
    if (key == JsonKey::Format) {
        if (v.kind != Scalar::String || v.string != kFormatId)
            return Error { tr("this is not a Toffee tool table: \"format\" must be \"%1\".").arg(kFormatId),
                line };
        table.hasFormat = true;
    } else if (key == JsonKey::Version) {
        if (auto known = checkVersion(v, line); !known)
            return known;
        table.hasVersion = true;
    } else if (key == JsonKey::Units) {
        table.units = v.kind == Scalar::String ? unitsFromSymbol(v.string) : std::nullopt;
        if (!table.units)
            return Error { tr("\"units\" must be \"mm\" or \"in\"."), line };
    } else if (!table.hasFormat) {
        return Error { tr("this is not a Toffee tool table: \"format\" must be \"%1\".").arg(kFormatId), 1 };
    } else {
        return Error { tr("unknown field \"%1\" in the table.").arg(excerpt(key)), line };
    }
    return {};
}

// The table object's fields, `json` inside its '{'.
Result<void> readTableFields(JsonScanner &json, TableFields &table, ToolCollector &tools)
{
    if (json.consume('}'))
        return {};
    JsonKeys keys;
    do {
        QByteArrayView raw;
        QString decoded;
        if (!json.key(raw, decoded) || !json.keyOnce(keys, raw, 0) || !json.expect(':', "':' after a key"))
            return json.error();
        const QString key = QString::fromUtf8(raw);
        if (key == JsonKey::Tools) {
            if (auto read = readTools(json, table, tools); !read)
                return read;
            continue;
        }
        Scalar v;
        const int line = (json.peek(), json.line());
        if (!json.value(v, 1, raw))
            return json.error();
        if (auto read = readTableField(key, v, line, table); !read)
            return read;
    } while (json.consume(','));
    if (!json.expect('}', "',' or '}' at the end of the table"))
        return json.error();
    return {};
}

// The first field the table must have and has not, on line 1, as the table as a whole lacks it.
Result<void> checkComplete(const TableFields &table)
{
    if (!table.hasFormat)
        return Error { tr("this is not a Toffee tool table: \"format\" must be \"%1\".").arg(kFormatId), 1 };
    if (!table.hasVersion)
        return Error { tr("\"version\" must be a whole number from 1 up."), 1 };
    if (!table.units)
        return Error { tr("\"units\" must be \"mm\" or \"in\"."), 1 };
    if (!table.hasTools)
        return Error { tr("\"tools\" must be a list of tools."), 1 };
    return {};
}

void appendString(QByteArray &out, const QString &s)
{
    out += '"';
    const bool plain = std::none_of(
        s.cbegin(), s.cend(), [](QChar c) { return c.unicode() < 0x20 || c == u'"' || c == u'\\'; });
    if (plain) {
        appendUtf8(out, s);
        out += '"';
        return;
    }
    const QByteArray utf8 = s.toUtf8();
    for (char c : utf8) {
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (uchar(c) < 0x20) {
                static const char hex[] = "0123456789abcdef";
                out += "\\u00";
                out += hex[(uchar(c) >> 4) & 0xf];
                out += hex[uchar(c) & 0xf];
            } else {
                out += c;
            }
        }
    }
    out += '"';
}

void appendField(QByteArray &out, QLatin1StringView key, double value)
{
    out += ", \"";
    out += key.data();
    out += "\": ";
    appendNumber(out, value);
}

} // namespace

Result<ToolTable> readJsonTable(const QByteArray &data)
{
    JsonScanner json(data);
    if (json.atEnd())
        return Error { tr("this is not valid JSON: the file is empty."), 1 };
    if (json.peek() != '{')
        return Error { tr("this is not a Toffee tool table: the file must hold one JSON object."),
            json.line() };
    json.consume('{');
    TableFields table;
    ToolCollector tools(data); // Toffee writes one tool a line
    if (auto read = readTableFields(json, table, tools); !read)
        return read.error();
    if (!json.atEnd())
        return Error { tr("this is not valid JSON: there is more text after the table."), json.line() };
    if (auto complete = checkComplete(table); !complete)
        return complete.error();
    return tools.build(*table.units);
}

namespace {

// How the tool is probed, each key only when it is not the default.
void appendProbing(QByteArray &out, const Tool &tool)
{
    const ProbeSettings &p = tool.probing;
    if (tool.flutes)
        out += ", \"flutes\": " + QByteArray::number(*tool.flutes);
    if (p.offsetX != 0.0)
        appendField(out, JsonKey::ProbeX, p.offsetX);
    if (p.offsetY != 0.0)
        appendField(out, JsonKey::ProbeY, p.offsetY);
    if (p.touches)
        out += ", \"probe_touches\": " + QByteArray::number(*p.touches);
    if (!p.turn)
        out += ", \"probe_turn\": false";
    if (p.latchFeed)
        appendField(out, JsonKey::ProbeLatchFeed, *p.latchFeed);
    if (p.spreadLimit)
        appendField(out, JsonKey::SpreadLimit, *p.spreadLimit);
}

} // namespace

bool writeJsonTable(const ToolTable &table, const ByteSink &sink)
{
    ChunkedWriter w(sink);
    QByteArray &out = w.out;
    const bool marks = std::any_of(table.tools().cbegin(), table.tools().cend(),
        [](const Tool &t) { return t.tloSource != TloSource::Probe || t.breakTestFailed || t.referenceMz; });
    const bool cutters = std::any_of(table.tools().cbegin(), table.tools().cend(), [](const Tool &t) {
        return !t.cutterType.isEmpty() || t.overallLength || t.lifeLimitMinutes || t.lifeLimitUses;
    });
    out += "{\n  \"format\": \"toffee-tool-table\",\n  \"version\": ";
    const bool pulled = std::any_of(table.tools().cbegin(), table.tools().cend(),
        [](const Tool &t) { return t.tloSource == TloSource::Pulled; });
    const bool probing = std::any_of(table.tools().cbegin(), table.tools().cend(),
        [](const Tool &t) { return t.flutes || !t.probing.isDefault(); });
    out += QByteArray::number(probing ? kJsonVersion : pulled ? 4 : cutters ? 3 : marks ? 2 : 1);
    out += ",\n  \"units\": \"";
    out += unitsSymbol(table.units()).toLatin1();
    out += "\",\n  \"tools\": [";
    bool first = true;
    for (const Tool &tool : table.tools()) {
        out += first ? "\n    {" : ",\n    {";
        first = false;
        out += "\"number\": ";
        out += QByteArray::number(tool.number);
        out += ", \"pocket\": ";
        out += QByteArray::number(tool.pocket);
        out += ", \"description\": ";
        appendString(out, tool.description);
        appendField(out, JsonKey::LengthGeometry, tool.lengthGeometry);
        appendField(out, JsonKey::LengthWear, tool.lengthWear);
        appendField(out, JsonKey::RadiusGeometry, tool.radiusGeometry);
        appendField(out, JsonKey::RadiusWear, tool.radiusWear);
        if (tool.measuredTlo)
            appendField(out, JsonKey::MeasuredTlo, *tool.measuredTlo);
        if (tool.measuredAt.isValid()) {
            out += ", \"measured_at\": \"";
            appendIsoUtc(out, tool.measuredAt);
            out += '"';
        }
        if (tool.tloSource != TloSource::Probe) {
            out += ", \"tlo_source\": \"";
            out.append(tloSourceName(tool.tloSource).data(), tloSourceName(tool.tloSource).size());
            out += '"';
        }
        if (tool.breakTestFailed)
            out += ", \"break_test_failed\": true";
        if (tool.referenceMz)
            appendField(out, JsonKey::ReferenceMz, *tool.referenceMz);
        if (!tool.notes.isEmpty()) {
            out += ", \"notes\": ";
            appendString(out, tool.notes);
        }
        if (!tool.linuxCncExtra.isEmpty()) {
            out += ", \"linuxcnc\": ";
            appendString(out, tool.linuxCncExtra);
        }
        if (!tool.cutterType.isEmpty()) {
            out += ", \"cutter_type\": ";
            appendString(out, tool.cutterType);
        }
        if (tool.overallLength)
            appendField(out, JsonKey::OverallLength, *tool.overallLength);
        if (tool.lifeLimitMinutes)
            appendField(out, JsonKey::LifeLimitMinutes, *tool.lifeLimitMinutes);
        if (tool.lifeLimitUses) {
            out += ", \"life_limit_uses\": ";
            out += QByteArray::number(*tool.lifeLimitUses);
        }
        appendProbing(out, tool);
        out += '}';
        if (!w.next())
            return false;
    }
    out += table.isEmpty() ? "]\n}\n" : "\n  ]\n}\n";
    return w.finish();
}

QByteArray writeJsonTable(const ToolTable &table)
{
    return collect(table, [](const ToolTable &t, const ByteSink &s) { return writeJsonTable(t, s); });
}

} // namespace Toffee
