// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "model/gcode/gcodewords.h"

namespace Toffee {

// The M-codes the Carvera's firmware still runs while it is halted (docs/CARVERA.md); anything else gets
// "error:Alarm lock" until $X. The emulator answers by it and the console warns by it.
inline constexpr std::array<double, 15> kCarveraRunsWhileHalted { 2, 5, 9, 30, 80, 81, 105, 106, 107, 114,
    115, 119, 503, 911, 999 };

[[nodiscard]] inline bool carveraRunsWhileHalted(const GCodeWord &word)
{
    return word.letter == 'M' && !word.bare
        && std::any_of(kCarveraRunsWhileHalted.cbegin(), kCarveraRunsWhileHalted.cend(),
            [&](double m) { return std::fabs(word.value - m) < 1e-6; });
}

// Whether a halted Carvera runs this block: an empty one, or one that starts with such an M-code (the
// firmware looks at the first word only).
[[nodiscard]] inline bool carveraRunsWhileHalted(const GCodeBlock &block)
{
    return block.isEmpty() || carveraRunsWhileHalted(block.words.front());
}

// The tools a C1's changer takes from its rack and puts back by itself: T0 (the wireless probe) to T6
// (ATCHandler: lowest_tool_number to tool_number). A change to or from any other tool is made by hand: the
// machine waits in state Tool for the operator's button. Custom slots (custom_tool_slots.txt) are not known
// here, so a tool in one counts as changed by hand: the cautious side.
inline constexpr int kCarveraLowestRackTool = 0;
inline constexpr int kCarveraHighestRackTool = 6;

[[nodiscard]] inline bool carveraChangesByItself(int tool)
{
    return tool >= kCarveraLowestRackTool && tool <= kCarveraHighestRackTool;
}

} // namespace Toffee
