// SPDX-License-Identifier: GPL-3.0-or-later
// Every range and constant a rule of Toffee's rests on, once. The rest of the code names these; a literal
// 999999 or 999.999 anywhere else is a second copy of a rule.
#pragma once

namespace Toffee {

// The ranges a real controller enforces (FANUC IS-B, see docs/DIALECTS.md); inch limits are the same digits
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
constexpr int kEmptySpindle = -1; // "T-1": the Carvera's empty spindle, a tool number only the machine uses
constexpr int kMaxOffsetNumber = 999; // FANUC's offset registers go up to 999 (docs/DIALECTS.md)
// An offset a controller takes: the geometry limit (the Carvera's M493.3 is held to it as well).
constexpr double kMaxMachineOffsetMm = kMaxGeometryMm;
constexpr double kMinBreakTolerance = 0.02; // the Carvera halts below this (docs/CARVERA.md)
constexpr double kDefaultBreakTolerance = 0.1; // M491.1 without H
// A G-code word no controller reads beyond (the interpreter refuses larger ones).
constexpr double kMaxWordValue = 99999999.0;
} // namespace Limits

// What any machine's reply may hold: 100 m is beyond every machine's travel, so a larger number is garbage.
inline constexpr double kMaxMachineMillimetres = 100000.0;

} // namespace Toffee
