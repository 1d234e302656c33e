// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

#include "model/probing.h"
#include "model/result.h"

namespace Toffee {

// Where a machine's tool setter is and how to probe on it, for a controller that measures tools with Toffee's
// own probing cycle (grblHAL; the Carvera's firmware knows its setter itself). Machine coordinates in mm,
// feeds in mm/min. The cycle (docs/GRBLHAL.md): lift to safeZ, move over (x, y), G38.2 down to zMin at
// seekFeed, back off by backoff, G38.2 again at latchFeed, lift to safeZ.
struct ToolSetter
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::ToolSetter)

public:
    static constexpr double kDefaultSeekFeed = 500.0;
    static constexpr double kDefaultLatchFeed = 40.0;
    static constexpr double kDefaultBackoff = 2.0;
    static constexpr double kMaxFeed = 20000.0;
    static constexpr double kMaxBackoff = 20.0;

    double x = 0.0;
    double y = 0.0;
    double zMin = 0.0; // the lowest machine Z the search goes to
    double seekFeed = kDefaultSeekFeed;
    double latchFeed = kDefaultLatchFeed;
    double backoff = kDefaultBackoff;
    double safeZ = 0.0; // the machine Z it lifts to before moving over the setter and after (0: the top)

    // "X,Y,ZMIN" or "X,Y,ZMIN,SEEK,LATCH[,BACKOFF[,SAFEZ]]" (toffee-cli --setter), each checked.
    [[nodiscard]] static Result<ToolSetter> parse(const QString &text);
    // The same form, every field: what parse() reads back.
    [[nodiscard]] QString text() const;
    // Every value finite and in range, zMin below safeZ, the latch feed no faster than the seek.
    [[nodiscard]] Result<void> validate() const;
    friend bool operator==(const ToolSetter &, const ToolSetter &) = default;
};

// Toffee's setter cycle for one tool: the setter and the tool's plan together, checked, with where the cycle
// goes. The cycle: lift to safeZ, move over (x, y) (the setter's centre plus the plan's offset), then for
// each touch: G38.2 down to zMin at the seek feed, back off by backoff, G38.2 again at the latch feed, and
// between touches lift clear of the setter (kEdgeClearance above the contact) for the spindle to turn.
struct SetterCycle
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::SetterCycle)

public:
    // How far above a contact the tool lifts between touches: clear of the setter for the next edge.
    static constexpr double kEdgeClearance = 6.0;

    ToolSetter setter;
    ProbePlan plan;

    // The setter's settings with the plan's (its latch feed), each checked: a latch faster than the seek, a
    // touch-off point beyond the machine's coordinates, a plan out of range are refused.
    [[nodiscard]] static Result<SetterCycle> of(const ToolSetter &setter, const ProbePlan &plan);
    [[nodiscard]] double x() const { return setter.x + plan.offsetX; }
    [[nodiscard]] double y() const { return setter.y + plan.offsetY; }
    [[nodiscard]] double latchFeed() const { return plan.latchFeed.value_or(setter.latchFeed); }
    [[nodiscard]] double liftBetween(double contact) const;
    // For a controller that cannot turn its spindle to an angle, when the plan asks for it: what its touches
    // then measured ("grblHAL cannot turn …"); empty otherwise.
    [[nodiscard]] QString cannotTurnNote(const QString &controller) const;
};

} // namespace Toffee
