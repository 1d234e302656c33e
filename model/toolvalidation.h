// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "model/limits.h"
#include "model/result.h"
#include "model/tool.h"
#include "model/units.h"

namespace Toffee {

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

// The one range of a TLO, in millimetres as a machine has it: finite and within ±Limits::kMaxMachineOffsetMm.
// Every path checks it before a TLO is written anywhere: a controller (MachineController::validateOffset,
// GrblHalController::writeOffset), the table (validateTool), the history (Library::append), what an operation
// records (MachineController::recording); and the wear trend reads no other.
[[nodiscard]] bool isMachineTlo(double millimetres);

} // namespace Toffee
