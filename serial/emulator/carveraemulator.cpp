// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/emulator/carveraemulator.h"

#include <cmath>

#include "model/numberformat.h"
#include "model/limits.h"
#include "model/textparsing.h"

namespace Toffee {

namespace {

QByteArray fixed(double v, int decimals = 3)
{
    return numberBytes(v, NumberFormat::fixed(decimals));
}

// "M493.3 Z-30.488" as (letter, value) words, upper-case, comments dropped.
struct Words
{
    QList<std::pair<char, QByteArray>> words;

    explicit Words(const QByteArray &line)
    {
        QByteArray text = line.toUpper();
        if (const qsizetype semicolon = text.indexOf(';'); semicolon >= 0)
            text.truncate(semicolon);
        for (const QByteArray &token : text.simplified().split(' ')) {
            if (!token.isEmpty())
                words.append({ token.front(), token.mid(1) });
        }
    }
    [[nodiscard]] bool has(char letter, QByteArrayView value) const
    {
        return std::any_of(words.cbegin(), words.cend(),
            [&](const auto &w) { return w.first == letter && w.second == value; });
    }
    [[nodiscard]] std::optional<QByteArray> text(char letter) const
    {
        for (const auto &w : words) {
            if (w.first == letter)
                return w.second;
        }
        return std::nullopt;
    }
    // A number word; `bad` is set when the word is there but not a number.
    [[nodiscard]] std::optional<double> number(char letter, bool &bad) const
    {
        const auto t = text(letter);
        if (!t)
            return std::nullopt;
        const auto v = parseDecimal(*t);
        bad = bad || !v;
        return v;
    }
};

// An offset or height no machine has (1e308 would make the next sum infinite) is refused, not taken.
bool plausible(std::optional<double> millimetres)
{
    return !millimetres || std::fabs(*millimetres) <= kMaxMachineMillimetres;
}

// A command quoted back in a reply: printable ASCII only, and short enough that the reply is one line a
// link takes whole.
QByteArray quoted(const QByteArray &line)
{
    QByteArray out = line.left(CarveraEmulator::kMaxLineBytes / 2);
    for (char &c : out) {
        if (c < 0x20 || c > 0x7e)
            c = '?';
    }
    return out;
}

} // namespace

CarveraEmulator::CarveraEmulator(QObject *parent)
    : QObject(parent)
{
    // The seed's example: the first tool probes at MCS Z -72.300, the second at -105.688.
    m_lengths.insert(1, 77.7);
    m_lengths.insert(2, 44.312);
    m_step.setSingleShot(true);
    connect(&m_step, &QTimer::timeout, this, [this] {
        auto action = std::move(m_stepAction);
        m_stepAction = nullptr;
        if (action)
            action();
    });
}

void CarveraEmulator::setProfile(Profile profile, double fixedReferenceMz)
{
    m_profile = profile;
    if (profile == Profile::FixedReference) {
        m_refMz = fixedReferenceMz;
        m_hasReference = true;
    }
}

double CarveraEmulator::toolLength(int tool) const
{
    if (tool < 0)
        return 0.0; // an empty spindle: the nose itself
    return m_lengths.value(tool, 40.0 + (tool % 20) * 2.5);
}

void CarveraEmulator::injectFault(Fault fault, const QByteArray &prefix, double amount)
{
    m_faults.append({ fault, prefix.toUpper(), amount });
}

void CarveraEmulator::halt(int reason)
{
    m_haltReason = reason;
}

QByteArray CarveraEmulator::statusReport() const
{
    const QByteArray state = isHalted() ? "Alarm" : m_held ? "Hold" : m_busy ? "Run" : "Idle";
    auto axes = [](double x, double y, double z) -> QByteArray {
        return fixed(x, 4) + ',' + fixed(y, 4) + ',' + fixed(z, 4) + ",0.0000,0.0000";
    };
    const double tloNow = m_curMz - m_refMz;
    QByteArray report = '<' + state + "|MPos:" + axes(m_mpos[0], m_mpos[1], m_mpos[2])
        + "|WPos:" + axes(m_mpos[0] - m_wcs[0], m_mpos[1] - m_wcs[1], m_mpos[2] - m_wcs[2] - tloNow)
        + "|R:0.0000|G:0|F:0.0,3000.0,100.0|S:0.0,0.0,100.0,0,23.5,24.1|T:" + QByteArray::number(m_tool) + ','
        + fixed(tloNow) + ",-1,0|W:0.00|C:1,0,0,1";
    if (isHalted())
        report += "|H:" + QByteArray::number(m_haltReason);
    return report + '>';
}

void CarveraEmulator::receiveRealtime(char c)
{
    switch (c) {
    case '?':
        Q_EMIT lineSent(statusReport());
        break;
    case 0x18: // Ctrl-X: abort whatever runs, drop what is queued
        m_queue.clear();
        if (m_busy) {
            m_step.stop();
            m_stepAction = nullptr;
            m_busy = false;
            m_dropOk = m_garble = false;
            halt(1);
            Q_EMIT lineSent("ALARM: Abort during cycle");
        }
        break;
    case '!':
        m_held = true;
        break;
    case '~':
        m_held = false;
        break;
    default:
        break;
    }
}

void CarveraEmulator::receiveBytes(QByteArrayView bytes)
{
    for (char c : bytes) {
        if (c == '?' || c == 0x18) {
            receiveRealtime(c);
        } else if ((c == '!' || c == '~') && m_input.isEmpty()) {
            receiveRealtime(c);
        } else if (c == '\n' || c == '\r') {
            receiveLine(std::exchange(m_input, {}));
        } else if (m_input.size() < kMaxLineBytes) {
            m_input += c;
        }
    }
}

void CarveraEmulator::receiveLine(const QByteArray &line)
{
    m_queue.append(line);
    if (!m_busy)
        processNext();
}

void CarveraEmulator::processNext()
{
    if (m_busy || m_queue.isEmpty())
        return;
    const QByteArray line = m_queue.takeFirst().trimmed();
    m_busy = true;
    m_printed = 0;
    const QByteArray upper = line.toUpper();
    m_failThisProbe = false;
    for (qsizetype i = 0; i < m_faults.size(); ++i) {
        const PendingFault f = m_faults.at(i);
        if (!f.prefix.isEmpty() && !upper.startsWith(f.prefix))
            continue;
        m_faults.removeAt(i);
        switch (f.fault) {
        case Fault::NoAnswer:
            m_busy = false;
            return; // swallowed; the queue waits for the next line
        case Fault::CloseLink:
            m_busy = false;
            m_queue.clear();
            Q_EMIT linkClosed();
            return;
        case Fault::DropOk:
            m_dropOk = true;
            break;
        case Fault::Garble:
            m_garble = true;
            break;
        case Fault::FailProbe:
            // With a prefix, it is this command's probe that fails (fail-probe@M491.1 leaves M491 alone);
            // without one, the next probing cycle's, whichever command runs it.
            if (f.prefix.isEmpty())
                m_faults.insert(i, f);
            else
                m_failThisProbe = true;
            break;
        case Fault::Delay:
            later(int(f.amount), [this, line] { execute(line); });
            return;
        case Fault::BreakTool:
            breakTool(m_tool, f.amount);
            break;
        }
        break;
    }
    if (m_timing.moveMs > 0)
        later(m_timing.moveMs, [this, line] { execute(line); });
    else
        execute(line);
}

void CarveraEmulator::later(int ms, std::function<void()> step)
{
    m_stepAction = std::move(step);
    m_step.start(ms);
}

void CarveraEmulator::say(const QByteArray &line)
{
    // Garbling hits every line the command prints, and its "ok" only when it prints nothing else.
    const bool garble = m_garble && (line != "ok" || m_printed == 0);
    if (line != "ok")
        ++m_printed;
    if (garble) {
        QByteArray mangled = line;
        for (char &c : mangled) {
            if ((c >= '0' && c <= '9') || c == 'k')
                c = char(0xBF);
        }
        Q_EMIT lineSent(mangled);
        return;
    }
    Q_EMIT lineSent(line);
}

void CarveraEmulator::finish()
{
    if (m_dropOk)
        m_dropOk = false;
    else
        say("ok");
    m_garble = false;
    m_busy = false;
    if (!m_queue.isEmpty())
        QMetaObject::invokeMethod(this, &CarveraEmulator::processNext, Qt::QueuedConnection);
}

bool CarveraEmulator::allowedWhileHalted(const QByteArray &upper) const
{
    static const QList<QByteArray> allowed = { "M2", "M5", "M9", "M30", "M80", "M81", "M105", "M106", "M107",
        "M114", "M115", "M119", "M503", "M911" };
    const QByteArray first = upper.simplified().split(' ').front();
    return first.isEmpty() || first == "$X" || first == "M999" || allowed.contains(first);
}

void CarveraEmulator::execute(const QByteArray &line)
{
    const QByteArray upper = line.toUpper();
    const Words w(line);
    if (upper.isEmpty() || upper.startsWith(';')) {
        finish();
        return;
    }
    if (isHalted() && !allowedWhileHalted(upper)) {
        say("error:Alarm lock");
        m_busy = m_dropOk = m_garble = false;
        QMetaObject::invokeMethod(this, &CarveraEmulator::processNext, Qt::QueuedConnection);
        return;
    }
    auto refuse = [this, &line](const QByteArray &why) {
        say(why.isEmpty() ? "error:Unsupported command - " + quoted(line) : why);
        m_dropOk = m_garble = false;
        m_busy = false;
        QMetaObject::invokeMethod(this, &CarveraEmulator::processNext, Qt::QueuedConnection);
    };
    bool bad = false;
    // Checked before it becomes an int: T1e308 would not fit one.
    auto isToolNumber = [](double t) {
        return t >= -1 && t < 1000000;
    };
    auto invalidTool = [this](double t) {
        say("ALARM: Invalid tool: T" + QByteArray::number(t, 'g', 10));
        halt(6);
        finish();
    };

    if (upper == "$X") {
        m_haltReason = 0;
        say("[Caution: Unlocked]");
        finish();
    } else if (upper == "M999") {
        m_haltReason = 0;
        say("WARNING: After HALT you should HOME as position is currently unknown");
        finish();
    } else if (upper == "$H") {
        m_homed = true;
        m_mpos = { 0.0, 0.0, 0.0 };
        finish();
    } else if (w.has('M', "491")) {
        calibrate(false, 0.0);
    } else if (w.has('M', "491.1")) {
        const double tolerance = w.number('H', bad).value_or(0.1);
        if (bad)
            return refuse({});
        if (tolerance < Limits::kMinBreakTolerance) {
            say("ERROR: Tool Break Check - tolerance set too small");
            halt(4);
            finish();
            return;
        }
        calibrate(true, tolerance);
    } else if (w.has('M', "493") || w.has('M', "493.0") || w.has('M', "493.1")) {
        if (m_lastProbeZ) {
            if (!m_hasReference) {
                m_refMz = *m_lastProbeZ;
                m_hasReference = true;
            }
            m_curMz = *m_lastProbeZ;
            m_calibrated = true;
        }
        finish();
    } else if (w.has('M', "493.2")) {
        const auto t = w.number('T', bad);
        if (!t || bad) {
            say("ERROR: No tool was set!");
            halt(7);
            finish();
            return;
        }
        if (!isToolNumber(*t))
            return invalidTool(*t);
        m_tool = int(*t);
        m_calibrated = false;
        finish();
    } else if (w.has('M', "493.3")) {
        const auto z = w.number('Z', bad);
        const auto h = w.number('H', bad);
        if (bad || !plausible(z) || !plausible(h))
            return refuse({});
        if (z) {
            m_curMz = m_refMz + *z;
            m_calibrated = true;
        } else if (h) {
            // The tool tip is h above work Z0: work Z of the spindle = mpos - wcs - tlo = h.
            m_curMz = m_refMz + (m_mpos[2] - m_wcs[2] - *h);
            m_calibrated = true;
        }
        reportTlo();
        finish();
    } else if (w.has('M', "493.4")) {
        reportOffsets();
        finish();
    } else if (w.has('M', "6")) {
        const auto t = w.number('T', bad);
        const auto h = w.number('H', bad);
        if (!t || bad || !plausible(h))
            return refuse({});
        if (!isToolNumber(*t))
            return invalidTool(*t);
        const int n = int(*t);
        m_tool = n;
        m_calibrated = false;
        if (h) {
            m_curMz = m_refMz + *h;
            m_calibrated = true;
            finish();
            return;
        }
        say("Start manually picking new tool: T" + QByteArray::number(n));
        calibrate(false, 0.0);
    } else if (w.words.front().first == 'G') {
        // G-code moves and work offsets: the shared interpreter, in step with the machine's own moves and
        // TLO.
        m_motion.setWorkOffset({ m_wcs[0], m_wcs[1], m_wcs[2] });
        m_motion.setLengthOffset(tlo());
        m_motion.setMachinePosition({ m_mpos[0], m_mpos[1], m_mpos[2] });
        if (auto r = m_motion.runLine(line, 1); !r)
            return refuse({}); // the firmware's own answer to what it does not take
        const Position &p = m_motion.position();
        const Position &g54 = m_motion.workOffset();
        m_mpos = { p[0], p[1], p[2] };
        m_wcs = { g54[0], g54[1], g54[2] };
        finish();
    } else if (allowedWhileHalted(upper)) {
        finish(); // M2, M5, M9, M30...: nothing to do on a table-top emulator
    } else {
        refuse({});
    }
}

void CarveraEmulator::reportTlo()
{
    say("current tool offset [" + fixed(m_curMz) + "] , reference tool offset [" + fixed(m_refMz) + ']');
}

void CarveraEmulator::reportOffsets()
{
    reportTlo();
    say("no one-off tool setter position offsets configured");
    say("using default Tool setter position: X[" + fixed(m_setter[0]) + "] Y[" + fixed(m_setter[1]) + "] Z["
        + fixed(m_setter[2]) + ']');
}

void CarveraEmulator::calibrate(bool breakTest, double tolerance)
{
    if (!m_homed) {
        say("Machine has not been homed");
        halt(2);
        finish();
        return;
    }
    if (breakTest && !m_calibrated) {
        say("No previous TLO included, aborting");
        finish();
        return;
    }
    const double startX = m_mpos[0];
    const double startY = m_mpos[1];
    // The probing script the firmware runs, echoed line by line.
    say("M497.3");
    say("G53 G0 Z" + fixed(kClearanceZ));
    say("G53 G0 X" + fixed(m_setter[0]) + " Y" + fixed(m_setter[1]));
    say("G38.6 Z" + fixed(kZTravelLimit) + " F500");
    m_mpos = { m_setter[0], m_setter[1], kClearanceZ };

    bool fail = std::exchange(m_failThisProbe, false);
    for (qsizetype i = 0; !fail && i < m_faults.size(); ++i) {
        if (m_faults.at(i).fault == Fault::FailProbe && m_faults.at(i).prefix.isEmpty()) {
            m_faults.removeAt(i);
            fail = true;
            break;
        }
    }
    const double trigger = kNoseTriggerZ + toolLength(m_tool);
    fail = fail || trigger < kZTravelLimit;

    later(m_timing.probeMs, [=, this] {
        if (fail) {
            m_mpos[2] = kZTravelLimit;
            say("ALARM: Probe failed to trigger within safety margin ("
                + fixed(kClearanceZ - kZTravelLimit, 2) + "mm)");
            halt(3);
            finish();
            return;
        }
        say("[PRB:" + fixed(m_setter[0]) + ',' + fixed(m_setter[1]) + ',' + fixed(trigger) + ":1]");
        m_lastProbeZ = trigger;
        const double oldTlo = m_curMz - m_refMz;
        if (!m_hasReference) {
            m_refMz = trigger;
            m_hasReference = true;
        }
        const double newTlo = trigger - m_refMz;
        if (breakTest) {
            say("Old: " + fixed(oldTlo) + " , new: " + fixed(newTlo));
            if (std::fabs(oldTlo - newTlo) > tolerance) {
                say("ERROR: Tool Break Check - check tool for breakage");
                halt(4);
                finish();
                return;
            }
        } else {
            say("M493.1");
        }
        m_curMz = trigger;
        m_calibrated = true;
        m_mpos = { startX, startY, kClearanceZ };
        say("Return to XY position: X" + fixed(startX) + " Y" + fixed(startY));
        say("Done ATC");
        finish();
    });
}

} // namespace Toffee
