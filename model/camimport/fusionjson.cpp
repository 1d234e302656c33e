// SPDX-License-Identifier: GPL-3.0-or-later
// Autodesk Fusion / HSM's JSON tool library (docs: /work/shared/FORMATS.md). Only the cutter's number,
// description, type, unit, diameter and lengths are read, and the post's length offset for a note;
// assemblyGaugeLength, the holder and the feeds are not offsets and are left alone.
#include <algorithm>
#include <cmath>

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "model/camimport/camreaders.h"
#include "model/limits.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

namespace Key {
constexpr auto Data = "data"_L1;
constexpr auto Unit = "unit"_L1;
constexpr auto Type = "type"_L1;
constexpr auto Description = "description"_L1;
constexpr auto Geometry = "geometry"_L1;
constexpr auto CuttingDiameter = "DC"_L1;
constexpr auto FluteLength = "LCF"_L1;
constexpr auto BodyLength = "LB"_L1;
constexpr auto OverallLength = "OAL"_L1;
constexpr auto PostProcess = "post-process"_L1;
constexpr auto Number = "number"_L1;
constexpr auto LengthOffset = "length-offset"_L1;
constexpr auto Comment = "comment"_L1;
} // namespace Key

// How a message shows a value of the wrong kind: the value when it is short text, else what it is.
QString shown(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::String:
        return u'"' + excerpt(value.toString()) + u'"';
    case QJsonValue::Bool:
        return value.toBool() ? u"true"_s : u"false"_s;
    case QJsonValue::Double:
        return quotedNumber(value.toDouble());
    case QJsonValue::Array:
        return tr("a list");
    case QJsonValue::Object:
        return tr("an object");
    default:
        return tr("null");
    }
}

// Reads one tool object; the first member that is not what the format says stops it, with the reason. It
// translates in its own context: lupdate files a class's tr() under the class, never under "Toffee".
class FusionToolReader
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::FusionToolReader)

public:
    FusionToolReader(const QJsonObject &object, QString place)
        : m_object(object)
    {
        m_tool.place = std::move(place);
    }

    Result<CamTool> read()
    {
        const QJsonObject geometry = object(m_object, Key::Geometry);
        const QJsonObject post = object(m_object, Key::PostProcess);
        m_tool.type = text(m_object, Key::Type);
        m_tool.description = text(m_object, Key::Description);
        if (m_tool.description.trimmed().isEmpty())
            m_tool.description = text(post, Key::Comment);
        m_tool.diameter = length(geometry, Key::CuttingDiameter);
        m_tool.fluteLength = length(geometry, Key::FluteLength);
        m_tool.stickOut = length(geometry, Key::BodyLength);
        m_tool.overallLength = length(geometry, Key::OverallLength);
        readNumber(post);
        readLengthOffset(post);
        readUnit();
        if (!m_why.isEmpty())
            return Error { m_tool.place + u": "_s + m_why };
        return m_tool;
    }

private:
    bool failed(const QString &why)
    {
        if (m_why.isEmpty())
            m_why = why;
        return false;
    }

    QJsonObject object(const QJsonObject &in, QLatin1StringView key)
    {
        const QJsonValue v = in.value(key);
        if (!v.isUndefined() && !v.isNull() && !v.isObject())
            failed(tr("\"%1\" is %2, not an object.").arg(key, shown(v)));
        return v.toObject();
    }

    QString text(const QJsonObject &in, QLatin1StringView key)
    {
        const QJsonValue v = in.value(key);
        if (!v.isUndefined() && !v.isNull() && !v.isString())
            failed(tr("\"%1\" is %2, not text.").arg(key, shown(v)));
        return v.toString();
    }

    std::optional<double> length(const QJsonObject &in, QLatin1StringView key)
    {
        const QJsonValue v = in.value(key);
        if (v.isUndefined() || v.isNull())
            return std::nullopt;
        if (!v.isDouble()) {
            failed(tr("\"%1\" is %2, not a number.").arg(key, shown(v)));
            return std::nullopt;
        }
        return v.toDouble();
    }

    void readNumber(const QJsonObject &post)
    {
        const QJsonValue v = post.value(Key::Number);
        if (v.isUndefined() || v.isNull()) {
            failed(tr("it has no \"post-process\" \"number\": Toffee needs the T number the post writes."));
            return;
        }
        const double n = v.toDouble(std::nan(""));
        if (!v.isDouble() || n != std::floor(n)) {
            failed(tr("its \"number\" is %1, not a whole number.").arg(shown(v)));
            return;
        }
        // Larger numbers are refused by the range check, with the number as the file has it.
        m_tool.number = int(std::clamp(n, -1e9, 1e9));
        if (n != m_tool.number)
            failed(tr("its \"number\" %1 is out of range; use %2 to %3.")
                       .arg(shown(v))
                       .arg(Limits::kMinToolNumber)
                       .arg(Limits::kMaxToolNumber));
    }

    // Only for the preview's note: Toffee's H is always T.
    void readLengthOffset(const QJsonObject &post)
    {
        const QJsonValue v = post.value(Key::LengthOffset);
        if (v.isUndefined() || v.isNull())
            return;
        const double n = v.toDouble(std::nan(""));
        if (!v.isDouble() || n != std::floor(n) || std::fabs(n) > 1e9) {
            failed(tr("its \"length-offset\" is %1, not a whole number.").arg(shown(v)));
            return;
        }
        m_tool.lengthOffset = int(n);
    }

    void readUnit()
    {
        const QString unit = text(m_object, Key::Unit);
        if (unit == u"millimeters"_s)
            m_tool.units = Units::Millimetre;
        else if (unit == u"inches"_s)
            m_tool.units = Units::Inch;
        else if (const auto units = unitsFromSymbol(unit))
            m_tool.units = *units;
        else
            failed(unit.isEmpty()
                    ? tr("it has no \"unit\" (millimeters or inches).")
                    : tr("its \"unit\" is \"%1\"; Toffee reads millimeters or inches.").arg(excerpt(unit)));
    }

    const QJsonObject &m_object;
    CamTool m_tool;
    QString m_why;
};

// The 1-based line and column (in characters) of a QJsonParseError's offset, which is just past the character
// the parser stopped at: the column is that character's.
std::pair<int, int> position(QByteArrayView data, qsizetype offset)
{
    offset = std::clamp<qsizetype>(offset, 0, data.size());
    const qsizetype at = std::max<qsizetype>(offset - 1, 0);
    const qsizetype lineStart = data.first(at).lastIndexOf('\n') + 1;
    const int column = int(QString::fromUtf8(data.sliced(lineStart, at - lineStart)).size()) + 1;
    return { lineAt(data, at), column };
}

} // namespace

Result<QList<CamTool>> readFusionJson(QByteArrayView data)
{
    QJsonParseError parsed {};
    const QJsonDocument document
        = QJsonDocument::fromJson(QByteArray::fromRawData(data.data(), data.size()), &parsed);
    if (parsed.error != QJsonParseError::NoError) {
        const auto [line, column] = position(data, parsed.offset);
        return Error { tr("column %1: this is not valid JSON (%2).").arg(column).arg(parsed.errorString()),
            line };
    }
    const QJsonValue tools = document.object().value(Key::Data);
    if (!document.isObject() || !tools.isArray())
        return Error { tr("this is not a Fusion tool library: that is a JSON object with \"data\", a list of "
                          "tools."),
            1 };
    const QJsonArray list = tools.toArray();
    QList<CamTool> read;
    read.reserve(list.size());
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString place = tr("tool %1 in \"data\"").arg(i + 1);
        const QJsonValue v = list.at(i);
        if (!v.isObject())
            return Error { place + u": "_s + tr("it is %1, not an object.").arg(shown(v)) };
        const QJsonObject object = v.toObject();
        auto tool = FusionToolReader(object, place).read();
        if (!tool)
            return tool.error();
        read.append(tool.takeValue());
    }
    return checkCamTools(std::move(read));
}

} // namespace Toffee
