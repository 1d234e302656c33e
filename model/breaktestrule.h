// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QString>

namespace Toffee {

// Which tools the Carvera's break test (M491.1) cannot test, as its firmware decides (ATCHandler.cpp, seen on
// the firmware): T0 and every tool from T9 up are taken for its wireless probe (it measures, then halts).
// Prepare and Check Rack skip such a tool alike and say why in the same words (a check that skipped one is
// incomplete: toffee-cli exits 1); the Break Test panel refuses it (MachineSession::breakTest).
enum class BreakTestExclusion { WirelessProbe };

// Why `tool` cannot be break-tested; nothing when it can.
[[nodiscard]] std::optional<BreakTestExclusion> breakTestExclusion(int tool);
// In words, for people (translated), or in English for a program's comment.
[[nodiscard]] QString breakTestExclusionText(BreakTestExclusion why, int tool, bool translated = true);

// The TLO a break test compares with. The firmware takes a TLO of 0.000 mm (the reference tool's) for none
// ("No previous TLO included": it would measure without comparing), but prints and reads the TLO in force to
// 0.001 mm: a stored 0.000 goes in as 0.001 mm first, and is compared, 1 µm off (the smallest tolerance the
// firmware takes is 20 µm). Every other TLO is itself. The Break Test panel, Check Rack and Prepare alike.
inline constexpr double kZeroTloCompared = 0.001;
[[nodiscard]] double comparableTlo(double storedTlo);
[[nodiscard]] bool isZeroTlo(double tlo);

} // namespace Toffee
