// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QCoreApplication>
#include <QList>
#include <QString>

#include "model/result.h"
#include "model/units.h"

namespace Toffee {

// How one tool is measured on the tool setter, kept with it in the table, lengths in the table's units. A
// face mill or fly cutter touches off-centre (its centre is recessed); a cutter with several edges is touched
// once per edge, the spindle turned by 360°/touches between touches where the controller can, and the spread
// between them is its runout or a chipped edge; a fragile tool gets a slower latch. The defaults are one
// touch at the centre at the setter's own feed, which is how every tool was measured before.
struct ProbeSettings
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::ProbeSettings)

public:
    static constexpr int kMaxTouches = 16;
    static constexpr int kMaxFlutes = 99;

    double offsetX = 0.0; // the touch-off point from the setter's centre
    double offsetY = 0.0;
    std::optional<int> touches; // empty: one per cutting edge when the tool's flute count is known, else 1
    bool turn = true; // between touches, turn the spindle by 360°/touches (where the controller can)
    std::optional<double> latchFeed; // per minute; empty: the setter's
    std::optional<double> spreadLimit; // the widest spread between touches that is no finding; empty: none

    [[nodiscard]] bool isDefault() const { return *this == ProbeSettings {}; }
    // The touches a probe makes: the setting, else one per edge when `flutes` is known, else 1.
    [[nodiscard]] int touchesFor(std::optional<int> flutes) const;
    // Every value in range for a table in `units` (offsets within the geometry limit, 1 to kMaxTouches
    // touches, a latch feed the setter takes, a spread limit above 0), else what is wrong.
    [[nodiscard]] Result<void> validate(Units units) const;
    // "X 30, 4 touches, latch 20, spread 0.02", "X 12.5, Y -3, same edge": how the settings are typed and
    // shown, the tool's flute count with them ("4 edges"); empty for the defaults. parse() reads it back, any
    // order.
    [[nodiscard]] static QString text(const ProbeSettings &settings, std::optional<int> flutes, Units units);
    struct Parsed;
    [[nodiscard]] static Result<Parsed> parse(const QString &text, Units units);
    friend bool operator==(const ProbeSettings &, const ProbeSettings &) = default;
};

struct ProbeSettings::Parsed
{
    ProbeSettings settings;
    std::optional<int> flutes;
};

// A probe's settings as a controller takes them: millimetres, the touches counted, the spread limit in force.
// ProbePlan::of is where a tool's settings cross from the table's units to the machine's.
struct ProbePlan
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::ProbePlan)

public:
    double offsetX = 0.0;
    double offsetY = 0.0;
    int touches = 1;
    bool turn = true;
    std::optional<double> latchFeed;
    std::optional<double> spreadLimit;

    [[nodiscard]] static ProbePlan of(const ProbeSettings &settings, std::optional<int> flutes, Units units);
    // One touch at the setter's centre at its own feed: the cycle as it was before settings.
    [[nodiscard]] bool isPlain() const
    {
        return offsetX == 0.0 && offsetY == 0.0 && touches == 1 && !latchFeed;
    }
    [[nodiscard]] bool isOffCentre() const { return offsetX != 0.0 || offsetY != 0.0; }
    // In range (as ProbeSettings::validate, in millimetres), else what is wrong.
    [[nodiscard]] Result<void> validate() const;
    // "4 touches, X 30 mm off centre" for an operator; empty when plain.
    [[nodiscard]] QString summary() const;
    friend bool operator==(const ProbePlan &, const ProbePlan &) = default;
};

// The contacts of one measurement, machine Z in mm, one per touch in the order made. The longest edge touches
// highest: the TLO is taken from it (as the Carvera's firmware does), so that no edge cuts deeper than the
// offset says; the spread is how far the edges lie apart.
[[nodiscard]] double highestTouch(const QList<double> &touches);
[[nodiscard]] double spreadOf(const QList<double> &touches);

} // namespace Toffee
