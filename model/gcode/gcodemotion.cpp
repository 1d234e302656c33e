// SPDX-License-Identifier: GPL-3.0-or-later
// The interpreter's tool life: motion modes, feed, which tool is loaded, and the length and time of each move
// (arcs as arcs), for the cutting time per tool of a program.
#include "model/gcode/gcodeinterpreter.h"

#include <cmath>
#include <numbers>

#include "model/gcode/gcodeinterpreter_p.h"

namespace Toffee {

namespace {

// The two axes of the arc plane and the helix axis: G17 X Y (Z), G18 Z X (Y), G19 Y Z (X); and the centre
// offset letters of the two plane axes.
struct ArcPlane
{
    size_t first;
    size_t second;
    size_t helix;
    char firstOffset;
    char secondOffset;
};

ArcPlane planeOf(int lengthAxis)
{
    if (lengthAxis == 1)
        return { 2, 0, 1, 'K', 'I' };
    if (lengthAxis == 0)
        return { 1, 2, 0, 'J', 'K' };
    return { 0, 1, 2, 'I', 'J' };
}

} // namespace

Result<void> GCodeInterpreter::modalWords(const Words &w, int line)
{
    if (w.word('F')) {
        if (w.get('F') < 0)
            return error(line, tr("F%1 is not a feed rate.").arg(formatNumber(w.get('F'))));
        m_feed = w.get('F');
    }
    if (w.word('T') && !w.isBare('T')) {
        // Only the Carvera has a tool -1, its empty spindle.
        const int lowest = m_dialect == Dialect::Carvera ? Limits::kEmptySpindle : Limits::kMinToolNumber;
        const auto tool = wholeWord(w, 'T', lowest, Limits::kMaxToolNumber, line);
        if (!tool)
            return tool.error();
        m_selectedTool = tool.value();
    }
    if (w.gCount > 0 && (w.hasG(20) || w.hasG(21))) {
        m_units = w.hasG(20) ? Units::Inch : Units::Millimetre;
        m_effect.unitsWord = true;
    }
    if (w.word('S') && w.get('S') >= 0)
        m_spindleSpeed = w.get('S');
    if (w.mCount > 0) { // most blocks have no M code: nothing below to look at
        if (w.hasM(98) || w.hasM(99))
            return error(line,
                tr("M%1 calls or ends a subprogram, which the check does not follow: what it cuts is "
                   "not checked.")
                    .arg(w.hasM(98) ? 98 : 99));
        if (w.hasM(3) || w.hasM(4))
            m_spindleOn = true;
        if (w.hasM(5) || w.hasM(6) || w.hasM(2) || w.hasM(30))
            m_spindleOn = false; // a tool change stops the spindle, and so does the end
        if (w.hasM(6)) {
            m_cuttingTool = m_selectedTool;
            m_effect.toolChange = true;
        }
    }
    if (w.hasM(61) && w.word('Q')) {
        const auto tool = wholeWord(w, 'Q', Limits::kMinToolNumber, Limits::kMaxToolNumber, line);
        if (!tool)
            return tool.error();
        m_cuttingTool = tool.value();
        m_effect.toolChange = true;
    }
    return {};
}

namespace {

// Whether the arc from angle `start` over `sweep` (negative: clockwise) passes through angle `target`.
bool sweepsThrough(double start, double sweep, double target)
{
    const double twoPi = 2.0 * std::numbers::pi;
    double delta = std::fmod(sweep > 0 ? target - start : start - target, twoPi);
    if (delta < 0)
        delta += twoPi;
    return delta <= std::fabs(sweep);
}

} // namespace

Result<GCodeInterpreter::MoveGeometry> GCodeInterpreter::measureMove(
    const Words &w, const Position &programStart, int line) const
{
    MoveGeometry out;
    // Where the move ends, or lower on its way: its start is the last move's end, already counted.
    out.lowestZ = m_program[2];
    double straight = 0.0;
    for (size_t i = 0; i < 3; ++i)
        straight += (m_program[i] - programStart[i]) * (m_program[i] - programStart[i]);
    out.length = std::sqrt(straight);
    if (m_motionMode != 2 && m_motionMode != 3)
        return out;
    const ArcPlane p = planeOf(m_lengthAxis);
    const double sx = programStart[p.first];
    const double sy = programStart[p.second];
    const double ex = m_program[p.first];
    const double ey = m_program[p.second];
    double cx = 0.0;
    double cy = 0.0;
    if (w.word('R')) {
        // The centre on the chord's perpendicular bisector; a negative R takes the arc over 180°.
        const double r = w.get('R');
        const double dx = ex - sx;
        const double dy = ey - sy;
        const double chord = std::hypot(dx, dy);
        if (chord == 0.0 || chord > 2.0 * std::fabs(r) + 1e-9)
            return error(line, tr("the arc's R%1 cannot reach its end point.").arg(formatNumber(r)));
        const double h = std::sqrt(std::max(0.0, r * r - chord * chord / 4.0));
        const double side = (m_motionMode == 2) == (r > 0) ? -1.0 : 1.0;
        cx = sx + dx / 2.0 - side * h * dy / chord;
        cy = sy + dy / 2.0 + side * h * dx / chord;
    } else if (w.word(p.firstOffset) || w.word(p.secondOffset)) {
        // G91.1 (the default): the centre from the start; G90.1: where it is.
        const double baseX = m_arcCentresAbsolute ? 0.0 : sx;
        const double baseY = m_arcCentresAbsolute ? 0.0 : sy;
        cx = baseX + (w.word(p.firstOffset) ? w.get(p.firstOffset) : (m_arcCentresAbsolute ? sx : 0.0));
        cy = baseY + (w.word(p.secondOffset) ? w.get(p.secondOffset) : (m_arcCentresAbsolute ? sy : 0.0));
    } else {
        return error(line,
            tr("G%1 needs the arc's centre (%2 %3) or its radius (R).")
                .arg(m_motionMode)
                .arg(QChar::fromLatin1(p.firstOffset), QChar::fromLatin1(p.secondOffset)));
    }
    const double radius = std::hypot(sx - cx, sy - cy);
    const double startAngle = std::atan2(sy - cy, sx - cx);
    double sweep = std::atan2(ey - cy, ex - cx) - startAngle;
    // G2 turns clockwise (negative), G3 counter-clockwise; the same start and end is a whole circle.
    if (m_motionMode == 2) {
        while (sweep >= -1e-12)
            sweep -= 2.0 * std::numbers::pi;
    } else {
        while (sweep <= 1e-12)
            sweep += 2.0 * std::numbers::pi;
    }
    const double helix = m_program[p.helix] - programStart[p.helix];
    out.length = std::hypot(radius * std::fabs(sweep), helix);
    // Z in the arc's plane (G18: the first axis, G19: the second) is lowest at one angle of the circle.
    if (p.first == 2 && sweepsThrough(startAngle, sweep, std::numbers::pi))
        out.lowestZ = std::min(out.lowestZ, cx - radius);
    else if (p.second == 2 && sweepsThrough(startAngle, sweep, -std::numbers::pi / 2.0))
        out.lowestZ = std::min(out.lowestZ, cy - radius);
    return out;
}

void GCodeInterpreter::returnHome(const Words &w, int line)
{
    const Position start = m_machine;
    Position via = m_machine;
    double path = 0.0;
    for (size_t i = 0; i < 3; ++i) {
        const char a = "XYZ"[i];
        if (!w.word(a))
            continue;
        const double program = m_absolute ? w.get(a) : m_program[i] + w.get(a);
        via[i] = program + m_g54[i] + (i == size_t(m_lengthAxis) ? m_appliedLength : 0.0);
        m_machine[i] = 0.0;
        m_program[i] = -m_g54[i] - (i == size_t(m_lengthAxis) ? m_appliedLength : 0.0);
    }
    double first = 0.0;
    for (size_t i = 0; i < 3; ++i) {
        first += (via[i] - start[i]) * (via[i] - start[i]);
        path += (m_machine[i] - via[i]) * (m_machine[i] - via[i]);
    }
    m_rapid += std::sqrt(first) + std::sqrt(path);
    m_effect.motion = BlockEffect::Motion::Rapid;
    m_effect.machineCoordinates = true;
    m_effect.lengthAxisWord = w.word("XYZ"[m_lengthAxis]);
    m_effect.lowestZ = m_program[2];
    recordStraight(line, start);
}

// A feed move's time: F in units a minute (G94), a minute over F for the whole move (G93, inverse time), or
// units a revolution at S revolutions a minute (G95). Nothing when F (or S) is not known.
double GCodeInterpreter::feedSeconds(double length) const
{
    if (m_feed <= 0.0)
        return 0.0;
    if (m_feedMode == 93)
        return 60.0 / m_feed;
    if (m_feedMode == 95)
        return m_spindleSpeed > 0.0 ? length / (m_feed * m_spindleSpeed) * 60.0 : 0.0;
    return length / m_feed * 60.0;
}

void GCodeInterpreter::account(double length)
{
    m_effect.motion = m_motionMode == 0 ? BlockEffect::Motion::Rapid : BlockEffect::Motion::Feed;
    tally(length, m_motionMode != 0);
}

void GCodeInterpreter::tally(double length, bool feed)
{
    if (!feed) {
        m_rapid += length;
        return;
    }
    const double seconds = feedSeconds(length);
    m_effect.feedPathMm += length;
    m_effect.cuttingSeconds += seconds;
    if (!m_keepUsage)
        return;
    ToolUsage &usage = m_usage[activeTool()];
    usage.feedPathMm += length;
    usage.cuttingSeconds += seconds;
}

} // namespace Toffee
