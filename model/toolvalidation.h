// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "result.h"
#include "tool.h"
#include "units.h"

namespace Toffee {

// The ranges a real controller enforces (FANUC IS-B, see DIALECTS.md); inch limits are the same digits
// shifted one place, as the controller's inch input does.
namespace Limits {
constexpr int kMinToolNumber = 0; // T0: the Carvera's wireless probe
constexpr int kMaxToolNumber = 999999; // the Carvera's 3-axis probe uses T999990-999999
// LinuxCNC writes P0 for the spindle of a random tool changer, and its own sample table has P99999.
constexpr int kMinPocket = 0;
constexpr int kMaxPocket = 99999;
constexpr int kMaxDescriptionLength = 255;
constexpr int kMaxNotesLength = 10000;
constexpr double kMaxGeometryMm = 999.999;
constexpr double kMaxWearMm = 99.999;
constexpr double kMaxGeometryInch = 99.9999;
constexpr double kMaxWearInch = 9.9999;
} // namespace Limits

[[nodiscard]] double maxGeometry(Units units);
// The pocket a new tool gets when none is given: its own number where that is a pocket, else 1.
[[nodiscard]] int defaultPocket(int toolNumber);
[[nodiscard]] double maxWear(Units units);

// Checks every field; the first bad one comes back with a message an operator can act on.
[[nodiscard]] Result<void> validateTool(const Tool &tool, Units units);

// The single-value checks validateTool is made of, for editors that check one field as it is typed.
[[nodiscard]] Result<void> validateToolNumber(int number);
[[nodiscard]] Result<void> validatePocket(int pocket);
[[nodiscard]] Result<void> validateLength(const QString &what, double value, double limit, Units units);
[[nodiscard]] Result<void> validateLinuxCncExtra(const QString &extra);

// Numbers for people: 3 decimals in mm, 4 in inches, more when the value has more, so nothing is hidden.
[[nodiscard]] QString displayNumber(double value, Units units);

// Numbers as Toffee writes them in files: the shortest text that reads back as the same double, never
// exponent.
[[nodiscard]] QString formatNumber(double value);

} // namespace Toffee
