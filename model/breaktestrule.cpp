// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/breaktestrule.h"

#include <cmath>

#include <QCoreApplication>

namespace Toffee {

std::optional<BreakTestExclusion> breakTestExclusion(int tool)
{
    if (tool == 0 || tool >= 9)
        return BreakTestExclusion::WirelessProbe;
    return std::nullopt;
}

QString breakTestExclusionText(BreakTestExclusion why, int tool, bool translated)
{
    Q_UNUSED(why) // one reason so far
    const char *text = QT_TRANSLATE_NOOP("Toffee",
        "T%1 is not break-tested: the firmware's break test takes T0 and every tool from T9 up for its "
        "wireless probe, and would halt.");
    return (translated ? QCoreApplication::translate("Toffee", text) : QString::fromUtf8(text)).arg(tool);
}

bool isZeroTlo(double tlo)
{
    return std::round(tlo * 1000.0) == 0.0;
}

double comparableTlo(double storedTlo)
{
    return isZeroTlo(storedTlo) ? kZeroTloCompared : storedTlo;
}

} // namespace Toffee
