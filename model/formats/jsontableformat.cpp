// SPDX-License-Identifier: GPL-3.0-or-later
// The native format: a JSON object with a format name and version, the units, and one object per tool.
#include "model/formats/tablefile.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <QCoreApplication>

#include "model/numberformat.h"
#include "model/formats/jsonscanner.h"
#include "model/formats/tablereading.h"
#include "model/textparsing.h"
#include "model/toolvalidation.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// Version 2 added "tlo_source", "break_test_failed" and "reference_mz". A table without them is still written
// as version 1, so that an older Toffee keeps reading it; one with them is version 2, which an older Toffee
// refuses rather than silently dropping a broken tool's mark.
constexpr int kJsonVersion = 2;
const auto kFormatId = "toffee-tool-table"_L1;

namespace Key {
const auto Format = "format"_L1;
const auto Version = "version"_L1;
const auto Units = "units"_L1;
const auto Tools = "tools"_L1;
const auto Number = "number"_L1;
const auto Pocket = "pocket"_L1;
const auto Description = "description"_L1;
const auto LengthGeometry = "length_geometry"_L1;
const auto LengthWear = "length_wear"_L1;
const auto RadiusGeometry = "radius_geometry"_L1;
const auto RadiusWear = "radius_wear"_L1;
const auto MeasuredTlo = "measured_tlo"_L1;
const auto MeasuredAt = "measured_at"_L1;
const auto Notes = "notes"_L1;
const auto TloSource = "tlo_source"_L1;
const auto BreakTestFailed = "break_test_failed"_L1;
const auto ReferenceMz = "reference_mz"_L1;
const auto LinuxCnc = "linuxcnc"_L1;
} // namespace Key

bool wholeNumber(JsonScanner &json, const Scalar &v, QLatin1StringView key, int &out)
{
    if (v.kind != Scalar::Number || v.number != std::floor(v.number))
        return json.fail(tr("\"%1\" must be a whole number.").arg(key));
    if (std::fabs(v.number) > 2e9) {
        // Whole, but beyond any tool or pocket: say so rather than "not a whole number".
        const bool tool = key == Key::Number;
        return json.fail(tr("\"%1\": %2 is out of range; use %3 to %4.")
                             .arg(key)
                             .arg(v.number, 0, 'g', 15)
                             .arg(tool ? Limits::kMinToolNumber : Limits::kMinPocket)
                             .arg(tool ? Limits::kMaxToolNumber : Limits::kMaxPocket));
    }
    out = int(v.number);
    return true;
}

bool decimal(JsonScanner &json, const Scalar &v, QLatin1StringView key, double &out)
{
    if (v.kind != Scalar::Number)
        return json.fail(tr("\"%1\" must be a number.").arg(key));
    out = v.number;
    return true;
}

bool text(JsonScanner &json, const Scalar &v, QLatin1StringView key, QString &out)
{
    if (v.kind == Scalar::Null)
        return true;
    if (v.kind != Scalar::String)
        return json.fail(tr("\"%1\" must be text.").arg(key));
    out = v.string;
    return true;
}

// One tool object; `json` is at its '{'.
bool readTool(JsonScanner &json, Tool &tool)
{
    if (json.peek() != '{')
        return json.fail(tr("each entry of \"tools\" must be a JSON object such as {\"number\": 1}."));
    json.consume('{');
    bool hasNumber = false;
    bool hasPocket = false;
    quint32 seen = 0;
    static const QLatin1StringView keys[] = { Key::Number, Key::Pocket, Key::Description, Key::LengthGeometry,
        Key::LengthWear, Key::RadiusGeometry, Key::RadiusWear, Key::MeasuredTlo, Key::MeasuredAt, Key::Notes,
        Key::TloSource, Key::BreakTestFailed, Key::ReferenceMz, Key::LinuxCnc };
    if (!json.consume('}')) {
        do {
            QByteArrayView key;
            QString decodedKey;
            Scalar v;
            if (!json.key(key, decodedKey) || !json.expect(':', "':' after a key") || !json.value(v))
                return false;
            const auto found = std::find_if(std::begin(keys), std::end(keys),
                [&key](QLatin1StringView k) { return QByteArrayView(k.data(), k.size()) == key; });
            if (found == std::end(keys))
                return json.fail(tr("unknown field \"%1\" in a tool.").arg(excerpt(key)));
            const auto bit = quint32(1) << (found - std::begin(keys));
            if (seen & bit)
                return json.fail(tr("the field \"%1\" appears twice in a tool.").arg(excerpt(key)));
            seen |= bit;
            const QLatin1StringView k = *found;
            bool ok = true;
            if (k == Key::Number) {
                ok = wholeNumber(json, v, k, tool.number);
                hasNumber = true;
            } else if (k == Key::Pocket) {
                ok = wholeNumber(json, v, k, tool.pocket);
                hasPocket = true;
            } else if (k == Key::Description) {
                ok = text(json, v, k, tool.description);
            } else if (k == Key::LengthGeometry) {
                ok = decimal(json, v, k, tool.lengthGeometry);
            } else if (k == Key::LengthWear) {
                ok = decimal(json, v, k, tool.lengthWear);
            } else if (k == Key::RadiusGeometry) {
                ok = decimal(json, v, k, tool.radiusGeometry);
            } else if (k == Key::RadiusWear) {
                ok = decimal(json, v, k, tool.radiusWear);
            } else if (k == Key::MeasuredTlo) {
                if (v.kind != Scalar::Null) {
                    double tlo = 0.0;
                    ok = decimal(json, v, k, tlo);
                    tool.measuredTlo = tlo;
                }
            } else if (k == Key::MeasuredAt) {
                QString at;
                ok = text(json, v, k, at);
                if (ok && !at.isEmpty()) {
                    tool.measuredAt = parseIsoDateTime(at.toLatin1());
                    if (!tool.measuredAt.isValid())
                        ok = json.fail(tr("\"measured_at\" is not a date and time (use ISO 8601, e.g. "
                                          "2026-11-22T10:15:00Z)."));
                }
            } else if (k == Key::Notes) {
                ok = text(json, v, k, tool.notes);
            } else if (k == Key::TloSource) {
                QString source;
                ok = text(json, v, k, source);
                if (ok && source == "manual"_L1)
                    tool.tloSource = TloSource::Manual;
                else if (ok && source != "probe"_L1)
                    ok = json.fail(tr("\"tlo_source\" must be \"probe\" or \"manual\"."));
            } else if (k == Key::ReferenceMz) {
                if (v.kind != Scalar::Null) {
                    double mz = 0.0;
                    ok = decimal(json, v, k, mz);
                    tool.referenceMz = mz;
                }
            } else if (k == Key::BreakTestFailed) {
                if (v.kind != Scalar::Bool)
                    ok = json.fail(tr("\"break_test_failed\" must be true or false."));
                else
                    tool.breakTestFailed = v.number != 0.0;
            } else {
                ok = text(json, v, k, tool.linuxCncExtra);
            }
            if (!ok)
                return false;
        } while (json.consume(','));
        if (!json.expect('}', "',' or '}' in a tool"))
            return false;
    }
    if (!hasNumber)
        return json.fail(tr("a tool has no \"number\"."));
    if (!hasPocket)
        tool.pocket = defaultPocket(tool.number);
    return true;
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

    std::optional<Units> units;
    bool hasFormat = false;
    bool hasVersion = false;
    bool hasTools = false;
    ToolCollector tools(data); // Toffee writes one tool a line
    if (!json.consume('}')) {
        do {
            QString key;
            if (!json.string(key) || !json.expect(':', "':' after a key"))
                return json.error();
            if (key == Key::Tools) {
                if (!hasFormat)
                    return Error { tr("this is not a Toffee tool table: \"format\" must be \"%1\", before "
                                      "\"tools\".")
                                       .arg(kFormatId),
                        json.line() };
                if (!hasVersion)
                    return Error { tr("\"version\" must come before \"tools\"."), json.line() };
                if (hasTools)
                    return Error { tr("\"tools\" appears twice."), json.line() };
                hasTools = true;
                if (!json.consume('['))
                    return Error { tr("\"tools\" must be a list of tools."), json.line() };
                if (!json.consume(']')) {
                    do {
                        Tool tool;
                        const int line = (json.peek(), json.line());
                        if (!readTool(json, tool))
                            return json.error();
                        if (auto added = tools.add(std::move(tool), line, units.value_or(Units::Millimetre));
                            !added)
                            return added.error();
                    } while (json.consume(','));
                    if (!json.expect(']', "',' or ']' after a tool"))
                        return json.error();
                }
                continue;
            }
            Scalar v;
            const int line = (json.peek(), json.line());
            if (!json.value(v))
                return json.error();
            if (key == Key::Format) {
                if (v.kind != Scalar::String || v.string != kFormatId)
                    return Error {
                        tr("this is not a Toffee tool table: \"format\" must be \"%1\".").arg(kFormatId), line
                    };
                hasFormat = true;
            } else if (key == Key::Version) {
                if (v.kind != Scalar::Number || v.number != std::floor(v.number) || v.number < 1)
                    return Error { tr("\"version\" must be a whole number from 1 up."), line };
                if (v.number > kJsonVersion)
                    return Error {
                        tr("this table was written by a newer Toffee (format version %1); this one "
                           "reads up to version %2. Update Toffee to open it.")
                            .arg(v.number)
                            .arg(kJsonVersion),
                        line
                    };
                hasVersion = true;
            } else if (key == Key::Units) {
                units = v.kind == Scalar::String ? unitsFromSymbol(v.string) : std::nullopt;
                if (!units)
                    return Error { tr("\"units\" must be \"mm\" or \"in\"."), line };
            } else if (!hasFormat) {
                return Error {
                    tr("this is not a Toffee tool table: \"format\" must be \"%1\".").arg(kFormatId), 1
                };
            } else {
                return Error { tr("unknown field \"%1\" in the table.").arg(excerpt(key)), line };
            }
        } while (json.consume(','));
        if (!json.expect('}', "',' or '}' at the end of the table"))
            return json.error();
    }
    if (!json.atEnd())
        return Error { tr("this is not valid JSON: there is more text after the table."), json.line() };
    if (!hasFormat)
        return Error { tr("this is not a Toffee tool table: \"format\" must be \"%1\".").arg(kFormatId), 1 };
    if (!hasVersion)
        return Error { tr("\"version\" must be a whole number from 1 up."), 1 };
    if (!units)
        return Error { tr("\"units\" must be \"mm\" or \"in\"."), 1 };
    if (!hasTools)
        return Error { tr("\"tools\" must be a list of tools."), 1 };
    return tools.build(*units);
}

bool writeJsonTable(const ToolTable &table, const ByteSink &sink)
{
    ChunkedWriter w(sink);
    QByteArray &out = w.out;
    const bool marks = std::any_of(table.tools().cbegin(), table.tools().cend(),
        [](const Tool &t) { return t.tloSource != TloSource::Probe || t.breakTestFailed || t.referenceMz; });
    out += "{\n  \"format\": \"toffee-tool-table\",\n  \"version\": ";
    out += QByteArray::number(marks ? kJsonVersion : 1);
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
        appendField(out, Key::LengthGeometry, tool.lengthGeometry);
        appendField(out, Key::LengthWear, tool.lengthWear);
        appendField(out, Key::RadiusGeometry, tool.radiusGeometry);
        appendField(out, Key::RadiusWear, tool.radiusWear);
        if (tool.measuredTlo)
            appendField(out, Key::MeasuredTlo, *tool.measuredTlo);
        if (tool.measuredAt.isValid()) {
            out += ", \"measured_at\": \"";
            appendIsoUtc(out, tool.measuredAt);
            out += '"';
        }
        if (tool.tloSource == TloSource::Manual)
            out += ", \"tlo_source\": \"manual\"";
        if (tool.breakTestFailed)
            out += ", \"break_test_failed\": true";
        if (tool.referenceMz)
            appendField(out, Key::ReferenceMz, *tool.referenceMz);
        if (!tool.notes.isEmpty()) {
            out += ", \"notes\": ";
            appendString(out, tool.notes);
        }
        if (!tool.linuxCncExtra.isEmpty()) {
            out += ", \"linuxcnc\": ";
            appendString(out, tool.linuxCncExtra);
        }
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
