// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/breaktestrule.h"

#include <cmath>

#include <QCoreApplication>

namespace Toffee {

std::optional<BreakTestExclusion> breakTestExclusion(int tool, std::optional<double> storedTlo)
{
    if (tool == 0 || tool >= 9)
        return BreakTestExclusion::WirelessProbe;
    if (storedTlo && std::round(*storedTlo * 1000.0) == 0.0)
        return BreakTestExclusion::NoPreviousTlo;
    return std::nullopt;
}

QString breakTestExclusionText(BreakTestExclusion why, int tool, bool translated)
{
    const char *text = why == BreakTestExclusion::WirelessProbe
        ? QT_TRANSLATE_NOOP("Toffee",
            "T%1 is not break-tested: the firmware's break test takes T0 and every tool from T9 up for its "
            "wireless probe, and would halt.")
        : QT_TRANSLATE_NOOP("Toffee",
            "T%1 is not break-tested: its TLO is 0.000 mm (the reference tool's), which the firmware's break "
            "test takes for none (\"No previous TLO included\"): it would measure the tool without "
            "comparing.");
    return (translated ? QCoreApplication::translate("Toffee", text) : QString::fromUtf8(text)).arg(tool);
}

} // namespace Toffee
