// SPDX-License-Identifier: GPL-3.0-or-later
// Autodesk Fusion / HSM's JSON tool library (docs: /work/shared/FORMATS.md), read a tool object at a time by
// JsonScanner, no document built: only the cutter's number, description, type, unit, diameter and lengths are
// kept, and the post's length offset for a note. assemblyGaugeLength, the holder and the feeds are not
// offsets: they are read through (every key once, every value valid JSON) and left alone. Memory: the file,
// and a CamTool for each tool.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

#include <QCoreApplication>

#include "model/camimport/camreaders.h"
#include "model/formats/jsonscanner.h"
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

// The depths JsonScanner counts: the library's object 0, "data" 1, a tool 2, its members 3, theirs 4.
constexpr int kToolDepth = 2;

bool is(QByteArrayView key, QLatin1StringView name)
{
    return key == QByteArrayView(name.data(), name.size());
}

// How a message shows a value of the wrong kind: the value when it is short text, else what it is.
QString shown(const Scalar &value)
{
    switch (value.kind) {
    case Scalar::String:
        return u'"' + excerpt(value.string) + u'"';
    case Scalar::Bool:
        return value.number != 0.0 ? u"true"_s : u"false"_s;
    case Scalar::Number:
        return quotedNumber(value.number);
    case Scalar::List:
        return tr("a list");
    case Scalar::Object:
        return tr("an object");
    case Scalar::Null:
        break;
    }
    return tr("null");
}

// What the scanner refused, with its line and column.
Error scanError(const JsonScanner &json)
{
    return Error { tr("column %1: %2").arg(json.errorColumn()).arg(json.error().message), json.error().line };
}

Error notALibrary()
{
    return Error {
        tr("this is not a Fusion tool library: that is a JSON object with \"data\", a list of tools."), 1
    };
}

// Reads one tool object, keeping only the members Toffee takes, then judges them: the first that is not what
// the format says stops it, with the reason. It translates in its own context: lupdate files a class's tr()
// under the class, never under "Toffee".
class FusionToolReader
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::FusionToolReader)

public:
    explicit FusionToolReader(QString place) { m_tool.place = std::move(place); }

    // `json` at the tool's '{'.
    Result<CamTool> read(JsonScanner &json)
    {
        json.consume('{');
        if (json.consume('}'))
            return judge();
        JsonKeys keys;
        do {
            QByteArrayView key;
            QString decoded;
            if (!json.key(key, decoded))
                return scanError(json);
            const qsizetype before = keys.size();
            keys.insert(key.toByteArray());
            if (keys.size() == before)
                return Error { m_tool.place + u": "_s
                        + tr("the key \"%1\" appears twice; Toffee will not guess which one is meant.")
                              .arg(excerpt(key)),
                    json.line() };
            if (!json.expect(':', "':' after a key") || !member(json, key))
                return scanError(json);
        } while (json.consume(','));
        if (!json.expect('}', "',' or '}' in a tool"))
            return scanError(json);
        return judge();
    }

private:
    // The value of the tool's member `key`, kept when Toffee reads it.
    bool member(JsonScanner &json, QByteArrayView key)
    {
        constexpr int depth = kToolDepth + 1;
        if (is(key, Key::Type))
            return json.value(m_type, depth, key);
        if (is(key, Key::Description))
            return json.value(m_description, depth, key);
        if (is(key, Key::Unit))
            return json.value(m_unit, depth, key);
        if (is(key, Key::Geometry))
            return object(json, key, m_geometry,
                { { Key::CuttingDiameter, &m_diameter }, { Key::FluteLength, &m_fluteLength },
                    { Key::BodyLength, &m_bodyLength }, { Key::OverallLength, &m_overallLength } });
        if (is(key, Key::PostProcess))
            return object(json, key, m_post,
                { { Key::Number, &m_number }, { Key::LengthOffset, &m_lengthOffset },
                    { Key::Comment, &m_comment } });
        return json.skip(depth, key);
    }

    // The member `key` that should be an object: the members in `wanted` kept, the rest read through.
    // Anything but an object is kept in `out`, for judge() to refuse.
    bool object(JsonScanner &json, QByteArrayView key, Scalar &out,
        std::initializer_list<std::pair<QLatin1StringView, Scalar *>> wanted)
    {
        constexpr int depth = kToolDepth + 1;
        if (json.peek() != '{')
            return json.value(out, depth, key);
        out.kind = Scalar::Object;
        const QByteArray name
            = key.toByteArray(); // `key` may be the scanner's buffer, which the next key replaces
        json.consume('{');
        if (json.consume('}'))
            return true;
        JsonKeys keys;
        do {
            QByteArrayView member;
            QString decoded;
            if (!json.key(member, decoded) || !json.keyOnce(keys, member, depth, name)
                || !json.expect(':', "':' after a key"))
                return false;
            const auto found = std::find_if(
                wanted.begin(), wanted.end(), [member](const auto &w) { return is(member, w.first); });
            if (!(found != wanted.end() ? json.value(*found->second, depth + 1, member)
                                        : json.skip(depth + 1, member)))
                return false;
        } while (json.consume(','));
        return json.expect('}', "',' or '}'");
    }

    Result<CamTool> judge()
    {
        expectObject(Key::Geometry, m_geometry);
        expectObject(Key::PostProcess, m_post);
        m_tool.type = text(Key::Type, m_type);
        m_tool.description = text(Key::Description, m_description);
        if (m_tool.description.trimmed().isEmpty())
            m_tool.description = text(Key::Comment, m_comment);
        m_tool.diameter = length(Key::CuttingDiameter, m_diameter);
        m_tool.fluteLength = length(Key::FluteLength, m_fluteLength);
        m_tool.stickOut = length(Key::BodyLength, m_bodyLength);
        m_tool.overallLength = length(Key::OverallLength, m_overallLength);
        readNumber();
        readLengthOffset();
        readUnit();
        if (!m_why.isEmpty())
            return Error { m_tool.place + u": "_s + m_why };
        return std::move(m_tool);
    }

    bool failed(const QString &why)
    {
        if (m_why.isEmpty())
            m_why = why;
        return false;
    }

    void expectObject(QLatin1StringView key, const Scalar &v)
    {
        if (v.kind != Scalar::Null && v.kind != Scalar::Object)
            failed(tr("\"%1\" is %2, not an object.").arg(key, shown(v)));
    }

    QString text(QLatin1StringView key, const Scalar &v)
    {
        if (v.kind != Scalar::Null && v.kind != Scalar::String)
            failed(tr("\"%1\" is %2, not text.").arg(key, shown(v)));
        return v.string;
    }

    std::optional<double> length(QLatin1StringView key, const Scalar &v)
    {
        if (v.kind == Scalar::Null)
            return std::nullopt;
        if (v.kind != Scalar::Number) {
            failed(tr("\"%1\" is %2, not a number.").arg(key, shown(v)));
            return std::nullopt;
        }
        return v.number;
    }

    void readNumber()
    {
        const Scalar &v = m_number;
        if (v.kind == Scalar::Null) {
            failed(tr("it has no \"post-process\" \"number\": Toffee needs the T number the post writes."));
            return;
        }
        const double n = v.number;
        if (v.kind != Scalar::Number || n != std::floor(n)) {
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
    void readLengthOffset()
    {
        const Scalar &v = m_lengthOffset;
        if (v.kind == Scalar::Null)
            return;
        const double n = v.number;
        if (v.kind != Scalar::Number || n != std::floor(n) || std::fabs(n) > 1e9) {
            failed(tr("its \"length-offset\" is %1, not a whole number.").arg(shown(v)));
            return;
        }
        m_tool.lengthOffset = int(n);
    }

    void readUnit()
    {
        const QString unit = text(Key::Unit, m_unit);
        if (unit == u"millimeters"_s)
            m_tool.units = Units::Millimetre;
        else if (unit == u"inches"_s)
            m_tool.units = Units::Inch;
        else if (const auto units = unitsFromSymbol(unit))
            m_tool.units = *units;
        else if (unit.isEmpty())
            m_tool.unitGiven
                = false; // the import asks which; the lengths are checked as millimetres meanwhile
        else
            failed(tr("its \"unit\" is \"%1\"; Toffee reads millimeters or inches.").arg(excerpt(unit)));
    }

    CamTool m_tool;
    QString m_why;
    // The members read, as the file gives them (Null when it does not); an object's only as its kind.
    Scalar m_type, m_description, m_unit, m_geometry, m_post;
    Scalar m_diameter, m_fluteLength, m_bodyLength, m_overallLength;
    Scalar m_number, m_lengthOffset, m_comment;
};

// The tools of "data", `json` at its '['.
Result<void> readTools(JsonScanner &json, QList<CamTool> &tools)
{
    json.consume('[');
    if (json.consume(']'))
        return {};
    do {
        const QString place = tr("tool %1 in \"data\"").arg(tools.size() + 1);
        if (json.peek() != '{') {
            Scalar v;
            const int line = json.line();
            if (!json.value(v, kToolDepth, Key::Data.data()))
                return scanError(json);
            return Error { place + u": "_s + tr("it is %1, not an object.").arg(shown(v)), line };
        }
        auto tool = FusionToolReader(place).read(json);
        if (!tool)
            return tool.error();
        tools.append(tool.takeValue());
    } while (json.consume(','));
    if (!json.expect(']', "',' or ']' after a tool"))
        return scanError(json);
    return {};
}

} // namespace

Result<QList<CamTool>> readFusionJson(QByteArrayView data)
{
    JsonScanner json(data);
    if (json.peek() != '{') {
        // Whatever else it is, JSON's own faults come first.
        if (!json.skip())
            return scanError(json);
        if (!json.atEnd() && !json.fail(tr("this is not valid JSON: there is more text after the value.")))
            return scanError(json);
        return notALibrary();
    }
    json.consume('{');
    JsonKeys keys;
    bool hasData = false;
    QList<CamTool> tools;
    if (!json.consume('}')) {
        do {
            QByteArrayView key;
            QString decoded;
            if (!json.key(key, decoded) || !json.keyOnce(keys, key, 0)
                || !json.expect(':', "':' after a key"))
                return scanError(json);
            if (!is(key, Key::Data)) {
                if (!json.skip(1, key))
                    return scanError(json);
                continue;
            }
            if (json.peek() != '[')
                return notALibrary();
            hasData = true;
            if (auto read = readTools(json, tools); !read)
                return read.error();
        } while (json.consume(','));
        if (!json.expect('}', "',' or '}' at the end of the library"))
            return scanError(json);
    }
    if (!json.atEnd()) {
        json.fail(tr("this is not valid JSON: there is more text after the library."));
        return scanError(json);
    }
    if (!hasData)
        return notALibrary();
    return checkCamTools(std::move(tools));
}

} // namespace Toffee
