// SPDX-License-Identifier: GPL-3.0-or-later
// The interpreter's work offsets (G54 to G59) and canned drilling and boring cycles (G73, G81 to G89): what a
// CAM post writes for holes, so that a job check sees the depth of every one.
#include "model/gcode/gcodeinterpreter.h"

#include <cmath>

#include "model/gcode/gcodeinterpreter_p.h"

namespace Toffee {

void GCodeInterpreter::selectWorkOffset(int index)
{
    m_workOffsets[size_t(m_workOffset)] = m_g54;
    m_workOffset = index;
    m_g54 = m_workOffsets[size_t(index)];
    setMachinePosition(m_machine);
}

void GCodeInterpreter::startCycle(int code)
{
    if (m_cycle == 0)
        m_cycleInitialZ = m_program[2]; // the level a G98 cycle returns to
    m_cycle = code;
    m_cycleCalled = true;
}

// One hole: to X Y at the current level, down to R at rapid, to Z at feed, and back up to R (G99) or the
// initial level (G98), at feed for the boring cycles that feed out (G85, G89) and at rapid for the rest. The
// pecks of G73 and G83 are taken as one plunge: the depth is the same, the time a little short.
Result<void> GCodeInterpreter::cycle(const Words &w, int line)
{
    if (m_lengthAxis != 2)
        return error(line, tr("canned cycles are simulated in the XY plane (G17) only."));
    if (w.word('R'))
        m_cycleR = m_absolute ? w.get('R') : m_cycleInitialZ + w.get('R');
    const double r = m_cycleR.value_or(m_cycleInitialZ);
    if (w.word('Z'))
        m_cycleZ = m_absolute ? w.get('Z') : r + w.get('Z');
    if (!m_cycleZ)
        return error(line, tr("G%1 needs Z, the bottom of the hole.").arg(m_cycle));
    if (w.word('F') && w.get('F') > 0)
        m_feed = w.get('F');
    Position target = m_program;
    for (size_t i = 0; i < 2; ++i) {
        const char a = "XY"[i];
        if (w.word(a))
            target[i] = m_absolute ? w.get(a) : m_program[i] + w.get(a);
    }
    m_appliedLength = lengthContribution(); // the cycle moves Z: the length offset rides on it
    cycleMove(target, false, line);
    target[2] = r;
    cycleMove(target, false, line);
    target[2] = *m_cycleZ;
    cycleMove(target, true, line);
    target[2] = m_cycleToR ? r : std::max(m_cycleInitialZ, r);
    cycleMove(target, m_cycle == 85 || m_cycle == 89, line);
    m_effect.motion = BlockEffect::Motion::Feed;
    m_effect.lengthAxisWord = true;
    m_effect.lowestZ = *m_cycleZ;
    return {};
}

void GCodeInterpreter::cycleMove(const Position &target, bool feed, int line)
{
    const Position start = m_machine;
    double length = 0.0;
    for (size_t i = 0; i < 3; ++i) {
        length += (target[i] - m_program[i]) * (target[i] - m_program[i]);
        m_program[i] = target[i];
        m_machine[i] = target[i] + m_g54[i] + (i == 2 ? m_appliedLength : 0.0);
    }
    length = std::sqrt(length);
    if (length == 0.0)
        return;
    tally(length, feed);
    recordStraight(line, start);
}

} // namespace Toffee
