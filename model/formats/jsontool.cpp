// SPDX-License-Identifier: GPL-3.0-or-later
// A tool object of the native JSON format: each key may come once, in any order, and only "number" is
// required.
#include "model/formats/jsontool.h"

#include <algorithm>
#include <cmath>

#include <QCoreApplication>

#include "model/formats/jsonscanner.h"
#include "model/textparsing.h"
#include "model/tool.h"
#include "model/toolvalidation.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

bool wholeNumber(JsonScanner &json, const Scalar &v, QLatin1StringView key, int &out)
{
    if (v.kind != Scalar::Number || v.number != std::floor(v.number))
        return json.fail(tr("\"%1\" must be a whole number.").arg(key));
    if (std::fabs(v.number) > 2e9) {
        // Whole, but beyond any tool or pocket: say so rather than "not a whole number".
        const bool tool = key == JsonKey::Number;
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

bool optionalDecimal(JsonScanner &json, const Scalar &v, QLatin1StringView key, std::optional<double> &out)
{
    if (v.kind == Scalar::Null)
        return true;
    double value = 0.0;
    const bool ok = decimal(json, v, key, value);
    out = value;
    return ok;
}

bool optionalWholeNumber(JsonScanner &json, const Scalar &v, QLatin1StringView key, std::optional<int> &out)
{
    if (v.kind == Scalar::Null)
        return true;
    if (v.kind != Scalar::Number || v.number != std::floor(v.number) || std::fabs(v.number) > 2e9)
        return json.fail(tr("\"%1\" must be a whole number.").arg(key));
    out = int(v.number);
    return true;
}

bool measuredAt(JsonScanner &json, const Scalar &v, QLatin1StringView key, QDateTime &out)
{
    QString at;
    if (!text(json, v, key, at))
        return false;
    if (at.isEmpty())
        return true;
    out = parseIsoDateTime(at.toLatin1());
    if (!out.isValid())
        return json.fail(tr("\"measured_at\" is not a date and time (use ISO 8601, e.g. "
                            "2026-11-22T10:15:00Z)."));
    return true;
}

bool tloSource(JsonScanner &json, const Scalar &v, QLatin1StringView key, TloSource &out)
{
    QString source;
    if (!text(json, v, key, source))
        return false;
    const auto known = tloSourceFromName(source.toLatin1());
    if (!known)
        return json.fail(tr("\"tlo_source\" must be \"probe\", \"manual\" or \"pulled\"."));
    out = *known;
    return true;
}

bool boolean(JsonScanner &json, const Scalar &v, QLatin1StringView key, bool &out)
{
    if (v.kind != Scalar::Bool)
        return json.fail(tr("\"%1\" must be true or false.").arg(key));
    out = v.number != 0.0;
    return true;
}

// A tool's keys, in the order of kToolKeys. readJsonTool marks each key it has read in the bit 1 << key.
enum class ToolKey {
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
    TloSource,
    BreakTestFailed,
    ReferenceMz,
    LinuxCnc,
    CutterType,
    OverallLength,
    LifeLimitMinutes,
    LifeLimitUses,
    Flutes,
    ProbeX,
    ProbeY,
    ProbeTouches,
    ProbeTurn,
    ProbeLatchFeed,
    SpreadLimit,
};
constexpr QLatin1StringView kToolKeys[] = { JsonKey::Number, JsonKey::Pocket, JsonKey::Description,
    JsonKey::LengthGeometry, JsonKey::LengthWear, JsonKey::RadiusGeometry, JsonKey::RadiusWear,
    JsonKey::MeasuredTlo, JsonKey::MeasuredAt, JsonKey::Notes, JsonKey::TloSource, JsonKey::BreakTestFailed,
    JsonKey::ReferenceMz, JsonKey::LinuxCnc, JsonKey::CutterType, JsonKey::OverallLength,
    JsonKey::LifeLimitMinutes, JsonKey::LifeLimitUses, JsonKey::Flutes, JsonKey::ProbeX, JsonKey::ProbeY,
    JsonKey::ProbeTouches, JsonKey::ProbeTurn, JsonKey::ProbeLatchFeed, JsonKey::SpreadLimit };

constexpr quint32 seenBit(ToolKey key)
{
    return quint32(1) << int(key);
}

// The value of `key` into its field of `tool`.
bool readToolField(JsonScanner &json, ToolKey key, const Scalar &v, Tool &tool)
{
    const QLatin1StringView k = kToolKeys[int(key)];
    switch (key) {
    case ToolKey::Number:
        return wholeNumber(json, v, k, tool.number);
    case ToolKey::Pocket:
        return wholeNumber(json, v, k, tool.pocket);
    case ToolKey::Description:
        return text(json, v, k, tool.description);
    case ToolKey::LengthGeometry:
        return decimal(json, v, k, tool.lengthGeometry);
    case ToolKey::LengthWear:
        return decimal(json, v, k, tool.lengthWear);
    case ToolKey::RadiusGeometry:
        return decimal(json, v, k, tool.radiusGeometry);
    case ToolKey::RadiusWear:
        return decimal(json, v, k, tool.radiusWear);
    case ToolKey::MeasuredTlo:
        return optionalDecimal(json, v, k, tool.measuredTlo);
    case ToolKey::MeasuredAt:
        return measuredAt(json, v, k, tool.measuredAt);
    case ToolKey::Notes:
        return text(json, v, k, tool.notes);
    case ToolKey::TloSource:
        return tloSource(json, v, k, tool.tloSource);
    case ToolKey::BreakTestFailed:
        return boolean(json, v, k, tool.breakTestFailed);
    case ToolKey::ReferenceMz:
        return optionalDecimal(json, v, k, tool.referenceMz);
    case ToolKey::LinuxCnc:
        return text(json, v, k, tool.linuxCncExtra);
    case ToolKey::CutterType:
        return text(json, v, k, tool.cutterType);
    case ToolKey::OverallLength:
        return optionalDecimal(json, v, k, tool.overallLength);
    case ToolKey::LifeLimitMinutes:
        return optionalDecimal(json, v, k, tool.lifeLimitMinutes);
    case ToolKey::LifeLimitUses:
        return optionalWholeNumber(json, v, k, tool.lifeLimitUses);
    case ToolKey::Flutes:
        return optionalWholeNumber(json, v, k, tool.flutes);
    case ToolKey::ProbeX:
        return decimal(json, v, k, tool.probing.offsetX);
    case ToolKey::ProbeY:
        return decimal(json, v, k, tool.probing.offsetY);
    case ToolKey::ProbeTouches:
        return optionalWholeNumber(json, v, k, tool.probing.touches);
    case ToolKey::ProbeTurn:
        return boolean(json, v, k, tool.probing.turn);
    case ToolKey::ProbeLatchFeed:
        return optionalDecimal(json, v, k, tool.probing.latchFeed);
    case ToolKey::SpreadLimit:
        return optionalDecimal(json, v, k, tool.probing.spreadLimit);
    }
    Q_UNREACHABLE();
    return false;
}

// One "key": value of a tool; `seen` has the bits of the keys read before, as each may come once.
bool readToolEntry(JsonScanner &json, Tool &tool, quint32 &seen)
{
    QByteArrayView key;
    QString decodedKey;
    Scalar v;
    // A tool is at depth 2 (the table, "tools", the tool): its values at 3.
    if (!json.key(key, decodedKey) || !json.expect(':', "':' after a key") || !json.value(v, 3, key))
        return false;
    const auto found = std::find_if(std::begin(kToolKeys), std::end(kToolKeys),
        [&key](QLatin1StringView k) { return QByteArrayView(k.data(), k.size()) == key; });
    if (found == std::end(kToolKeys))
        return json.fail(tr("unknown field \"%1\" in a tool.").arg(excerpt(key)));
    const auto toolKey = ToolKey(found - std::begin(kToolKeys));
    if (seen & seenBit(toolKey))
        return json.fail(tr("the field \"%1\" appears twice in a tool.").arg(excerpt(key)));
    seen |= seenBit(toolKey);
    return readToolField(json, toolKey, v, tool);
}

} // namespace

bool readJsonTool(JsonScanner &json, Tool &tool)
{
    if (json.peek() != '{')
        return json.fail(tr("each entry of \"tools\" must be a JSON object such as {\"number\": 1}."));
    json.consume('{');
    quint32 seen = 0;
    if (!json.consume('}')) {
        do {
            if (!readToolEntry(json, tool, seen))
                return false;
        } while (json.consume(','));
        if (!json.expect('}', "',' or '}' in a tool"))
            return false;
    }
    if (!(seen & seenBit(ToolKey::Number)))
        return json.fail(tr("a tool has no \"number\"."));
    if (!(seen & seenBit(ToolKey::Pocket)))
        tool.pocket = defaultPocket(tool.number);
    return true;
}

} // namespace Toffee
