// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QString>

namespace Toffee {

enum class Units { Millimetre, Inch };

// Every conversion of a length between the units happens through these, and only here: machines speak
// millimetres (Toffee refuses a controller set to inches before it writes), tables are in their own units.
// A length crosses at ToolTable::recordMeasurement (machine to table) and ToolTable::storedTlo (table to
// machine); a CAM library's at its import.
inline constexpr double kMillimetresPerInch = 25.4;
[[nodiscard]] constexpr double convertLength(double length, Units from, Units to)
{
    if (from == to)
        return length;
    return to == Units::Inch ? length / kMillimetresPerInch : length * kMillimetresPerInch;
}
[[nodiscard]] constexpr double toMillimetres(double length, Units from)
{
    return convertLength(length, from, Units::Millimetre);
}
[[nodiscard]] constexpr double fromMillimetres(double millimetres, Units to)
{
    return convertLength(millimetres, Units::Millimetre, to);
}

// How far a machine's millimetres (printed to 0.001 mm) may lie from a length stored in `stored` units and
// still be that length: half the machine's step, and for an inch table half of its 0.0001 in step as well.
[[nodiscard]] constexpr double sameLengthWithin(Units stored)
{
    return stored == Units::Inch ? 0.0005 + 0.00005 * kMillimetresPerInch : 0.0005;
}

[[nodiscard]] QString unitsSymbol(Units units); // "mm" or "in", as written in files
[[nodiscard]] std::optional<Units> unitsFromSymbol(QStringView symbol);
// The decimals of a machine's resolution, at which lengths are stored and shown: 0.001 mm, 0.0001 in.
[[nodiscard]] constexpr int resolutionDecimals(Units units)
{
    return units == Units::Inch ? 4 : 3;
}

} // namespace Toffee
