// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/weartrend.h"

#include <algorithm>
#include <cmath>

#include "model/library/library.h"
#include "model/numberformat.h"
#include "model/toolvalidation.h"

namespace Toffee {

QList<TrendPoint> WearTrend::pointsOf(
    const QList<HistoryEvent> &events, const QList<ToolUse> &uses, bool *overCuttingTime)
{
    // Only the cutter in the pocket now: a new cutter ends the old one's trend and its cutting time.
    const QDateTime since = cutterSince(events);
    const bool cutting = std::any_of(
        uses.cbegin(), uses.cend(), [&since](const ToolUse &u) { return !since.isValid() || u.at > since; });
    if (overCuttingTime)
        *overCuttingTime = cutting;
    QList<TrendPoint> out;
    QDateTime first;
    for (const HistoryEvent &e : events) {
        // A TLO beyond any tool (written before the history checked them) is no point of a trend.
        if (e.kind != EventKind::Probe || !e.tlo || !isMachineTlo(*e.tlo)
            || (since.isValid() && e.at <= since))
            continue;
        if (!first.isValid())
            first = e.at;
        double x = 0.0;
        if (cutting) {
            for (const ToolUse &u : uses) {
                if (u.at <= e.at && (!since.isValid() || u.at > since))
                    x += u.cuttingSeconds;
            }
        } else {
            x = double(first.msecsTo(e.at)) / 1000.0;
        }
        out.append({ x, *e.tlo });
    }
    return out;
}

std::optional<WearTrend> WearTrend::fit(const QList<TrendPoint> &points)
{
    if (points.isEmpty())
        return std::nullopt;
    WearTrend t;
    t.points = int(points.size());
    const double n = double(points.size());
    double sx = 0.0;
    double sy = 0.0;
    for (const TrendPoint &p : points) {
        sx += p.x;
        sy += p.tlo;
    }
    const double mx = sx / n;
    const double my = sy / n;
    double sxx = 0.0;
    double sxy = 0.0;
    for (const TrendPoint &p : points) {
        sxx += (p.x - mx) * (p.x - mx);
        sxy += (p.x - mx) * (p.tlo - my);
    }
    // All at one x (one point, or probes with no cutting between them): a level line through their mean.
    t.slope = sxx > 0.0 ? sxy / sxx : 0.0;
    t.intercept = my - t.slope * mx;
    double ss = 0.0;
    for (const TrendPoint &p : points) {
        const double r = p.tlo - t.predict(p.x);
        ss += r * r;
    }
    const int freedom = t.points - (sxx > 0.0 ? 2 : 1);
    t.spread = freedom > 0 ? std::sqrt(ss / double(freedom)) : 0.0;
    // Values no machine measures overflow the sums: no trend then, rather than one of infinities.
    if (!std::isfinite(t.slope) || !std::isfinite(t.intercept) || !std::isfinite(t.spread))
        return std::nullopt;
    return t;
}

std::optional<QString> WearTrend::check(int tool, double x, double tlo, double tolerance) const
{
    const double off = tlo - predict(x);
    // Lengths at the machine's 0.001 mm: a difference of exactly the tolerance is within it, whatever its
    // last binary digit (43.04 - 42.94 is 0.1000000000000014).
    if (!std::isfinite(off) || std::fabs(off) <= tolerance + 1e-9)
        return std::nullopt; // never "nan mm longer"
    const QString amount = millimetres(std::fabs(off));
    const QString band = formatNumber(tolerance, NumberFormat::upTo(3).inLocale());
    return off < 0
        ? tr("T%1 measured %2 shorter than its trend predicts (±%3): check the tip.")
              .arg(tool)
              .arg(amount, band)
        : tr("T%1 measured %2 longer than its trend predicts (±%3): check that it sits right in its "
             "holder.")
              .arg(tool)
              .arg(amount, band);
}

std::optional<QString> checkProbeAgainstTrend(
    const Library &library, const HistoryEvent &event, double tolerance)
{
    if (event.kind != EventKind::Probe || !event.tlo || !isMachineTlo(*event.tlo))
        return std::nullopt;
    auto history = library.history({ event.machine, event.tool, {}, 0 });
    auto uses = library.uses(event.machine, event.tool);
    if (!history || !uses)
        return std::nullopt;
    QList<HistoryEvent> before;
    for (const HistoryEvent &e : history.value()) {
        if (e.id != event.id && e.at <= event.at)
            before.append(e);
    }
    const auto trend = WearTrend::fit(WearTrend::pointsOf(before, uses.value()));
    if (!trend)
        return std::nullopt;
    QList<HistoryEvent> withThis = before;
    withThis.append(event);
    const QList<TrendPoint> all = WearTrend::pointsOf(withThis, uses.value());
    return trend->check(event.tool, all.last().x, *event.tlo, tolerance);
}

} // namespace Toffee
