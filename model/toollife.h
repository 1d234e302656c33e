// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QCoreApplication>
#include <QString>

#include "model/result.h"
#include "model/tool.h"

namespace Toffee {

// What the cutter in a tool's pocket has done since it went in (the history's program runs after the tool's
// newest new cutter): its minutes of cutting and the programs it cut in.
struct UsedLife
{
    double seconds = 0.0;
    int uses = 0;
    friend bool operator==(const UsedLife &, const UsedLife &) = default;
};

// How near its limit a tool is: within kNearFraction of either limit is near, beyond one is exceeded.
enum class LifeState { NoLimit, Fine, Near, Exceeded };

class ToolLife
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::ToolLife)

public:
    static constexpr double kNearFraction = 0.9;

    [[nodiscard]] static LifeState state(const Tool &tool, const UsedLife &used);
    // The fraction of its life used, the larger of minutes and uses; nothing without a limit.
    [[nodiscard]] static std::optional<double> fraction(const Tool &tool, const UsedLife &used);
    // "90 min", "40 uses", "90 min, 40 uses", or empty: how the limits are typed and shown.
    [[nodiscard]] static QString limitText(const Tool &tool);
    // The limits typed as limitText writes them (any order, "min"/"uses" in English or in the language
    // Toffee speaks; empty: none). A bare number is minutes.
    [[nodiscard]] static Result<void> parseLimit(const QString &text, Tool &tool);
    // "25 min of 90 · 3 of 40 uses", "25 min · 3 uses" without a limit.
    [[nodiscard]] static QString usedText(const Tool &tool, const UsedLife &used);
};

} // namespace Toffee
