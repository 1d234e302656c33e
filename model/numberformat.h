// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

#include "model/units.h"

namespace Toffee {

// How a number is written. One formatter makes every number Toffee writes: in files, in commands to a
// machine, in the window and on the command line. Files and machines always get a point and no grouping; the
// window gets the user's decimal mark.
struct NumberFormat
{
    int minDecimals = 0; // zeros are added up to this many decimals
    int maxDecimals = -1; // rounded (as printf rounds) to at most this many; -1: exact, see formatNumber
    bool localized = false; // the user's locale's decimal mark and minus sign, for people

    // Exactly `decimals` places: "30.488", "0.100".
    [[nodiscard]] static constexpr NumberFormat fixed(int decimals) { return { decimals, decimals, false }; }
    // At most `decimals` places, trailing zeros dropped: "30.5" for 30.5 at 4.
    [[nodiscard]] static constexpr NumberFormat upTo(int decimals) { return { 0, decimals, false }; }
    // For people reading tool data: the unit's usual decimals (3 in mm, 4 in inches), more when the value has
    // more, so nothing is hidden.
    [[nodiscard]] static constexpr NumberFormat display(Units units)
    {
        return { resolutionDecimals(units), -1, false };
    }
    // A value in a command to a machine: at most four decimals (finer than 0.001 mm and as fine as 0.0001
    // in), no trailing zeros: "M493.3 Z-30.488".
    [[nodiscard]] static constexpr NumberFormat command() { return upTo(4); }
    [[nodiscard]] constexpr NumberFormat inLocale() const { return { minDecimals, maxDecimals, true }; }
};

// Appends `value` as `format` says (never localized: bytes go to files and machines). With no maximum, the
// text is the shortest one that reads back as the same double; never an exponent, never "-0" (a value that
// rounds to zero is written without its sign), and a value that is not finite is written as 0 when exact.
void appendNumber(QByteArray &out, double value, NumberFormat format = {});
[[nodiscard]] QByteArray numberBytes(double value, NumberFormat format = {});
[[nodiscard]] QString formatNumber(double value, NumberFormat format = {});
// How a message quotes a number it refuses: formatNumber's digits when they are few, else the shortest form
// with an exponent ("1e+308"), never the 309 digits of a huge double.
[[nodiscard]] QString quotedNumber(double value);

// Shorthands for the formats the window uses most.
[[nodiscard]] QString displayNumber(double value, Units units);
// "30.488 mm" in the user's locale (3 decimals), or the number alone.
[[nodiscard]] QString millimetres(double value, bool withUnit = true);

} // namespace Toffee
