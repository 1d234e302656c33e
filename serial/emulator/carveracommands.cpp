// SPDX-License-Identifier: GPL-3.0-or-later
// The Carvera's commands as the firmware answers them: a table keyed by M-code, the system commands ($X, $H),
// motion through the shared interpreter, and the probing cycle behind M491, M491.1 and M6 (their firmware
// differences, the tool change and the rack are in carverarack.cpp).
#include "serial/emulator/carveraemulator.h"

#include <cmath>

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
    if (line.isEmpty() || line.startsWith(';')) {
        finish();
        return;
    }
    const auto read = GCodeBlock::read(line);
    if (isHalted() && !(read && carveraRunsWhileHalted(read.value()))) {
        say("error:Alarm lock");
        m_busy = m_dropOk = m_garble = false;
        QMetaObject::invokeMethod(this, &CarveraEmulator::processNext, Qt::QueuedConnection);
        return;
    }
    if (!read) {
        refuse(line);
        return;
    }
    const GCodeBlock &block = read.value();
    // Both firmwares alarm; the halt reason is Toffee's assumption (the sources name none).
    if (block.has('G', 20))
        return haltWith("ALARM: Imperial Units are unsupported", HaltReason::Manual);
    for (const auto &[code, run] : kMCommands) {
        if (block.has('M', code)) {
            (this->*run)(block, line);
            return;
        }
    }
    if (block.has('M', 999)) {
        m_haltReason = 0;
        say("WARNING: After HALT you should HOME as position is currently unknown");
        finish();
    } else if (block.isEmpty()) {
        finish(); // a comment alone
    } else if (block.words.front().letter == 'G') {
        move(line);
    } else if (carveraRunsWhileHalted(block)) {
        finish(); // M2, M5, M9, M30...: nothing to do on a table-top emulator
    } else {
        refuse(line);
    }
}

void CarveraEmulator::refuse(const QByteArray &line, const QByteArray &why)
{
    say(why.isEmpty() ? "error:Unsupported command - " + quoted(line) : why);
    m_dropOk = m_garble = false;
    m_busy = false;
    QMetaObject::invokeMethod(this, &CarveraEmulator::processNext, Qt::QueuedConnection);
}

void CarveraEmulator::haltWith(const QByteArray &message, HaltReason reason)
{
    say(message);
    halt(int(reason));
    finish();
}

// M493 (and .0, .1): the last probe becomes the current tool's, and the reference's if there is none.
void CarveraEmulator::takeProbe(const GCodeBlock &, const QByteArray &)
{
    if (m_lastProbeZ) {
        if (!m_hasReference) {
            m_refMz = *m_lastProbeZ;
            m_hasReference = true;
        }
        m_curMz = *m_lastProbeZ;
        m_calibrated = true;
    }
    finish();
}

void CarveraEmulator::selectTool(const GCodeBlock &block, const QByteArray &)
{
    const auto t = block.value('T');
    if (!t)
        return haltWith("ERROR: No tool was set!", HaltReason::AtcNoTool);
    if (!isToolNumber(*t))
        return invalidTool(*t);
    m_tool = int(*t);
    m_calibrated = false;
    finish();
}

void CarveraEmulator::setTlo(const GCodeBlock &block, const QByteArray &line)
{
    if (m_firmware == Firmware::Stock)
        return finish(); // the stock firmware ignores M493.3 without a word
    const auto z = block.value('Z');
    const auto h = block.value('H');
    if (!plausible(z) || !plausible(h))
        return refuse(line);
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
    if (auto r = m_motion.runLine(line, 1); !r)
        return refuse(line); // the firmware's own answer to what it does not take
    const Position &p = m_motion.position();
    const Position &g54 = m_motion.workOffset();
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
        + fixed(m_setter[2]) + ']');
}

void CarveraEmulator::calibrate(bool breakTest, double tolerance, int repeats)
{
    if (!m_homed) {
        return haltWith("Machine has not been homed", HaltReason::HomeFail);
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

    const double trigger = kNoseTriggerZ + toolLength(m_tool);
    const bool fail = probeFails(trigger);
    if (repeats > 0) {
        if (fail)
            return later(m_timing.probeMs, [this] { failProbe(); });
        return measureRepeatedly({ repeats, trigger, startX, startY, {} });
    }
    later(m_timing.probeMs, [=, this] {
        if (fail)
            return failProbe();
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
                return haltWith(
                    "ERROR: Tool Break Check - check tool for breakage", HaltReason::CalibrateFail);
            }
        } else {
            say("M493.1");
        }
        m_curMz = trigger;
        m_calibrated = true;
        returnTo(startX, startY);
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

void CarveraEmulator::failProbe()
{
    m_mpos[2] = kZTravelLimit;
    haltWith("ALARM: Probe failed to trigger within safety margin (" + fixed(kClearanceZ - kZTravelLimit, 2)
            + "mm)",
        HaltReason::ProbeFail);
}

void CarveraEmulator::returnTo(double x, double y)
{
    m_mpos = { x, y, kClearanceZ };
    say("Return to XY position: X" + fixed(x) + " Y" + fixed(y));
    say("Done ATC");
    finish();
}

} // namespace Toffee
