// SPDX-License-Identifier: GPL-3.0-or-later
// The Carvera's commands as the firmware answers them: a table keyed by M-code, the system commands ($X, $H),
// motion through the shared interpreter, and the probing cycle behind M491, M491.1 and M6 (their firmware
// differences, the tool change and the rack are in carverarack.cpp).
#include "serial/emulator/carveraemulator.h"

#include <cmath>
#include <limits>

#include "model/gcode/carvera.h"
#include "model/limits.h"
#include "model/numberformat.h"

namespace Toffee {

namespace {

QByteArray fixed(double v, int decimals = 3)
{
    return numberBytes(v, NumberFormat::fixed(decimals));
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

// An offset or height no machine has (1e308 would make the next sum infinite) is refused, not taken.
bool CarveraEmulator::plausible(std::optional<double> millimetres)
{
    return !millimetres || std::fabs(*millimetres) <= kMaxMachineMillimetres;
}

// Checked before it becomes an int: T1e308 would not fit one, and T2.5 is no tool.
bool CarveraEmulator::isToolNumber(double t)
{
    return t >= Limits::kEmptySpindle && t < Limits::kMaxToolNumber + 1 && t == std::floor(t);
}

// The M-codes the emulator runs, each with its handler; the first the block has wins.
const std::array<CarveraEmulator::MCommand, 8> CarveraEmulator::kMCommands { {
    { 491, &CarveraEmulator::probeTool },
    { 491.1, &CarveraEmulator::breakTest },
    { 493, &CarveraEmulator::takeProbe },
    { 493.1, &CarveraEmulator::takeProbe },
    { 493.2, &CarveraEmulator::selectTool },
    { 493.3, &CarveraEmulator::setTlo },
    { 493.4, &CarveraEmulator::showOffsets },
    { 6, &CarveraEmulator::changeTool },
} };

void CarveraEmulator::execute(const QByteArray &line)
{
    if (shellCommand(line))
        return;
    if (line.isEmpty() || line.startsWith(';') || line.startsWith('(')) {
        finish();
        return;
    }
    // The dispatcher reads a line by its first character (GcodeDispatch): G, M, T, S, N and # are G-code,
    // X, Y, Z, A and F a move in the last mode; any other is answered "ok - ignore: [line]", halted or not,
    // the line printed as a C string (to its first NUL). A frame's bytes sent to a plain-text firmware end
    // so.
    if (!QByteArrayView("GMTSN#XYZAF").contains(line.front())) {
        const qsizetype nul = line.indexOf('\0');
        const QByteArray echoed = (nul < 0 ? line : line.first(nul)).left(kMaxLineBytes - 16);
        say("ok - ignore: [" + echoed + "]");
        return endSilently();
    }
    const auto read = GCodeBlock::read(line);
    if (isHalted() && !(read && carveraRunsWhileHalted(read.value()))) {
        say("error:Alarm lock");
        m_busy = m_dropOk = m_garble = false;
        QMetaObject::invokeMethod(this, &CarveraEmulator::processNext, Qt::QueuedConnection);
        return;
    }
    if (!read)
        return unknownCommand(line);
    const GCodeBlock &block = read.value();
    if (block.has('G', 20))
        return haltWith("ERROR: Imperial Units are unsupported", HaltReason::Manual);
    for (const auto &[code, run] : kMCommands) {
        if (block.has('M', code)) {
            (this->*run)(block, line);
            return;
        }
    }
    if (block.has('M', 999)) {
        m_haltReason = 0;
        say(kHaltLine);
        say("WARNING: After HALT you should HOME as position is currently unknown");
        finish();
    } else if (block.isEmpty()) {
        finish(); // a comment alone
    } else if (block.words.front().letter == 'G') {
        move(line);
    } else {
        finish(); // M2, M5, M9, M30, and any M-code it does not know: taken without a word
    }
}

// Upper-case text that is no G-code: the firmware says "ok", then halts on the expression it cannot read
// (seen on the firmware: `FOO`).
void CarveraEmulator::unknownCommand(const QByteArray &)
{
    say("ok");
    say("ERROR: Invalid number in expression, " + QByteArray(kHaltLine));
    halt(int(HaltReason::Manual));
    m_busy = m_dropOk = m_garble = false;
    QMetaObject::invokeMethod(this, &CarveraEmulator::processNext, Qt::QueuedConnection);
}

void CarveraEmulator::refuse(const QByteArray &line, const QByteArray &why)
{
    say(why.isEmpty() ? "error:Unsupported command - " + quoted(line) : why);
    m_dropOk = m_garble = false;
    m_busy = false;
    QMetaObject::invokeMethod(this, &CarveraEmulator::processNext, Qt::QueuedConnection);
}

// The firmware says why it halts, then where ("Halt Happened at Line: …"), then the "ok" of the line that
// halted it.
void CarveraEmulator::haltWith(const QByteArray &message, HaltReason reason)
{
    say(message);
    say(kHaltLine);
    halt(int(reason));
    m_waitingForOperator = false;
    finish();
}

// The TLO the firmware takes from a probe: the tool's MCS Z against the configured reference.
void CarveraEmulator::takeTlo(double currentMz)
{
    m_curMz = currentMz;
    m_tlo = currentMz - m_refMz;
}

// M493 (and .0, .1): the last probe becomes the current tool's TLO.
void CarveraEmulator::takeProbe(const GCodeBlock &, const QByteArray &)
{
    if (m_lastProbeZ)
        takeTlo(*m_lastProbeZ);
    finish();
}

// M493.2 T: the tool changes, the TLO in force does not (it is the previous tool's until measured or set).
void CarveraEmulator::selectTool(const GCodeBlock &block, const QByteArray &)
{
    m_oneOff = { 0.0, 0.0 }; // M493.2 ends M491's one-off touch-off point, as M6 does
    const auto t = block.value('T');
    if (!t)
        return haltWith("ERROR: No tool was set!", HaltReason::AtcNoTool);
    if (m_firmware == Firmware::Stock && !isToolNumber(*t))
        return invalidTool(*t);
    // The community firmware takes any number, as an int (ATCHandler: active_tool = get_value('T')): T-2 and
    // T1000000 are "ok", and its status report then says T:-2. Beyond an int, x86 gives INT_MIN.
    const double whole = std::trunc(*t);
    m_tool = std::isfinite(whole) && whole >= double(std::numeric_limits<int>::min())
            && whole <= double(std::numeric_limits<int>::max())
        ? int(whole)
        : std::numeric_limits<int>::min();
    finish();
}

// M493.3 Z<v>: the TLO is v, and so is the "current tool offset" the firmware prints (ATCHandler:
// cur_tool_mz = Z; tool_offset = cur_tool_mz). M493.3 H<h>: the current tool offset moves by the tool tip's
// work Z less h, and the TLO is it less the reference; after an M493.3 Z that is off by the reference, as on
// the firmware.
void CarveraEmulator::setTlo(const GCodeBlock &block, const QByteArray &line)
{
    if (m_firmware == Firmware::Stock)
        return finish(); // the stock firmware ignores M493.3 without a word
    const auto z = block.value('Z');
    const auto h = block.value('H');
    if (!plausible(z) || !plausible(h))
        return refuse(line);
    if (z) {
        m_curMz = *z;
        m_tlo = *z;
    } else if (h) {
        const double workZ = m_mpos[2] - m_wcs[2] - m_tlo;
        takeTlo(m_curMz + workZ - *h);
    }
    reportTlo();
    finish();
}

void CarveraEmulator::showOffsets(const GCodeBlock &, const QByteArray &)
{
    if (m_firmware == Firmware::Stock)
        return finish(); // as M493.3
    reportOffsets();
    finish();
}

// G-code moves and work offsets: the shared interpreter, in step with the machine's own moves and TLO.
void CarveraEmulator::move(const QByteArray &line)
{
    m_motion.setWorkOffset({ m_wcs[0], m_wcs[1], m_wcs[2] });
    m_motion.setLengthOffset(tlo());
    m_motion.setMachinePosition({ m_mpos[0], m_mpos[1], m_mpos[2] });
    if (auto r = m_motion.runLine(line, 1); !r) {
        finish(); // the firmware takes what it does not know without a word
        return;
    }
    const Position &p = m_motion.position();
    const Position &g54 = m_motion.workOffset();
    for (int axis = 0; m_homed && axis < 3; ++axis) {
        const double delta = p[axis] - m_mpos[axis];
        if ((p[axis] < kSoftMin[axis] && delta < 0) || (p[axis] > kSoftMax[axis] && delta > 0))
            return haltWith("ERROR: Soft Endstop " + QByteArray(1, char('X' + axis))
                    + " was exceeded - reset or $X or M999 required",
                HaltReason::SoftLimit);
    }
    m_mpos = { p[0], p[1], p[2] };
    m_wcs = { g54[0], g54[1], g54[2] };
    finish();
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
        + fixed(kZTravelLimit) + ']');
}

// A script starts by saving where the spindle is, and the command's own "ok" comes at once.
void CarveraEmulator::saveXy()
{
    m_savedXy = { m_mpos[0], m_mpos[1] };
    say("Saved XY position: X" + fixed(m_mpos[0]) + " Y" + fixed(m_mpos[1]));
    say("ok");
}

// The firmware's probing script, echoed line by line: fast down to the setter, back 2 mm, slowly again; the
// slow probe is the one taken (M493.1 R1). A break test compares it with the TLO in force (M491.2 H… , P…):
// a TLO of exactly 0 is "no previous TLO", compared with nothing.
void CarveraEmulator::calibrate(Calibration kind, double tolerance, int repeats)
{
    if (!m_homed)
        return haltWith(m_firmware == Firmware::Stock
                ? QByteArray("Machine has not been homed") // CARVERA.md's words
                : QByteArray("ERROR: Machine has not been homed. Use M888 to disable homed check"),
            HaltReason::HomeFail);
    const bool breakTest = kind == Calibration::BreakTest;
    if (breakTest)
        echo("M5");
    echo("M497.3");
    echo("G53 G0 Z" + fixed(kClearanceZ));
    const double atX = m_setter[0] + m_oneOff[0];
    const double atY = m_setter[1] + m_oneOff[1];
    echo("G53 G0 X" + fixed(atX) + " Y" + fixed(atY));
    say("G38.6 Z" + fixed(kZTravelLimit) + " F600.000");
    m_mpos = { atX, atY, kClearanceZ };
    const double trigger = kNoseTriggerZ + toolLength(m_tool);
    const bool fail = probeFails(trigger);
    if (repeats > 0) {
        if (fail)
            return later(m_timing.probeMs, [this] { failProbe(); });
        return measureRepeatedly({ repeats, trigger, m_savedXy[0], m_savedXy[1], {} });
    }
    later(m_timing.probeMs, [=, this] {
        if (fail)
            return failProbe();
        say("[PRB:" + fixed(atX) + ',' + fixed(atY) + ',' + fixed(trigger - 0.01) + ":1]");
        say("ok");
        echo("G91 G0 Z2.000");
        say("G38.6 Z-3.000 F150.000");
        say("[PRB:" + fixed(atX) + ',' + fixed(atY) + ',' + fixed(trigger) + ":1]");
        say("ok");
        m_lastProbeZ = trigger;
        m_mpos[2] = trigger;
        const double stored = m_tlo;
        echo("M493.1 R1");
        takeTlo(trigger);
        echo("G53 G0 Z" + fixed(kClearanceZ));
        m_mpos[2] = kClearanceZ;
        if (breakTest) {
            if (m_tool == 0 || m_tool >= 9) {
                // The community firmware takes T0 and T9 on for its wireless probe here.
                echo("M494.1");
                return haltWith("ERROR: Wireless probe dead or not set, please charge or set first!",
                    HaltReason::ProbeInvalid);
            }
            echo("G53 G0 Z-20.000");
            m_mpos[2] = -20.0;
            say("M491.2 H" + fixed(tolerance) + " , P" + fixed(stored));
            if (std::round(stored * 1000.0) == 0.0) {
                say("No previous TLO included, aborting");
                say("ok");
            } else {
                say("Old: " + fixed(stored) + " , new: " + fixed(m_tlo));
                // The new, broken length stays in force while the machine halts over the setter.
                if (std::fabs(stored - m_tlo) > tolerance)
                    return haltWith(
                        "ERROR: Tool Break Check - check tool for breakage", HaltReason::CalibrateFail);
                say("ok");
            }
        }
        returnTo(m_savedXy[0], m_savedXy[1]);
    });
}

// Whether the coming probe fails: a fault aimed at it, or a tool too short to reach the setter.
bool CarveraEmulator::probeFails(double trigger)
{
    bool fail = std::exchange(m_failThisProbe, false);
    for (qsizetype i = 0; !fail && i < m_faults.size(); ++i) {
        if (m_faults.at(i).fault == Fault::FailProbe && m_faults.at(i).prefix.isEmpty()) {
            m_faults.removeAt(i);
            fail = true;
            break;
        }
    }
    return fail || trigger < kZTravelLimit;
}

// The setter never triggered. The community firmware's G38.6 reports where it stopped, untriggered, and halts
// with a failed calibration (ZProbe::calibrate_Z); CARVERA.md gives the stock firmware's words.
void CarveraEmulator::failProbe()
{
    m_mpos[2] = kZTravelLimit;
    if (m_firmware == Firmware::Stock) {
        return haltWith("ALARM: Probe failed to trigger within safety margin ("
                + fixed(kClearanceZ - kZTravelLimit, 2) + "mm)",
            HaltReason::ProbeFail);
    }
    say("[PRB:" + fixed(m_setter[0]) + ',' + fixed(m_setter[1]) + ',' + fixed(kZTravelLimit) + ":0]");
    haltWith("ERROR: Calibrate fail!", HaltReason::CalibrateFail);
}

void CarveraEmulator::returnTo(double x, double y)
{
    m_mpos = { x, y, kClearanceZ };
    say("Return to XY position: X" + fixed(x) + " Y" + fixed(y));
    finishScript();
}

} // namespace Toffee
