// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/gcode/gcodeinterpreter.h"

#include <cmath>

#include <QCoreApplication>

#include "model/gcode/gcodeinterpreter_p.h"
#include "model/gcode/gcodewords.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/tooltable.h"
#include "model/toolvalidation.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

OffsetTable offsetTableFor(const ToolTable &table, Dialect dialect)
{
    OffsetTable offsets;
    for (const Tool &t : table.tools()) {
        if (dialect != Dialect::Carvera)
            offsets[t.number] = { t.lengthGeometry, t.lengthWear, t.radiusGeometry, t.radiusWear };
        else if (const auto stored = table.storedTlo(t.number)) // the Carvera's TLOs: millimetres
            offsets[t.number] = { stored->tlo, 0.0, t.radiusGeometry, t.radiusWear };
    }
    return offsets;
}

GCodeInterpreter::GCodeInterpreter(Dialect dialect, OffsetTable offsets, int samples)
    : m_dialect(dialect)
    , m_offsets(std::move(offsets))
    , m_samples(samples)
{
    if (dialect == Dialect::Aerotech) {
        m_compAxes = { 0, 1 };
        m_compOffsets = { 0.0, 0.0 };
    }
}

// G-codes that change nothing the simulation follows: a dwell, exact stop, path control, spindle speed in
// revolutions (the default), cancelling polar coordinates and rotation.
bool GCodeInterpreter::isPassive(double g)
{
    return same(g, 4) || same(g, 9) || same(g, 61) || same(g, 61.1) || same(g, 64) || same(g, 97)
        || same(g, 15) || same(g, 69);
}

// Drilling and boring: G73 and G83 peck, G81 drills, G82 dwells at the bottom, G85 / G86 / G89 bore.
bool GCodeInterpreter::isCycle(double g)
{
    return same(g, 73) || same(g, 81) || same(g, 82) || same(g, 83) || same(g, 85) || same(g, 86)
        || same(g, 89);
}

Error GCodeInterpreter::error(int line, const QString &message) const
{
    return Error { message, line };
}

Result<int> GCodeInterpreter::wholeWord(const Words &w, char letter, int low, int high, int line) const
{
    const double v = w.get(letter);
    if (v != std::floor(v) || v < low || v > high)
        return error(line,
            tr("%1%2 must be a whole number from %3 to %4.")
                .arg(QChar::fromLatin1(letter))
                .arg(formatNumber(v))
                .arg(low)
                .arg(high));
    return int(v);
}

double GCodeInterpreter::offsetValue(int number) const
{
    const auto it = m_offsets.find(number);
    return it == m_offsets.end() ? 0.0 : it->second.length();
}

void GCodeInterpreter::setMachinePosition(const Position &position)
{
    m_machine = position;
    for (size_t i = 0; i < 3; ++i)
        m_program[i] = position[i] - m_g54[i] - (i == size_t(m_lengthAxis) ? m_appliedLength : 0.0);
}

void GCodeInterpreter::setLengthOffset(double offset)
{
    m_lengthMode = LengthMode::Plus;
    m_lengthValue = offset;
    m_appliedLength = offset;
    setMachinePosition(m_machine);
}

Result<void> GCodeInterpreter::run(QByteArrayView program)
{
    qsizetype start = 0;
    int line = 0;
    while (start < program.size() && !m_ended) {
        qsizetype end = program.indexOf('\n', start);
        if (end < 0)
            end = program.size();
        ++line;
        if (auto r = runLine(program.sliced(start, end - start), line); !r)
            return r;
        start = end + 1;
    }
    return {};
}

Result<void> GCodeInterpreter::runLine(QByteArrayView text, int line)
{
    m_effect = {};
    m_cycleCalled = false;
    Words w;
    // Block delete ("/" first): the switch is off, so the block runs, as on a controller at its default. The
    // Carvera has none.
    if (m_dialect != Dialect::Carvera) {
        qsizetype at = 0;
        while (at < text.size() && (text.at(at) == ' ' || text.at(at) == '\t'))
            ++at;
        if (at < text.size() && text.at(at) == '/' && (at + 1 == text.size() || text.at(at + 1) != '/'))
            text = text.sliced(
                at + 1 + (at + 1 < text.size() && text.at(at + 1) >= '1' && text.at(at + 1) <= '9'));
    }
    GCodeLexer lexer(text);
    for (;;) {
        switch (lexer.next()) {
        case GCodeLexer::Token::Word:
            if (QString problem; !w.add(lexer.word(), problem))
                return error(line, problem);
            continue;
        case GCodeLexer::Token::Call:
            if (m_dialect != Dialect::Aerotech)
                return error(line,
                    tr("\"%1\" is not G-code this controller reads.").arg(QString::fromUtf8(lexer.call())));
            ++m_blocks;
            return callFunction(lexer.call(), line);
        case GCodeLexer::Token::Error:
            return error(line, lexer.error());
        case GCodeLexer::Token::End:
            break;
        }
        break;
    }
    if (w.gCount == 0 && w.mCount == 0
        && std::none_of(w.has.cbegin(), w.has.cend(), [](bool b) { return b; }))
        return {};
    ++m_blocks;
    return execute(w, line);
}

// The block's G-codes that set a mode; whether one of them is a motion (G0-G3) in `motion`.
Result<void> GCodeInterpreter::modalGCodes(const Words &w, int line, bool &motion)
{
    for (int i = 0; i < w.gCount; ++i) {
        const double g = w.g[size_t(i)];
        if (same(g, 0) || same(g, 1) || same(g, 2) || same(g, 3)) {
            motion = true;
            m_motionMode = int(g);
            m_cycle = 0; // a motion ends a canned cycle
        } else if (same(g, 90))
            m_absolute = true;
        else if (same(g, 91))
            m_absolute = false;
        else if (same(g, 17))
            m_lengthAxis = 2;
        else if (same(g, 18))
            m_lengthAxis = 1;
        else if (same(g, 19))
            m_lengthAxis = 0;
        else if (same(g, 40))
            m_radiusComp = false;
        else if (same(g, 41) || same(g, 42))
            m_radiusComp = true;
        else if (same(g, 80))
            m_cycle = 0;
        else if (same(g, 98) || same(g, 99))
            m_cycleToR = same(g, 99);
        else if (isCycle(g) && m_dialect != Dialect::Aerotech)
            startCycle(int(g));
        else if (g >= 54 - 1e-6 && g <= 59 + 1e-6 && same(g, std::round(g)))
            selectWorkOffset(int(std::round(g)) - 54);
        else if (same(g, 59.1) || same(g, 59.2) || same(g, 59.3))
            selectWorkOffset(6 + int(std::round((g - 59.0) * 10.0)) - 1);
        else if (same(g, 90.1) || same(g, 91.1))
            m_arcCentresAbsolute = same(g, 90.1);
        else if (same(g, 93) || same(g, 94) || same(g, 95))
            m_feedMode = int(std::round(g));
        else if (same(g, 20) || same(g, 21) || same(g, 10) || same(g, 43) || same(g, 44) || same(g, 49)
            || same(g, 43.1) || same(g, 43.2) || same(g, 74) || same(g, 143) || same(g, 144) || same(g, 149)
            || same(g, 53) || same(g, 28) || same(g, 30) || isPassive(g))
            continue; // handled below, or changes nothing the simulation follows
        else
            return error(line, tr("G%1 is not simulated.").arg(formatNumber(g)));
    }
    return {};
}

Result<void> GCodeInterpreter::execute(const Words &w, int line)
{
    bool motion = false;
    if (auto r = modalGCodes(w, line, motion); !r)
        return r;
    if (w.hasG(10))
        return g10(w, line);
    if (auto r = modalWords(w, line); !r)
        return r;
    // FAGOR latches the offset of the tool a T selects (or of its D).
    if ((w.gCount > 0 && (w.hasG(43) || w.hasG(44) || w.hasG(49) || w.hasG(43.1) || w.hasG(43.2)))
        || w.word('H') || (m_dialect == Dialect::Fagor8055M && (w.word('D') || w.word('T'))))
        ++m_lengthCalls;
    if (m_dialect == Dialect::Aerotech && w.hasG(44))
        return aerotechWords(w, line); // G44 X Y Z names the axes: nothing moves
    if (auto r = usesToolTableWords(m_dialect) ? linuxCncLength(w, line)
            : m_dialect == Dialect::Aerotech   ? aerotechWords(w, line)
                                               : lengthWords(w, line);
        !r)
        return r;
    for (char a : { 'X', 'Y', 'Z' }) {
        if (w.word(a) && w.isBare(a))
            return error(line, tr("the word %1 needs a value.").arg(QChar::fromLatin1(a)));
    }
    if (auto r = motionOf(w, line, motion); !r)
        return r;
    if (w.hasM(2) || w.hasM(30))
        m_ended = true;
    return {};
}

Result<void> GCodeInterpreter::aerotechWords(const Words &w, int line)
{
    if (w.hasG(43))
        return error(line,
            tr("on Automation1, G43 is not tool length compensation; use G44 axes, offsets and "
               "G143 / G144."));
    if (w.hasG(44)) {
        QList<int> axes;
        for (char a : { 'X', 'Y', 'Z' }) {
            if (w.word(a))
                axes.append(axisIndex(a));
        }
        return aerotechAxes(axes, line);
    }
    const int requests = int(w.hasG(143)) + int(w.hasG(144)) + int(w.hasG(149));
    if (requests > 1)
        return error(line, tr("G143, G144 and G149 exclude one another."));
    if (w.hasG(143))
        m_pending = 1;
    else if (w.hasG(144))
        m_pending = -1;
    else if (w.hasG(149))
        m_pending = 2;
    return {};
}

// What the block moves: home (G28), a canned cycle's hole, or a move (G0-G3, or axis words in the mode).
Result<void> GCodeInterpreter::motionOf(const Words &w, int line, bool motion)
{
    // LinuxCNC's G43.1 takes Z as the offset, and so does the Carvera's M493.3; a dwell's X (FANUC's G4 X) is
    // its time.
    const bool consumedZ
        = (usesToolTableWords(m_dialect) && w.hasG(43.1)) || (m_dialect == Dialect::Carvera && w.hasM(493.3));
    const bool dwell = w.hasG(4);
    // G30's second reference point is the machine's own setting: Toffee takes it as home, as G28.
    if (w.hasG(28) || w.hasG(30)) {
        returnHome(w, line);
        return {};
    }
    if (m_cycle != 0 && !motion && (w.anyAxis() || m_cycleCalled) && !dwell)
        return cycle(w, line);
    if ((motion || (w.anyAxis() && !consumedZ)) && !dwell) {
        const Position programStart = m_program;
        move(w, line);
        const auto geometry = measureMove(w, programStart, line);
        if (!geometry)
            return geometry.error();
        m_effect.machineCoordinates = w.hasG(53);
        m_effect.lengthAxisWord = w.word("XYZ"[m_lengthAxis]);
        m_effect.lowestZ = geometry.value().lowestZ;
        account(geometry.value().length);
    }
    return {};
}

LengthCompensation GCodeInterpreter::lengthCompensation() const
{
    if (m_dialect == Dialect::Aerotech)
        return { m_compSign != 0 || m_pending == 1 || m_pending == -1, -1, 0.0, 0.0 };
    return { m_lengthMode != LengthMode::Off, m_lengthRegister, lengthContribution(), m_lengthValue };
}

double GCodeInterpreter::lengthContribution() const
{
    switch (m_lengthMode) {
    case LengthMode::Plus:
        return m_lengthValue;
    case LengthMode::Minus:
        return -m_lengthValue;
    case LengthMode::Off:
        return 0.0;
    }
    return 0.0;
}

void GCodeInterpreter::move(const Words &w, int line)
{
    const Position start = m_machine;
    const Position programStart = m_program;
    for (size_t i = 0; i < 3; ++i) {
        const char a = "XYZ"[i];
        if (w.word(a))
            m_program[i] = m_absolute ? w.get(a) : m_program[i] + w.get(a);
    }
    const bool machineCoordinates = w.hasG(53);

    // Aerotech: the offsets go on (or off) gradually over this move, on every compensation axis.
    double fromFraction = m_compFraction;
    double toFraction = m_compFraction;
    if (m_dialect == Dialect::Aerotech && m_pending != 0) {
        if (m_pending == 2) {
            toFraction = 0.0;
        } else {
            m_compSign = m_pending;
            fromFraction = 0.0;
            toFraction = 1.0;
        }
        m_pending = 0;
    }
    auto compensation = [&](size_t axis, double fraction) {
        if (m_dialect != Dialect::Aerotech)
            return 0.0;
        const qsizetype k = m_compAxes.indexOf(int(axis));
        return k < 0 ? 0.0 : m_compSign * m_compOffsets.at(k) * fraction;
    };

    Position end {};
    for (size_t i = 0; i < 3; ++i) {
        const bool commanded = w.word("XYZ"[i]);
        if (i == size_t(m_lengthAxis) && commanded)
            m_appliedLength = lengthContribution(); // a length offset rides on the next move of its axis
        const double length = i == size_t(m_lengthAxis) ? m_appliedLength : 0.0;
        if (m_dialect == Dialect::Aerotech)
            end[i] = m_program[i] + compensation(i, toFraction);
        else if (machineCoordinates && commanded)
            end[i] = m_program[i];
        else if (commanded || m_dialect == Dialect::Carvera)
            end[i] = m_program[i] + m_g54[i] + length;
        else
            end[i] = start[i];
    }
    m_compFraction = toFraction;
    if (m_compFraction == 0.0 && m_dialect == Dialect::Aerotech)
        m_compSign = 0;
    if (machineCoordinates) {
        for (size_t i = 0; i < 3; ++i)
            m_program[i] = end[i] - m_g54[i] - (i == size_t(m_lengthAxis) ? m_appliedLength : 0.0);
    }
    m_machine = end;
    if (m_dialect == Dialect::Aerotech)
        recordCompensated(line, programStart, fromFraction, toFraction);
    else
        recordStraight(line, start);
}

void GCodeInterpreter::keep(SimulatedMove &&move)
{
    if (m_moveSink)
        m_moveSink(move);
    else
        m_moves.append(std::move(move));
}

// The move to where the machine is now, from `start`, sampled along a straight line.
void GCodeInterpreter::recordStraight(int line, const Position &start)
{
    if (!m_recordMoves)
        return;
    SimulatedMove record { line, m_machine, {} };
    for (int s = 0; s < m_samples; ++s) {
        const double t = m_samples == 1 ? 1.0 : double(s) / double(m_samples - 1);
        Position p {};
        for (size_t k = 0; k < 3; ++k)
            p[k] = start[k] + t * (m_machine[k] - start[k]);
        record.points.append(p);
    }
    keep(std::move(record));
}

// An Aerotech move, sampled as the controller blends its compensation in (or out) from `fromFraction` to
// `toFraction` of the offsets over the move.
void GCodeInterpreter::recordCompensated(
    int line, const Position &programStart, double fromFraction, double toFraction)
{
    if (!m_recordMoves)
        return;
    SimulatedMove record { line, m_machine, {} };
    const int sign = m_compSign != 0 ? m_compSign : (fromFraction > 0 ? 1 : 0);
    for (int s = 0; s < m_samples; ++s) {
        const double t = m_samples == 1 ? 1.0 : double(s) / double(m_samples - 1);
        Position p {};
        for (size_t i = 0; i < 3; ++i) {
            const double programmed = programStart[i] + t * (m_program[i] - programStart[i]);
            const qsizetype k = m_compAxes.indexOf(int(i));
            const double offset = k < 0 ? 0.0 : m_compOffsets.at(k);
            p[i] = programmed
                + (sign == 0 ? 0.0 : sign * offset * (fromFraction + t * (toFraction - fromFraction)));
        }
        record.points.append(p);
    }
    keep(std::move(record));
}

} // namespace Toffee
