// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QString>

namespace Toffee {

enum class Units { Millimetre, Inch };

[[nodiscard]] QString unitsSymbol(Units units); // "mm" or "in", as written in files
[[nodiscard]] std::optional<Units> unitsFromSymbol(QStringView symbol);

} // namespace Toffee
