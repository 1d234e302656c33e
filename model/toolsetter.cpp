// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/toolsetter.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <QStringList>

#include "model/limits.h"
#include "model/numberformat.h"
#include "model/textparsing.h"

namespace Toffee {

namespace {

QString mm(double v)
{
    return formatNumber(v, NumberFormat::upTo(3));
}

} // namespace

Result<ToolSetter> ToolSetter::parse(const QString &text)
{
    const QStringList parts = text.split(u',');
    if (parts.size() != 3 && parts.size() != 5 && parts.size() != 6 && parts.size() != 7)
        return Error { tr("The tool setter \"%1\" is not X,Y,ZMIN (machine coordinates in mm, e.g. 0,0,-120) "
                          "nor X,Y,ZMIN,SEEK,LATCH[,BACKOFF] (feeds in mm/min, back-off in mm).")
                           .arg(text) };
    std::array<double, 7> v {};
    for (qsizetype i = 0; i < parts.size(); ++i) {
        const auto value = parseDecimal(QByteArrayView(parts[i].trimmed().toLatin1()));
        if (!value)
            return Error {
                tr("The tool setter \"%1\": \"%2\" is not a number.").arg(text, parts[i].trimmed())
            };
        v[size_t(i)] = *value;
    }
    ToolSetter setter;
    setter.x = v[0];
    setter.y = v[1];
    setter.zMin = v[2];
    if (parts.size() >= 5) {
        setter.seekFeed = v[3];
        setter.latchFeed = v[4];
    }
    if (parts.size() >= 6)
        setter.backoff = v[5];
    if (parts.size() == 7)
        setter.safeZ = v[6];
    if (auto valid = setter.validate(); !valid)
        return valid.error();
    return setter;
}

QString ToolSetter::text() const
{
    QStringList fields { mm(x), mm(y), mm(zMin), mm(seekFeed), mm(latchFeed), mm(backoff) };
    if (safeZ != 0.0)
        fields << mm(safeZ);
    return fields.join(u',');
}

Result<void> ToolSetter::validate() const
{
    for (double value : { x, y, zMin, safeZ }) {
        if (!std::isfinite(value) || std::fabs(value) > Limits::kMaxMachineOffsetMm)
            return Error { tr("The tool setter's position must be machine coordinates from -%1 to %1 mm.")
                               .arg(Limits::kMaxMachineOffsetMm) };
    }
    if (zMin >= safeZ)
        return Error { tr("The tool setter's lowest Z (%1 mm) must be below the Z it lifts to (%2 mm): the "
                          "search goes down.")
                           .arg(mm(zMin), mm(safeZ)) };
    for (double feed : { seekFeed, latchFeed }) {
        if (!std::isfinite(feed) || feed <= 0.0 || feed > kMaxFeed)
            return Error {
                tr("A probing feed must be more than 0 and at most %1 mm/min.").arg(mm(kMaxFeed))
            };
    }
    if (latchFeed > seekFeed)
        return Error { tr("The latch feed (%1 mm/min) must not be faster than the search feed (%2 mm/min): "
                          "the second touch is the slow, precise one.")
                           .arg(mm(latchFeed), mm(seekFeed)) };
    if (!std::isfinite(backoff) || backoff <= 0.0 || backoff > kMaxBackoff)
        return Error { tr("The back-off between the two touches must be more than 0 and at most %1 mm.")
                           .arg(mm(kMaxBackoff)) };
    return {};
}

Result<SetterCycle> SetterCycle::of(const ToolSetter &setter, const ProbePlan &plan)
{
    if (auto valid = plan.validate(); !valid)
        return valid.error();
    SetterCycle cycle { setter, plan };
    if (auto valid = cycle.setter.validate(); !valid)
        return valid.error();
    if (cycle.latchFeed() > setter.seekFeed)
        return Error { tr(
            "The tool's latch feed (%1 mm/min) must not be faster than the setter's search feed (%2 "
            "mm/min).")
                           .arg(mm(cycle.latchFeed()), mm(setter.seekFeed)) };
    for (double v : { cycle.x(), cycle.y() }) {
        if (std::fabs(v) > Limits::kMaxMachineOffsetMm)
            return Error { tr(
                "The tool's touch-off point (X %1, Y %2 mm) lies beyond the machine's coordinates.")
                               .arg(mm(cycle.x()), mm(cycle.y())) };
    }
    return cycle;
}

double SetterCycle::liftBetween(double contact) const
{
    return std::min(setter.safeZ, contact + kEdgeClearance);
}

QString SetterCycle::cannotTurnNote(const QString &controller) const
{
    if (plan.touches < 2 || !plan.turn)
        return {};
    return tr("%1 cannot turn its spindle to an angle, so the %2 touches met the setter wherever the spindle "
              "stood: their spread is the setter's repeatability and the cutter's runout there, not each "
              "edge's.")
        .arg(controller)
        .arg(plan.touches);
}

} // namespace Toffee
