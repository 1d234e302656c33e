// SPDX-License-Identifier: GPL-3.0-or-later
// The interpreter's length offsets (G43/G44/G49 and their kin) and offset tables (G10).
#include "model/gcode/gcodeinterpreter.h"

#include <cmath>

#include "model/gcode/gcodeinterpreter_p.h"
#include "model/textparsing.h"

using namespace Qt::StringLiterals;

namespace Toffee {

Result<void> GCodeInterpreter::lengthWords(const Words &w, int line)
{
    const bool fanuc = m_dialect == Dialect::Fanuc;
    const bool ab = m_dialect == Dialect::AllenBradley9;
    const bool fagor = m_dialect == Dialect::Fagor8055M;
    const bool carvera = m_dialect == Dialect::Carvera;

    if (carvera)
        return carveraLength(w, line);
    if (fagor) {
        if (w.word('T') && !w.word('D')) {
            const auto tool = wholeWord(w, 'T', Limits::kMinToolNumber, Limits::kMaxToolNumber, line);
            if (!tool)
                return tool.error();
            m_lengthValue = offsetValue(tool.value()); // the offset linked to the tool
        }
        if (w.word('D')) {
            const auto d = wholeWord(w, 'D', 0, kMaxOffsetNumber, line);
            if (!d)
                return d.error();
            m_lengthValue = offsetValue(d.value());
        }
        if (w.word('T') || w.word('D'))
            m_lengthRegister = w.word('D') ? int(w.get('D')) : int(w.get('T'));
        if (w.hasG(43))
            m_lengthMode = LengthMode::Plus; // the value carries its own sign
        if (w.hasG(44) || w.hasG(74))
            m_lengthMode = LengthMode::Off;
        return {};
    }
    // FANUC and Allen-Bradley: H calls (and latches) an offset; G43 / G44 set the direction; G49 cancels.
    if (w.word('H')) {
        const double h = w.get('H');
        if (h != std::floor(h) || h < 0 || h > kMaxOffsetNumber)
            return error(line,
                fanuc ? tr("PS0030 ILLEGAL OFFSET NUMBER: H%1; offsets go from 0 to %2.")
                            .arg(formatNumber(h))
                            .arg(kMaxOffsetNumber)
                      : tr("H%1 is not an offset number (0 to %2).")
                            .arg(formatNumber(h))
                            .arg(kMaxOffsetNumber));
        m_hNumber = int(h);
        m_lengthRegister = m_hNumber;
        m_lengthValue = m_hNumber == 0 ? 0.0 : offsetValue(m_hNumber);
        if (fanuc && m_hNumber == 0)
            m_lengthMode = LengthMode::Off; // FANUC: H0 cancels; AB keeps the mode with a value of 0
    }
    if (w.hasG(43))
        m_lengthMode = LengthMode::Plus;
    if (w.hasG(44))
        m_lengthMode = LengthMode::Minus;
    if (w.hasG(49))
        m_lengthMode = LengthMode::Off; // AB keeps H; FANUC's next G43 needs an H anyway
    Q_UNUSED(ab);
    return {};
}

// The Carvera has one TLO, always applied: set by M493.3 Z or M6 … H, and measured on the setter by M6
// (without H), M491 and M491.1. A measurement gives the tool its own length: the table's, when the table has
// the tool.
Result<void> GCodeInterpreter::carveraLength(const Words &w, int line)
{
    if (w.hasG(43) || w.hasG(44) || w.hasG(49))
        return error(line, tr("the Carvera has no G43/G44/G49: its TLO always applies."));
    if (w.hasM(493.3) && w.word('Z'))
        m_lengthValue = w.get('Z');
    if (w.hasM(6) && w.word('H'))
        m_lengthValue = w.get('H');
    m_effect.setsTlo = (w.hasM(493.3) && w.word('Z')) || (w.hasM(6) && w.word('H'));
    const bool measures = (w.hasM(6) && !w.word('H')) || w.hasM(491) || w.hasM(491.1);
    if (measures) {
        m_effect.probe = true;
        if (const auto it = m_offsets.find(m_cuttingTool); it != m_offsets.end())
            m_lengthValue = it->second.length();
    }
    m_lengthRegister = -1;
    m_lengthMode = LengthMode::Plus;
    return {};
}

Result<void> GCodeInterpreter::linuxCncLength(const Words &w, int line)
{
    const bool change = w.hasG(43) || w.hasG(43.1) || w.hasG(43.2) || w.hasG(49);
    if (change && m_radiusComp)
        return error(line, tr("Cannot change tool offset with cutter radius compensation on"));
    if (w.word('T')) {
        const auto tool = wholeWord(w, 'T', Limits::kMinToolNumber, Limits::kMaxToolNumber, line);
        if (!tool)
            return tool.error();
        m_preparedTool = tool.value();
    }
    if (w.hasM(6))
        m_loadedTool = m_preparedTool; // the offset does not change: issue G43 after
    if (w.hasM(61)) {
        if (!w.word('Q'))
            return error(line, tr("M61 needs Q, the tool number."));
        const auto tool = wholeWord(w, 'Q', Limits::kMinToolNumber, Limits::kMaxToolNumber, line);
        if (!tool)
            return tool.error();
        m_loadedTool = tool.value();
    }
    // The length of the tool the H word names, or else of the loaded tool.
    auto toolLength = [this, &w, line]() -> Result<double> {
        int tool = m_loadedTool;
        if (w.word('H')) {
            const auto h = wholeWord(w, 'H', Limits::kMinToolNumber, Limits::kMaxToolNumber, line);
            if (!h)
                return h.error();
            tool = h.value();
        }
        m_lengthRegister = tool;
        if (tool == 0)
            return 0.0;
        const auto it = m_offsets.find(tool);
        if (it == m_offsets.end())
            return error(line, tr("tool %1 is not in the tool table.").arg(tool));
        return it->second.length();
    };
    if (w.hasG(43)) {
        auto v = toolLength();
        if (!v)
            return v.error();
        m_lengthValue = v.value();
        m_lengthMode = LengthMode::Plus;
    } else if (w.hasG(43.1)) {
        if (!w.word('Z'))
            return error(line, tr("G43.1 needs Z, the offset."));
        m_lengthValue = w.get('Z');
        m_lengthRegister = -1;
        m_lengthMode = LengthMode::Plus;
    } else if (w.hasG(43.2)) {
        if (!w.word('H'))
            return error(line, tr("G43.2 needs H, the tool whose offset it adds."));
        auto v = toolLength();
        if (!v)
            return v.error();
        m_lengthValue += v.value();
        m_lengthMode = LengthMode::Plus;
    } else if (w.hasG(49)) {
        m_lengthValue = 0.0;
        m_lengthMode = LengthMode::Off;
    }
    return {};
}

Result<void> GCodeInterpreter::g10(const Words &w, int line)
{
    const bool fanuc = m_dialect == Dialect::Fanuc;
    if (!w.word('L'))
        return error(line,
            fanuc ? tr("PS0031 ILLEGAL P COMMAND IN G10: G10 needs an L word.") : tr("G10 needs an L word."));
    const double l = w.get('L');
    if (same(l, 2) || same(l, 20))
        return g10WorkOffset(w, l, line);
    if (usesToolTableWords(m_dialect))
        return g10ToolTable(w, l, line);
    return g10Register(w, l, line);
}

// G10 L2 P X Y Z, or L20: a work offset itself (P1 G54 … P6 G59; P0 the one in use, as LinuxCNC has it), or
// made so that the current position is the given one.
Result<void> GCodeInterpreter::g10WorkOffset(const Words &w, double l, int line)
{
    const double p = w.word('P') ? w.get('P') : 1.0;
    const int highest = usesToolTableWords(m_dialect) ? 9 : 6; // LinuxCNC adds G59.1 to G59.3
    if (p != std::floor(p) || p < 0 || p > highest)
        return error(line,
            tr("G10 L%1 P%2: the work offsets are G54 to G59 (P1 to P6; LinuxCNC's G59.1 to G59.3 are P7 to "
               "P9).")
                .arg(formatNumber(l), formatNumber(p)));
    const int index = p == 0 ? m_workOffset : int(p) - 1;
    Position &offset = index == m_workOffset ? m_g54 : m_workOffsets[size_t(index)];
    for (size_t i = 0; i < 3; ++i) {
        const char a = "XYZ"[i];
        if (w.word(a))
            // L20: the current position becomes `value`, tool length offset included.
            offset[i] = same(l, 2)
                ? w.get(a)
                : m_machine[i] - w.get(a) - (i == size_t(m_lengthAxis) ? m_appliedLength : 0.0);
    }
    return {};
}

// LinuxCNC's G10 L1 P<tool> Z R: the tool table, not the active offset.
Result<void> GCodeInterpreter::g10ToolTable(const Words &w, double l, int line)
{
    if (!same(l, 1))
        return error(line,
            tr("G10 L%1 is not simulated for LinuxCNC; G10 L1 writes the tool table.").arg(formatNumber(l)));
    if (!w.word('P') || w.get('P') < 1 || w.get('P') > Limits::kMaxToolNumber
        || w.get('P') != std::floor(w.get('P')))
        return error(line, tr("G10 L1 needs P, a tool number in the tool table."));
    const auto it = m_offsets.find(int(w.get('P')));
    if (it == m_offsets.end())
        return error(line, tr("G10 L1: tool %1 is not in the tool table.").arg(formatNumber(w.get('P'))));
    if (w.word('Z'))
        it->second.lengthGeometry = w.get('Z'); // the table only: the active offset changes at the next G43
    if (w.word('R'))
        it->second.radiusGeometry = w.get('R');
    return {};
}

// FANUC's and AB's G10 L10-L13 P<register> R: a register's length or radius, geometry or wear.
Result<void> GCodeInterpreter::g10Register(const Words &w, double l, int line)
{
    const bool fanuc = m_dialect == Dialect::Fanuc;
    if (m_dialect != Dialect::Fanuc && m_dialect != Dialect::AllenBradley9)
        return error(line, tr("this controller's offset table is not programmed with G10."));
    if (m_dialect == Dialect::AllenBradley9 && m_radiusComp)
        return error(line,
            tr("G10 may not be programmed while cutter compensation (G41/G42) is active; nothing was "
               "written."));
    if (!same(l, 10) && !same(l, 11) && !same(l, 12) && !same(l, 13))
        return error(line,
            fanuc ? tr("PS0031 ILLEGAL P COMMAND IN G10: L%1 is not L10 to L13.").arg(formatNumber(l))
                  : tr("G10 L%1 is not L10 to L13.").arg(formatNumber(l)));
    const double p = w.word('P') ? w.get('P') : -1;
    if (p < 1 || p > kMaxOffsetNumber || p != std::floor(p))
        return error(line,
            fanuc ? tr("PS0031 ILLEGAL P COMMAND IN G10: P must be an offset number from 1 to %1.")
                        .arg(kMaxOffsetNumber)
                  : tr("G10 needs P, an offset number from 1 to %1.").arg(kMaxOffsetNumber));
    // AB: R may be replaced by the tool length axis' name.
    const char lengthAxis = "XYZ"[m_lengthAxis];
    double value = 0.0;
    if (w.word('R'))
        value = w.get('R');
    else if (m_dialect == Dialect::AllenBradley9 && (same(l, 10) || same(l, 11)) && w.word(lengthAxis)
        && !w.isBare(lengthAxis))
        value = w.get(lengthAxis);
    else
        return error(line,
            fanuc ? tr("PS0031 ILLEGAL P COMMAND IN G10: the value (R) is missing.")
                  : tr("G10 needs R, the value."));
    const bool wear = same(l, 11) || same(l, 13);
    // Worked on a copy: a refused value must not leave behind a register it created.
    const auto stored = m_offsets.find(int(p));
    OffsetEntry entry = stored == m_offsets.end() ? OffsetEntry {} : stored->second;
    double &field = same(l, 10) ? entry.lengthGeometry
        : same(l, 11)           ? entry.lengthWear
        : same(l, 12)           ? entry.radiusGeometry
                                : entry.radiusWear;
    const double result = m_absolute ? value : field + value; // G90 replaces, G91 adds
    const double limit = wear ? kMaxWear : kMaxGeometry;
    if (!std::isfinite(result) || std::fabs(result) > limit + 1e-9)
        return error(line,
            fanuc ? tr("PS0032 ILLEGAL OFFSET VALUE IN G10: %1 is beyond ±%2.")
                        .arg(formatNumber(result))
                        .arg(limit)
                  : tr("G10: %1 is beyond ±%2.").arg(formatNumber(result), formatNumber(limit)));
    field = result;
    m_offsets[int(p)] = entry;
    return {};
}

} // namespace Toffee
