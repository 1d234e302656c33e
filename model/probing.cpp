// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/probing.h"

#include <algorithm>
#include <cmath>

#include <QRegularExpression>
#include <QStringList>

#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/toolsetter.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// The farthest a touch-off point lies from the setter's centre: a 200 mm face mill's edge.
constexpr double kMaxOffCentreMm = 100.0;
// A spread wider than this is no runout but a broken tool: the break test says that.
constexpr double kMaxSpreadLimitMm = 5.0;

QString shown(double value, Units units)
{
    return formatNumber(value, NumberFormat::upTo(resolutionDecimals(units)));
}

bool inRange(double value, double lowest, double highest)
{
    return std::isfinite(value) && value >= lowest && value <= highest;
}

Result<void> validateMillimetres(const ProbePlan &p, const QString &unit, Units units)
{
    const double offMax = fromMillimetres(kMaxOffCentreMm, units);
    if (!inRange(p.offsetX, -offMax, offMax) || !inRange(p.offsetY, -offMax, offMax))
        return Error { ProbeSettings::tr(
            "A touch-off point lies at most %1 %2 from the setter's centre in X and Y.")
                           .arg(shown(offMax, units), unit) };
    if (p.touches < 1 || p.touches > ProbeSettings::kMaxTouches)
        return Error {
            ProbeSettings::tr("A tool is touched 1 to %1 times.").arg(ProbeSettings::kMaxTouches)
        };
    const double feedMax = fromMillimetres(ToolSetter::kMaxFeed, units);
    if (p.latchFeed && !inRange(*p.latchFeed, 1e-9, feedMax))
        return Error { ProbeSettings::tr("A latch feed must be more than 0 and at most %1 %2/min.")
                           .arg(shown(feedMax, units), unit) };
    const double spreadMax = fromMillimetres(kMaxSpreadLimitMm, units);
    if (p.spreadLimit && !inRange(*p.spreadLimit, 1e-9, spreadMax))
        return Error { ProbeSettings::tr("A spread limit must be more than 0 and at most %1 %2.")
                           .arg(shown(spreadMax, units), unit) };
    return {};
}

ProbePlan plainPlan(const ProbeSettings &s, int touches)
{
    ProbePlan p;
    p.offsetX = s.offsetX;
    p.offsetY = s.offsetY;
    p.touches = touches;
    p.turn = s.turn;
    p.latchFeed = s.latchFeed;
    p.spreadLimit = s.spreadLimit;
    return p;
}

} // namespace

int ProbeSettings::touchesFor(std::optional<int> flutes) const
{
    if (touches)
        return *touches;
    return flutes && *flutes >= 1 && *flutes <= kMaxTouches ? *flutes : 1;
}

Result<void> ProbeSettings::validate(Units units) const
{
    return validateMillimetres(plainPlan(*this, touches.value_or(1)), unitsSymbol(units), units);
}

QString ProbeSettings::text(const ProbeSettings &s, std::optional<int> flutes, Units units)
{
    QStringList parts;
    if (s.offsetX != 0.0)
        parts << tr("X %1").arg(shown(s.offsetX, units));
    if (s.offsetY != 0.0)
        parts << tr("Y %1").arg(shown(s.offsetY, units));
    if (flutes)
        parts << (*flutes == 1 ? tr("1 edge") : tr("%1 edges").arg(*flutes));
    if (s.touches)
        parts << (*s.touches == 1 ? tr("1 touch") : tr("%1 touches").arg(*s.touches));
    if (!s.turn)
        parts << tr("same edge");
    if (s.latchFeed)
        parts << tr("latch %1").arg(shown(*s.latchFeed, units));
    if (s.spreadLimit)
        parts << tr("spread %1").arg(shown(*s.spreadLimit, units));
    return parts.join(u", "_s);
}

Result<ProbeSettings::Parsed> ProbeSettings::parse(const QString &text, Units units)
{
    const QString how
        = tr("Type how the tool is measured, any of: \"X 30\" and \"Y 0\" (the touch-off point from "
             "the setter's centre), \"4 edges\", \"4 touches\", \"same edge\" (no turn between "
             "touches), \"latch 20\" (the slow touch's feed per minute), \"spread 0.02\" (the widest "
             "spread that is no finding), separated by commas; empty for one touch at the centre.");
    Parsed out;
    bool seen[7] = {};
    const auto once = [&seen](int which) {
        return !std::exchange(seen[which], true);
    };
    // A word and a number, either way round: "X 30", "4 touches", "latch 20".
    static const QRegularExpression wordNumber(
        u"^\\s*([^\\s0-9+\\-.,]+(?:\\s+[^\\s0-9+\\-.,]+)?)\\s*([+\\-]?[0-9]+(?:\\.[0-9]+)?)\\s*$"_s);
    static const QRegularExpression numberWord(
        u"^\\s*([+\\-]?[0-9]+(?:\\.[0-9]+)?)\\s*([^\\s0-9+\\-.,]+)\\s*$"_s);
    // Each word in English or in the language Toffee speaks.
    static const char *const kSameEdge[] = { QT_TR_NOOP("same edge") };
    static const char *const kX[] = { "X" };
    static const char *const kY[] = { "Y" };
    static const char *const kTouches[] = { QT_TR_NOOP("touches"), QT_TR_NOOP("touch") };
    static const char *const kEdges[] = { QT_TR_NOOP("edges"), QT_TR_NOOP("edge"), QT_TR_NOOP("flutes") };
    static const char *const kLatch[] = { QT_TR_NOOP("latch") };
    static const char *const kSpread[] = { QT_TR_NOOP("spread") };
    const auto is = [](const QString &word, const auto &names) {
        return std::any_of(std::begin(names), std::end(names), [&word](const char *name) {
            return word.compare(QLatin1StringView(name), Qt::CaseInsensitive) == 0
                || word.compare(tr(name), Qt::CaseInsensitive) == 0;
        });
    };
    for (const QString &raw : text.split(u',', Qt::SkipEmptyParts)) {
        const QString piece = raw.simplified();
        if (piece.isEmpty())
            continue;
        const auto fail = [&] {
            return Error { tr("\"%1\" is not a probing setting. %2").arg(excerpt(piece), how) };
        };
        if (is(piece, kSameEdge)) {
            if (!once(0))
                return fail();
            out.settings.turn = false;
            continue;
        }
        QString word;
        QString digits;
        if (const auto m = wordNumber.match(piece); m.hasMatch()) {
            word = m.captured(1);
            digits = m.captured(2);
        } else if (const auto n = numberWord.match(piece); n.hasMatch()) {
            word = n.captured(2);
            digits = n.captured(1);
        } else {
            return fail();
        }
        const auto value = parseDecimal(QByteArrayView(digits.toLatin1()));
        if (!value)
            return fail();
        const bool whole = *value == std::floor(*value) && *value >= 1.0;
        if (is(word, kX) && once(1)) {
            out.settings.offsetX = *value;
        } else if (is(word, kY) && once(2)) {
            out.settings.offsetY = *value;
        } else if (is(word, kTouches) && once(3)) {
            if (!whole || *value > kMaxTouches)
                return Error { tr("A tool is touched 1 to %1 times.").arg(kMaxTouches) };
            out.settings.touches = int(*value);
        } else if (is(word, kEdges) && once(4)) {
            if (!whole || *value > kMaxFlutes)
                return Error { tr("A cutter has 1 to %1 cutting edges.").arg(kMaxFlutes) };
            out.flutes = int(*value);
        } else if (is(word, kLatch) && once(5)) {
            out.settings.latchFeed = *value;
        } else if (is(word, kSpread) && once(6)) {
            out.settings.spreadLimit = *value;
        } else {
            return fail();
        }
    }
    if (auto valid = out.settings.validate(units); !valid)
        return valid.error();
    return out;
}

ProbePlan ProbePlan::of(const ProbeSettings &settings, std::optional<int> flutes, Units units)
{
    ProbePlan p = plainPlan(settings, settings.touchesFor(flutes));
    p.offsetX = toMillimetres(settings.offsetX, units);
    p.offsetY = toMillimetres(settings.offsetY, units);
    if (settings.latchFeed)
        p.latchFeed = toMillimetres(*settings.latchFeed, units);
    if (settings.spreadLimit)
        p.spreadLimit = toMillimetres(*settings.spreadLimit, units);
    return p;
}

Result<void> ProbePlan::validate() const
{
    return validateMillimetres(*this, u"mm"_s, Units::Millimetre);
}

QString ProbePlan::summary() const
{
    QStringList parts;
    if (touches > 1)
        parts << tr("%1 touches").arg(touches);
    if (isOffCentre())
        parts << tr("X %1 Y %2 mm from the setter's centre")
                     .arg(shown(offsetX, Units::Millimetre), shown(offsetY, Units::Millimetre));
    if (latchFeed)
        parts << tr("latch at %1 mm/min").arg(shown(*latchFeed, Units::Millimetre));
    return parts.join(u", "_s);
}

double highestTouch(const QList<double> &touches)
{
    return touches.isEmpty() ? 0.0 : *std::max_element(touches.cbegin(), touches.cend());
}

double spreadOf(const QList<double> &touches)
{
    if (touches.isEmpty())
        return 0.0;
    const auto [low, high] = std::minmax_element(touches.cbegin(), touches.cend());
    return std::round((*high - *low) * 1e6) / 1e6;
}

} // namespace Toffee
