// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/gcode/gcodeinterpreter.h"

#include <cmath>

#include <QCoreApplication>

#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/toolvalidation.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr int kMaxOffsetNumber = Limits::kMaxOffsetNumber;
constexpr double kMaxGeometry = Limits::kMaxGeometryMm;
constexpr double kMaxWear = Limits::kMaxWearMm;
// Controllers take at most eight digits before the point (FANUC's +-99999999). The bound also keeps every
// position a program can reach finite: without it, two G91 moves of 1e308 end at infinity.
constexpr double kMaxWordValue = Limits::kMaxWordValue;

bool isLetter(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

char upper(char c)
{
    return c >= 'a' && c <= 'z' ? char(c - 'a' + 'A') : c;
}

bool same(double a, double b)
{
    return std::fabs(a - b) < 1e-6;
}

QString number(double v)
{
    return formatNumber(v);
}

QString tooLarge(QByteArrayView word)
{
    return tr("%1 is too large: a controller takes at most eight digits before the decimal point.")
        .arg(QString::fromUtf8(word));
}

int axisIndex(char letter)
{
    return letter == 'X' ? 0 : letter == 'Y' ? 1 : letter == 'Z' ? 2 : -1;
}

} // namespace

struct GCodeInterpreter::Words
{
    std::array<double, 26> value {};
    std::array<bool, 26> has {};
    std::array<bool, 26> bare {}; // a letter with no number: Aerotech's "G44 X Y Z"
    std::array<double, 8> g {};
    int gCount = 0;
    std::array<double, 4> m {};
    int mCount = 0;

    [[nodiscard]] bool hasG(double code) const
    {
        for (int i = 0; i < gCount; ++i) {
            if (same(g[size_t(i)], code))
                return true;
        }
        return false;
    }
    [[nodiscard]] bool hasM(double code) const
    {
        for (int i = 0; i < mCount; ++i) {
            if (same(m[size_t(i)], code))
                return true;
        }
        return false;
    }
    [[nodiscard]] bool word(char letter) const { return has[size_t(letter - 'A')]; }
    [[nodiscard]] double get(char letter) const { return value[size_t(letter - 'A')]; }
    [[nodiscard]] bool isBare(char letter) const { return bare[size_t(letter - 'A')]; }
    [[nodiscard]] bool anyAxis() const { return word('X') || word('Y') || word('Z'); }
};

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
                .arg(number(v))
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
    Words w;
    qsizetype i = 0;
    const qsizetype n = text.size();
    while (i < n) {
        const char c = text.at(i);
        if (c == ' ' || c == '\t' || c == '\r' || c == '%') {
            ++i;
        } else if (c == '(') {
            const qsizetype close = text.indexOf(')', i);
            if (close < 0)
                return error(line, tr("a comment \"(\" is never closed on this line."));
            i = close + 1;
        } else if (c == ';' || (c == '/' && i + 1 < n && text.at(i + 1) == '/')) {
            break;
        } else if (isLetter(c) && i + 1 < n && isLetter(text.at(i + 1))) {
            // A function call, as Aerotech writes them: the rest of the line, less a trailing comment.
            QByteArrayView call = text.sliced(i);
            if (const qsizetype comment = call.indexOf("//"); comment >= 0)
                call = call.first(comment);
            if (m_dialect != Dialect::Aerotech)
                return error(line,
                    tr("\"%1\" is not G-code this controller reads.").arg(QString::fromUtf8(call.trimmed())));
            ++m_blocks;
            return callFunction(call.trimmed(), line);
        } else if (isLetter(c)) {
            const char letter = upper(c);
            qsizetype j = i + 1;
            while (j < n && (text.at(j) == ' '))
                ++j;
            qsizetype k = j;
            while (k < n
                && ((text.at(k) >= '0' && text.at(k) <= '9') || text.at(k) == '.' || text.at(k) == '-'
                    || text.at(k) == '+'))
                ++k;
            const size_t slot = size_t(letter - 'A');
            if (k == j) {
                if (axisIndex(letter) < 0)
                    return error(line, tr("the word %1 needs a value.").arg(QChar::fromLatin1(letter)));
                w.has[slot] = true;
                w.bare[slot] = true;
                i = j;
                continue;
            }
            const auto v = parseDecimal(text.sliced(j, k - j));
            if (!v)
                return error(
                    line, tr("\"%1\" is not a number.").arg(QString::fromUtf8(text.sliced(j, k - j))));
            if (std::fabs(*v) > kMaxWordValue)
                return error(line, tooLarge(text.sliced(i, k - i)));
            if (letter == 'G') {
                if (w.gCount == int(w.g.size()))
                    return error(line, tr("too many G codes in one block."));
                w.g[size_t(w.gCount++)] = *v;
            } else if (letter == 'M') {
                if (w.mCount == int(w.m.size()))
                    return error(line, tr("too many M codes in one block."));
                w.m[size_t(w.mCount++)] = *v;
            } else {
                if (w.has[slot])
                    return error(
                        line, tr("the word %1 appears twice in one block.").arg(QChar::fromLatin1(letter)));
                w.has[slot] = true;
                w.value[slot] = *v;
            }
            i = k;
        } else {
            return error(line, tr("unexpected \"%1\".").arg(QChar::fromLatin1(c)));
        }
    }
    if (w.gCount == 0 && w.mCount == 0
        && std::none_of(w.has.cbegin(), w.has.cend(), [](bool b) { return b; }))
        return {};
    ++m_blocks;
    return execute(w, line);
}

Result<void> GCodeInterpreter::execute(const Words &w, int line)
{
    bool motion = false;
    for (int i = 0; i < w.gCount; ++i) {
        const double g = w.g[size_t(i)];
        if (same(g, 0) || same(g, 1))
            motion = true;
        else if (same(g, 90))
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
        else if (same(g, 20) || same(g, 21) || same(g, 54) || same(g, 10) || same(g, 43) || same(g, 44)
            || same(g, 49) || same(g, 43.1) || same(g, 43.2) || same(g, 74) || same(g, 143) || same(g, 144)
            || same(g, 149) || same(g, 53))
            continue; // handled below
        else
            return error(line, tr("G%1 is not simulated.").arg(number(g)));
    }
    if (w.hasG(10))
        return g10(w, line);

    if (m_dialect == Dialect::LinuxCnc) {
        if (auto r = linuxCncLength(w, line); !r)
            return r;
    } else if (m_dialect == Dialect::Aerotech) {
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
    } else {
        if (auto r = lengthWords(w, line); !r)
            return r;
    }

    for (char a : { 'X', 'Y', 'Z' }) {
        if (w.word(a) && w.isBare(a))
            return error(line, tr("the word %1 needs a value.").arg(QChar::fromLatin1(a)));
    }
    const bool consumedZ = m_dialect == Dialect::LinuxCnc && w.hasG(43.1);
    if (motion || (w.anyAxis() && !consumedZ))
        move(w, line);
    if (w.hasM(2) || w.hasM(30))
        m_ended = true;
    return {};
}

Result<void> GCodeInterpreter::lengthWords(const Words &w, int line)
{
    const bool fanuc = m_dialect == Dialect::Fanuc;
    const bool ab = m_dialect == Dialect::AllenBradley9;
    const bool fagor = m_dialect == Dialect::Fagor8055M;
    const bool carvera = m_dialect == Dialect::Carvera;

    if (carvera) {
        if (w.hasG(43) || w.hasG(44) || w.hasG(49))
            return error(line, tr("the Carvera has no G43/G44/G49: its TLO always applies."));
        if (w.hasM(493.3) && w.word('Z'))
            m_lengthValue = w.get('Z');
        if (w.hasM(6) && w.word('H'))
            m_lengthValue = w.get('H');
        m_lengthMode = LengthMode::Plus;
        return {};
    }
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
                            .arg(number(h))
                            .arg(kMaxOffsetNumber)
                      : tr("H%1 is not an offset number (0 to %2).").arg(number(h)).arg(kMaxOffsetNumber));
        m_hNumber = int(h);
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
    if (same(l, 2) || same(l, 20)) { // a work offset: G10 L2 P1 X Y Z
        if (w.word('P') && !same(w.get('P'), 1))
            return error(line, tr("only G54 (P1) is simulated."));
        for (size_t i = 0; i < 3; ++i) {
            const char a = "XYZ"[i];
            if (w.word(a))
                // L20: the current position becomes `value`, tool length offset included.
                m_g54[i] = same(l, 2)
                    ? w.get(a)
                    : m_machine[i] - w.get(a) - (i == size_t(m_lengthAxis) ? m_appliedLength : 0.0);
        }
        return {};
    }
    if (m_dialect == Dialect::LinuxCnc) {
        if (!same(l, 1))
            return error(line,
                tr("G10 L%1 is not simulated for LinuxCNC; G10 L1 writes the tool table.").arg(number(l)));
        if (!w.word('P') || w.get('P') < 1 || w.get('P') > Limits::kMaxToolNumber
            || w.get('P') != std::floor(w.get('P')))
            return error(line, tr("G10 L1 needs P, a tool number in the tool table."));
        const auto it = m_offsets.find(int(w.get('P')));
        if (it == m_offsets.end())
            return error(line, tr("G10 L1: tool %1 is not in the tool table.").arg(number(w.get('P'))));
        if (w.word('Z'))
            it->second.lengthGeometry
                = w.get('Z'); // the table only: the active offset changes at the next G43
        if (w.word('R'))
            it->second.radiusGeometry = w.get('R');
        return {};
    }
    if (m_dialect != Dialect::Fanuc && m_dialect != Dialect::AllenBradley9)
        return error(line, tr("this controller's offset table is not programmed with G10."));
    if (m_dialect == Dialect::AllenBradley9 && m_radiusComp)
        return error(line,
            tr("G10 may not be programmed while cutter compensation (G41/G42) is active; nothing was "
               "written."));
    if (!same(l, 10) && !same(l, 11) && !same(l, 12) && !same(l, 13))
        return error(line,
            fanuc ? tr("PS0031 ILLEGAL P COMMAND IN G10: L%1 is not L10 to L13.").arg(number(l))
                  : tr("G10 L%1 is not L10 to L13.").arg(number(l)));
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
            fanuc ? tr("PS0032 ILLEGAL OFFSET VALUE IN G10: %1 is beyond ±%2.").arg(number(result)).arg(limit)
                  : tr("G10: %1 is beyond ±%2.").arg(number(result)).arg(limit));
    field = result;
    m_offsets[int(p)] = entry;
    return {};
}

Result<void> GCodeInterpreter::aerotechAxes(const QList<int> &axes, int line)
{
    if (axes.size() != 2 && axes.size() != 3)
        return error(line, tr("cutter compensation takes 2 or 3 axes."));
    if (m_compSign != 0 || m_pending != 0)
        return error(
            line, tr("the compensation axes can only change while cutter offset compensation is off."));
    m_compAxes = axes;
    m_compOffsets = QList<double>(axes.size(), 0.0);
    return {};
}

Result<void> GCodeInterpreter::callFunction(QByteArrayView call, int line)
{
    const qsizetype open = call.indexOf('(');
    if (open < 0 || !call.endsWith(')'))
        return error(line, tr("\"%1\" is not a call this simulator knows.").arg(QString::fromUtf8(call)));
    const QByteArrayView name = call.first(open).trimmed();
    QByteArrayView args = call.sliced(open + 1, call.size() - open - 2).trimmed();
    if (args.startsWith('[') && args.endsWith(']'))
        args = args.sliced(1, args.size() - 2);
    QList<QByteArrayView> items;
    for (QByteArrayView item : splitView(args, ',')) {
        if (!item.trimmed().isEmpty())
            items.append(item.trimmed());
    }
    auto axesOf = [&](QList<int> &axes) -> bool {
        for (QByteArrayView item : items) {
            const int index = item.size() == 1 ? axisIndex(upper(item.front())) : -1;
            if (index < 0)
                return false;
            axes.append(index);
        }
        return true;
    };
    if (name == "CutterCompensationSetAxes") {
        QList<int> axes;
        if (!axesOf(axes))
            return error(line, tr("CutterCompensationSetAxes takes axes such as [X, Y, Z]."));
        return aerotechAxes(axes, line);
    }
    if (name == "CutterCompensationSetOffsets") {
        if (m_compSign != 0 || m_pending != 0)
            return error(
                line, tr("CutterCompensationSetOffsets works only while cutter offset compensation is off."));
        if (items.size() != m_compAxes.size())
            return error(line,
                tr("CutterCompensationSetOffsets needs %1 offsets, one for each compensation axis.")
                    .arg(m_compAxes.size()));
        QList<double> offsets;
        for (QByteArrayView item : items) {
            const auto v = parseDecimal(item);
            if (!v)
                return error(line, tr("\"%1\" is not a number.").arg(QString::fromUtf8(item)));
            if (std::fabs(*v) > kMaxWordValue)
                return error(line, tooLarge(item));
            offsets.append(*v);
        }
        m_compOffsets = offsets;
        return {};
    }
    if (name == "Home") {
        QList<int> axes;
        if (!axesOf(axes) || axes.isEmpty())
            return error(line, tr("Home takes axes such as X or [X, Y]."));
        // Compensation ends at once, with no lead-off.
        m_compSign = 0;
        m_compFraction = 0.0;
        m_pending = 0;
        SimulatedMove record { line, m_machine, {} };
        const Position start = m_machine;
        for (int a : axes) {
            m_machine[size_t(a)] = 0.0;
            m_program[size_t(a)] = 0.0;
        }
        if (m_recordMoves) {
            record.end = m_machine;
            for (int s = 0; s < m_samples; ++s) {
                const double t = m_samples == 1 ? 1.0 : double(s) / double(m_samples - 1);
                Position p {};
                for (size_t k = 0; k < 3; ++k)
                    p[k] = start[k] + t * (m_machine[k] - start[k]);
                record.points.append(p);
            }
            m_moves.append(record);
        }
        return {};
    }
    return error(line, tr("\"%1\" is not a call this simulator knows.").arg(QString::fromUtf8(name)));
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
    if (!m_recordMoves)
        return;
    SimulatedMove record { line, end, {} };
    for (int s = 0; s < m_samples; ++s) {
        const double t = m_samples == 1 ? 1.0 : double(s) / double(m_samples - 1);
        Position p {};
        for (size_t i = 0; i < 3; ++i) {
            if (m_dialect == Dialect::Aerotech) {
                const double programmed = programStart[i] + t * (m_program[i] - programStart[i]);
                const int sign = m_compSign != 0 ? m_compSign : (fromFraction > 0 ? 1 : 0);
                const qsizetype k = m_compAxes.indexOf(int(i));
                const double offset = k < 0 ? 0.0 : m_compOffsets.at(k);
                p[i] = programmed
                    + (sign == 0 ? 0.0 : sign * offset * (fromFraction + t * (toFraction - fromFraction)));
            } else {
                p[i] = start[i] + t * (end[i] - start[i]);
            }
        }
        record.points.append(p);
    }
    m_moves.append(record);
}

} // namespace Toffee
