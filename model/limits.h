// SPDX-License-Identifier: GPL-3.0-or-later
// Every range and constant a rule of Toffee's rests on, once. The rest of the code names these; a literal
// 999999 or 999.999 anywhere else is a second copy of a rule.
#pragma once

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

// What any machine's reply may hold: 100 m is beyond every machine's travel, so a larger number is garbage.
inline constexpr double kMaxMachineMillimetres = 100000.0;

} // namespace Toffee
