// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/timetext.h"

#include <cmath>

#include "model/clock.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

QString ageText(const QDateTime &at, const QDateTime &now)
{
    // A time beyond now (a clock set wrong somewhere) is no age: said as what it is.
    if (Clock::isInFuture(at, now))
        return tr("dated in the future (%1)").arg(at.toUTC().toString(u"yyyy-MM-dd HH:mm 'UTC'"_s));
    const qint64 minutes = std::max<qint64>(0, at.secsTo(now) / 60);
    if (minutes < 1)
        return tr("just now");
    if (minutes < 60)
        return tr("%1 min ago").arg(minutes);
    if (minutes < 48 * 60)
        return tr("%1 h ago").arg(minutes / 60);
    return tr("%1 days ago").arg(minutes / (24 * 60));
}

QString durationText(double seconds)
{
    const qint64 whole = qint64(std::llround(seconds));
    if (whole < 60)
        return tr("%1 s").arg(whole);
    const qint64 minutes = (whole + 30) / 60;
    if (minutes < 60)
        return tr("%1 min").arg(minutes);
    return tr("%1 h %2 min").arg(minutes / 60).arg(minutes % 60, 2, 10, QLatin1Char('0'));
}

} // namespace Toffee
