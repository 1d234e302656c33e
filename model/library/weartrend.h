// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QCoreApplication>
#include <QList>

#include "model/library/historyevent.h"

namespace Toffee {

class Library;

// One probe on a tool's trend: how far into its life (x) it was measured, and the TLO.
struct TrendPoint
{
    double x = 0.0; // seconds of cutting before the probe, or of wall time since the first probe
    double tlo = 0.0;
};

// A tool's wear trend: the least-squares line of its probed TLO over its recorded cutting time (over wall
// time when none is recorded), and the spread of the probes around it.
struct WearTrend
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::WearTrend)

public:
    int points = 0;
    bool overCuttingTime = false;
    double slope = 0.0; // mm per second of x
    double intercept = 0.0; // the TLO at x = 0
    double spread = 0.0; // the residuals' standard deviation, mm

    [[nodiscard]] double predict(double x) const { return intercept + slope * x; }

    // The points of one tool's probes (oldest first), with x from the uses recorded before each.
    [[nodiscard]] static QList<TrendPoint> pointsOf(
        const QList<HistoryEvent> &events, const QList<ToolUse> &uses, bool *overCuttingTime = nullptr);
    // The line through them: none for no point, a level line through one.
    [[nodiscard]] static std::optional<WearTrend> fit(const QList<TrendPoint> &points);

    // A probe at `x` measuring `tlo`, against this trend: a warning with numbers when it is farther from the
    // prediction than `tolerance`, else nothing.
    [[nodiscard]] std::optional<QString> check(int tool, double x, double tlo, double tolerance) const;
};

// A new probe of `event.tool` checked against the trend of the probes before it in `library`.
[[nodiscard]] std::optional<QString> checkProbeAgainstTrend(
    const Library &library, const HistoryEvent &event, double tolerance);

} // namespace Toffee
