// SPDX-License-Identifier: GPL-3.0-or-later
// The native format: a JSON object with a format name and version, the units, and one object per tool.
#include "tablefile.h"

#include <cmath>

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

#include "textparsing.h"
#include "toolvalidation.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr int kJsonVersion = 1;
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
const auto LinuxCnc = "linuxcnc"_L1;
} // namespace Key

QString tr(const char *text)
{
    return QCoreApplication::translate("Toffee::JsonFormat", text);
}

int lineAt(const QByteArray &data, qsizetype offset)
{
    offset = std::clamp<qsizetype>(offset, 0, data.size());
    return int(QByteArrayView(data).first(offset).count('\n')) + 1;
}

// QJsonDocument keeps no positions: find where the index-th element of the top-level "tools" array starts.
qsizetype toolOffset(const QByteArray &data, qsizetype index)
{
    int depth = 0;
    bool inString = false;
    bool escaped = false;
    bool inTools = false;
    bool expectElement = false;
    qsizetype stringStart = 0;
    QByteArrayView lastKey;
    qsizetype count = -1;
    for (qsizetype i = 0; i < data.size(); ++i) {
        const char c = data.at(i);
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"') {
                inString = false;
                if (depth == 1)
                    lastKey = QByteArrayView(data).sliced(stringStart, i - stringStart);
            }
            continue;
        }
        if (expectElement && c != ' ' && c != '\n' && c != '\r' && c != '\t' && c != ']') {
            expectElement = false;
            if (++count == index)
                return i;
        }
        switch (c) {
        case '"':
            inString = true;
            stringStart = i + 1;
            break;
        case '{':
        case '[':
            ++depth;
            if (c == '[' && depth == 2 && lastKey == "tools") {
                inTools = true;
                expectElement = true;
            }
            break;
        case '}':
        case ']':
            --depth;
            if (inTools && depth < 2)
                inTools = false;
            break;
        case ',':
            if (inTools && depth == 2)
                expectElement = true;
            break;
        default:
            break;
        }
    }
    return -1;
}

Error toolError(const QByteArray &data, qsizetype index, const QString &message)
{
    const qsizetype offset = toolOffset(data, index);
    return Error { message, offset < 0 ? 0 : lineAt(data, offset) };
}

struct ToolReader
{
    const QJsonObject &object;
    QString problem;

    double number(QLatin1StringView key, double fallback)
    {
        const QJsonValue v = object.value(key);
        if (v.isUndefined() || v.isNull())
            return fallback;
        if (!v.isDouble()) {
            fail(tr("\"%1\" must be a number.").arg(key));
            return fallback;
        }
        return v.toDouble();
    }

    int integer(QLatin1StringView key, int fallback)
    {
        const double d = number(key, fallback);
        if (d != std::floor(d) || std::fabs(d) > 2e9) {
            fail(tr("\"%1\" must be a whole number.").arg(key));
            return fallback;
        }
        return int(d);
    }

    QString string(QLatin1StringView key)
    {
        const QJsonValue v = object.value(key);
        if (v.isUndefined() || v.isNull())
            return {};
        if (!v.isString()) {
            fail(tr("\"%1\" must be text.").arg(key));
            return {};
        }
        return v.toString();
    }

    void fail(const QString &message)
    {
        if (problem.isEmpty())
            problem = message;
    }
};

Result<Tool> readTool(const QJsonObject &object)
{
    static const QSet<QString> known = { Key::Number,     Key::Pocket,     Key::Description,
                                         Key::LengthGeometry, Key::LengthWear, Key::RadiusGeometry,
                                         Key::RadiusWear, Key::MeasuredTlo, Key::MeasuredAt,
                                         Key::Notes,      Key::LinuxCnc };
    for (auto it = object.constBegin(); it != object.constEnd(); ++it) {
        if (!known.contains(it.key()))
            return Error { tr("unknown field \"%1\" in a tool.").arg(it.key()) };
    }
    if (!object.contains(Key::Number))
        return Error { tr("a tool has no \"number\".") };

    ToolReader r { object, {} };
    Tool tool;
    tool.number = r.integer(Key::Number, 0);
    tool.pocket = r.integer(Key::Pocket, defaultPocket(tool.number));
    tool.description = r.string(Key::Description);
    tool.lengthGeometry = r.number(Key::LengthGeometry, 0.0);
    tool.lengthWear = r.number(Key::LengthWear, 0.0);
    tool.radiusGeometry = r.number(Key::RadiusGeometry, 0.0);
    tool.radiusWear = r.number(Key::RadiusWear, 0.0);
    if (object.contains(Key::MeasuredTlo) && !object.value(Key::MeasuredTlo).isNull())
        tool.measuredTlo = r.number(Key::MeasuredTlo, 0.0);
    const QString at = r.string(Key::MeasuredAt);
    if (!at.isEmpty()) {
        tool.measuredAt = QDateTime::fromString(at, Qt::ISODateWithMs);
        if (!tool.measuredAt.isValid())
            r.fail(tr("\"measured_at\" is not a date and time (use ISO 8601, e.g. 2026-11-22T10:15:00Z)."));
        tool.measuredAt = tool.measuredAt.toUTC();
    }
    tool.notes = r.string(Key::Notes);
    tool.linuxCncExtra = r.string(Key::LinuxCnc);
    if (!r.problem.isEmpty())
        return Error { r.problem };
    return tool;
}

void appendString(QByteArray &out, const QString &s)
{
    out += '"';
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
    out += formatNumber(value).toLatin1();
}

} // namespace

Result<ToolTable> readJsonTable(const QByteArray &data)
{
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(data, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return Error { tr("this is not valid JSON: %1.").arg(parseError.errorString()),
                       lineAt(data, parseError.offset) };
    if (!document.isObject())
        return Error { tr("this is not a Toffee tool table: the file must hold one JSON object."), 1 };
    const QJsonObject root = document.object();
    if (root.value(Key::Format).toString() != kFormatId)
        return Error { tr("this is not a Toffee tool table: \"format\" must be \"%1\".").arg(kFormatId), 1 };
    const QJsonValue version = root.value(Key::Version);
    if (!version.isDouble() || version.toDouble() != std::floor(version.toDouble()) || version.toDouble() < 1)
        return Error { tr("\"version\" must be a whole number from 1 up."), 1 };
    if (version.toDouble() > kJsonVersion)
        return Error { tr("this table was written by a newer Toffee (format version %1); this one reads up to "
                          "version %2. Update Toffee to open it.")
                           .arg(version.toInt())
                           .arg(kJsonVersion),
                       1 };
    for (auto it = root.constBegin(); it != root.constEnd(); ++it) {
        if (it.key() != Key::Format && it.key() != Key::Version && it.key() != Key::Units && it.key() != Key::Tools)
            return Error { tr("unknown field \"%1\" in the table.").arg(it.key()), 1 };
    }
    const auto units = unitsFromSymbol(root.value(Key::Units).toString());
    if (!units)
        return Error { tr("\"units\" must be \"mm\" or \"in\"."), 1 };
    const QJsonValue toolsValue = root.value(Key::Tools);
    if (!toolsValue.isArray())
        return Error { tr("\"tools\" must be a list of tools."), 1 };

    const QJsonArray array = toolsValue.toArray();
    QList<Tool> tools;
    tools.reserve(array.size());
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QJsonValue value = array.at(i);
        if (!value.isObject())
            return toolError(data, i, tr("tool %1 in the list is not a JSON object.").arg(i + 1));
        auto tool = readTool(value.toObject());
        if (!tool)
            return toolError(data, i, tool.error().message);
        tools.append(tool.takeValue());
    }
    qsizetype bad = -1;
    auto table = ToolTable::fromTools(std::move(tools), *units, &bad);
    if (!table)
        return toolError(data, bad, table.error().message);
    return table;
}

QByteArray writeJsonTable(const ToolTable &table)
{
    QByteArray out;
    out.reserve(64 + table.size() * 200);
    out += "{\n  \"format\": \"toffee-tool-table\",\n  \"version\": ";
    out += QByteArray::number(kJsonVersion);
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
            out += ", \"measured_at\": ";
            appendString(out, tool.measuredAt.toUTC().toString(Qt::ISODateWithMs));
        }
        if (!tool.notes.isEmpty()) {
            out += ", \"notes\": ";
            appendString(out, tool.notes);
        }
        if (!tool.linuxCncExtra.isEmpty()) {
            out += ", \"linuxcnc\": ";
            appendString(out, tool.linuxCncExtra);
        }
        out += '}';
    }
    out += table.isEmpty() ? "]\n}\n" : "\n  ]\n}\n";
    return out;
}

} // namespace Toffee
