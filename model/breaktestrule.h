// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QString>

namespace Toffee {

// Which tools the Carvera's break test (M491.1) cannot test, as its firmware decides (ATCHandler.cpp, seen on
// the firmware): T0 and every tool from T9 up are taken for its wireless probe (it measures, then halts), and
// a stored TLO of 0.000 mm, the reference tool's, is "No previous TLO included": it measures without
// comparing. Prepare and Check Rack skip such a tool alike and say why in the same words; the Break Test
// panel refuses it (MachineSession::breakTest).
enum class BreakTestExclusion { WirelessProbe, NoPreviousTlo };

// Why `tool`, holding `storedTlo`, cannot be break-tested; nothing when it can.
[[nodiscard]] std::optional<BreakTestExclusion> breakTestExclusion(int tool, std::optional<double> storedTlo);
// In words, for people (translated), or in English for a program's comment.
[[nodiscard]] QString breakTestExclusionText(BreakTestExclusion why, int tool, bool translated = true);

} // namespace Toffee
