// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QString>

namespace Toffee {

enum class Units { Millimetre, Inch };

[[nodiscard]] QString unitsSymbol(Units units); // "mm" or "in", as written in files
[[nodiscard]] std::optional<Units> unitsFromSymbol(QStringView symbol);
// The decimals of a machine's resolution, at which lengths are stored and shown: 0.001 mm, 0.0001 in.
[[nodiscard]] constexpr int resolutionDecimals(Units units)
{
    return units == Units::Inch ? 4 : 3;
}

} // namespace Toffee
