// SPDX-License-Identifier: GPL-3.0-or-later
// Where the two firmwares part (docs/CARVERA.md § 7): the shell commands, M491's repeats and subcode, the
// status report's T field, and the tool change with its rack.
#include "serial/emulator/carveraemulator.h"

#include <algorithm>
#include <cmath>

#include "model/limits.h"
#include "model/numberformat.h"
#include "model/textparsing.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QByteArray fixed(double v, int decimals = 3)
{
    return numberBytes(v, NumberFormat::fixed(decimals));
}

constexpr int kMaxSlotTool = Limits::kMaxToolNumber - 10; // T999990 on are the 3-axis probes

// Where repeat i of M491 R<n> triggers, in units of the repeatability: the same every run, so tests can
// check the spread and the mean.
constexpr std::array<double, 5> kRepeatSpread { 0.0, 1.0, -1.0, 0.5, -0.5 };

} // namespace

// The C1's six slots as its firmware goes to them (seen on it): a row 30 mm apart in Y from X-4.960
// Y-84.480, at MCS Z -114.400.
QList<CarveraEmulator::RackSlot> CarveraEmulator::defaultRack()
{
    QList<RackSlot> rack;
    for (int n = 1; n <= 6; ++n)
        rack.append({ n, -4.96, -84.48 - 30.0 * (n - 1), -114.4 });
    return rack;
}

bool CarveraEmulator::inRack(int tool) const
{
    return std::any_of(m_rack.cbegin(), m_rack.cend(), [tool](const RackSlot &s) { return s.tool == tool; });
}

Result<QList<CarveraEmulator::RackSlot>> CarveraEmulator::parseToolSlots(const QByteArray &text)
{
    QList<RackSlot> rack;
    const QList<QByteArray> lines = text.split('\n');
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const int lineNumber = int(i + 1);
        const qsizetype hash = lines.at(i).indexOf('#');
        const QByteArray content = (hash < 0 ? lines.at(i) : lines.at(i).left(hash)).simplified();
        if (content.isEmpty())
            continue;
        const QList<QByteArray> fields = content.split(' ');
        const bool counted = fields.size() == 3 || fields.size() == 4;
        const auto tool = counted ? parseInteger(fields.at(0)) : std::nullopt;
        std::array<std::optional<double>, 3> xyz;
        for (qsizetype k = 1; counted && k < fields.size(); ++k) {
            xyz[size_t(k - 1)] = parseDecimal(fields.at(k));
            if (!plausible(xyz[size_t(k - 1)]))
                xyz[size_t(k - 1)].reset();
        }
        if (!tool || !xyz[0] || !xyz[1] || (fields.size() == 4 && !xyz[2])) {
            return Error(
                u"\"%1\" is not \"number x y [z]\""_s.arg(QString::fromUtf8(content.left(80))), lineNumber);
        }
        if (*tool < 1 || *tool > kMaxSlotTool)
            return Error(u"tool %1 is not 1-%2"_s.arg(*tool).arg(kMaxSlotTool), lineNumber);
        if (std::any_of(rack.cbegin(), rack.cend(), [&](const RackSlot &s) { return s.tool == *tool; }))
            return Error(u"tool %1 has a slot already"_s.arg(*tool), lineNumber);
        if (!xyz[2] && rack.isEmpty())
            return Error(u"the first slot needs a z"_s, lineNumber);
        rack.append({ int(*tool), *xyz[0], *xyz[1], xyz[2] ? *xyz[2] : rack.last().z });
    }
    if (rack.isEmpty())
        return Error(u"no tool slots"_s);
    return rack;
}

QByteArray CarveraEmulator::toolField() const
{
    const bool empty = m_tool == Limits::kEmptySpindle;
    if (m_firmware == Firmware::Stock)
        return empty ? QByteArray() : "|T:" + QByteArray::number(m_tool) + ',' + fixed(tlo());
    return "|T:" + QByteArray::number(m_tool) + ',' + fixed(empty ? 0.0 : tlo()) + ",-1,0";
}

// The firmware's shell: its commands are not G-code, so they run while halted too, and they are answered
// without "ok" (`version`), or not at all ($X on a machine that is not halted).
bool CarveraEmulator::shellCommand(const QByteArray &line)
{
    // The shell takes the first word for the command and ignores the words after it (`version ?`).
    const qsizetype space = line.indexOf(' ');
    const QByteArray word = space < 0 ? line : line.first(space);
    if (word == "version") {
        say(QByteArray("version = ")
            + (!m_version.isEmpty()                 ? m_version
                    : m_firmware == Firmware::Stock ? QByteArray(kStockVersion)
                                                    : QByteArray(kCommunityVersion)));
        endSilently();
        return true;
    }
    if (line.startsWith('$')) {
        systemCommand(line);
        return true;
    }
    if (!line.isEmpty() && line.front() >= 'a' && line.front() <= 'z') {
        // Another shell word (echo, ls, …): this emulator has none of them (the firmware names the word).
        refuse(line.split(' ').front());
        return true;
    }
    return false;
}

// The firmware's grbl commands (SimpleShell), by their second character as sent (`$x` is no `$X`): $G and $I
// the modal state (only $G with "ok"), $# the work offsets with "ok", $X an unlock that says nothing when
// nothing is halted, $H homing; $J, $S, $F and $O end without "ok" (this emulator neither jogs nor switches);
// any other letter "error:Invalid statement", and a bare "$" the shell's unknown command. The shell takes
// them while halted too ($H clears the halt first).
void CarveraEmulator::systemCommand(const QByteArray &line)
{
    if (line.size() < 2)
        return refuse(line);
    // The state as the peer prints it at rest: the shell asks a tool manager the Carvera does not have (T0).
    const QByteArray state = "[G0 G54 G17 G21 G90 G94 M0 M5 M9 T0 F5000.0000 S1.0000]";
    switch (line.at(1)) {
    case 'X':
        if (!isHalted())
            return endSilently(); // not a word when there is nothing to unlock
        m_haltReason = 0;
        say(kHaltLine);
        say("[Caution: Unlocked]");
        return finish();
    case 'H':
        m_haltReason = 0;
        m_homed = true;
        m_mpos = { 0.0, 0.0, 0.0 };
        return finish();
    case 'G':
        say(state);
        return finish();
    case 'I':
        say(state);
        return endSilently();
    case '#':
        for (const char *name : { "G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3" }) {
            const bool g54 = qstrcmp(name, "G54") == 0;
            say(QByteArray("[") + name + ':' + fixed(g54 ? m_wcs[0] : 0.0, 4) + ','
                + fixed(g54 ? m_wcs[1] : 0.0, 4) + ',' + fixed(g54 ? m_wcs[2] : 0.0, 4)
                + ",0.0000,0.0000,0.0000]");
        }
        say("[G28:0.0000,0.0000,0.0000]");
        say("[G30:0.0000,0.0000,0.0000]");
        say("[G92:0.0000,0.0000,0.0000,0.0000,0.0000]");
        say("[TL0:0.0000]");
        say("[PRB:0.0000,0.0000,0.0000:0]");
        return finish();
    case 'J':
    case 'S':
        return endSilently();
    case 'F':
    case 'O':
        if (!line.contains('S'))
            say("usage: $O S100");
        return endSilently();
    default:
        say("error:Invalid statement");
        return endSilently();
    }
}

void CarveraEmulator::probeTool(const GCodeBlock &block, const QByteArray &line)
{
    const GCodeWord *r = block.find('R');
    if (r && m_firmware != Firmware::Stock
        && (r->bare || r->value != std::floor(r->value) || r->value > kMaxRepeats))
        return refuse(line);
    m_oneOff = { 0.0, 0.0 };
    if (m_firmware != Firmware::Stock) {
        for (int axis = 0; axis < 2; ++axis) {
            if (const auto v = block.value(axis == 0 ? 'X' : 'Y'))
                m_oneOff[size_t(axis)] = *v;
        }
    }
    saveXy();
    // The stock firmware has no repeats and ignores R; the community's takes R0 and below as one.
    if (!r || m_firmware == Firmware::Stock || r->value <= 1)
        return calibrate(Calibration::Measure, 0.0);
    calibrate(Calibration::Measure, 0.0, int(r->value));
}

void CarveraEmulator::breakTest(const GCodeBlock &block, const QByteArray &line)
{
    if (m_firmware == Firmware::Stock) {
        saveXy();
        return calibrate(Calibration::Measure, 0.0); // the subcode is ignored: a plain M491
    }
    const GCodeWord *h = block.find('H');
    if (h && h->bare)
        return refuse(line);
    const double tolerance = h ? h->value : Limits::kDefaultBreakTolerance;
    if (tolerance < Limits::kMinBreakTolerance)
        return haltWith("ERROR: Tool Break Check - tolerance set too small", HaltReason::CalibrateFail);
    saveXy();
    calibrate(Calibration::BreakTest, tolerance);
}

// M491 R<n> as the community firmware runs it (ATCHandler.cpp): each pass a fast and a slow probe and M493.1,
// then 25 mm up for the operator to turn the cutter; after the last, M493.1 R<n> prints every pass's TLO, the
// highest as "Using", the spread as "Max delta", and keeps the LOWEST contact's TLO (the shortest edge's).
// The edge numbers come out as the firmware's do (equal values: "1, n").
void CarveraEmulator::measureRepeatedly(Repeats repeats)
{
    later(m_timing.probeMs, [this, r = std::move(repeats)]() mutable {
        const qsizetype i = r.triggers.size();
        const double trigger = r.trigger + m_repeatability * kRepeatSpread[size_t(i) % kRepeatSpread.size()];
        const QByteArray xy = fixed(m_setter[0] + m_oneOff[0]) + ',' + fixed(m_setter[1] + m_oneOff[1]);
        say("[PRB:" + xy + ',' + fixed(trigger - 0.01) + ":1]");
        say("ok");
        echo("G91 G0 Z2.000");
        say("G38.6 Z-3.000 F150.000");
        say("[PRB:" + xy + ',' + fixed(trigger) + ":1]");
        say("ok");
        m_lastProbeZ = trigger;
        r.triggers.append(trigger);
        if (r.triggers.size() < r.count) {
            echo("M493.1");
            echo("G91 G0 Z25.000");
            echo("G53 G0 X" + fixed(m_setter[0] + m_oneOff[0]) + " Y" + fixed(m_setter[1] + m_oneOff[1]));
            say("G38.6 Z" + fixed(kZTravelLimit) + " F600.000");
            return measureRepeatedly(std::move(r));
        }
        say("M493.1 R" + QByteArray::number(r.count));
        say("------------------ Measurements--------------------");
        for (qsizetype n = 0; n < r.triggers.size(); ++n)
            say("TLO value from measurement " + QByteArray::number(n + 1) + ": "
                + fixed(r.triggers[n] - m_refMz));
        const auto high = std::max_element(r.triggers.cbegin(), r.triggers.cend());
        const auto low = std::min_element(r.triggers.crbegin(), r.triggers.crend());
        const qsizetype highIndex = high - r.triggers.cbegin() + 1;
        const qsizetype lowIndex = r.triggers.size() - (low - r.triggers.crbegin());
        say("------------------ Results------------------------------");
        say("Using TLO value from measurement " + QByteArray::number(highIndex) + ": "
            + fixed(*high - m_refMz));
        say("Max delta: " + fixed(*high - *low));
        say("Lowest cutting edge: " + QByteArray::number(highIndex)
            + ", Highest cutting edge: " + QByteArray::number(lowIndex));
        say("-----------------------------------------------------------");
        say("ok");
        takeTlo(*low);
        echo("G53 G0 Z" + fixed(kClearanceZ));
        m_mpos[2] = kClearanceZ;
        returnTo(r.startX, r.startY);
    });
}

// M6 T<n>: the firmware changes only to another tool (M6 to the tool in the spindle gets a bare "ok"). A rack
// tool is put back or picked and always measured (H is for manual changes only); a tool with no slot is
// changed by hand: the machine waits in state Tool for the operator (changeMs here), then measures it, or
// takes H as its TLO.
void CarveraEmulator::changeTool(const GCodeBlock &block, const QByteArray &line)
{
    const auto t = block.value('T');
    const auto h = block.value('H');
    if (!t || !plausible(h))
        return refuse(line);
    m_oneOff = { 0.0, 0.0 };
    if (!isToolNumber(*t))
        return invalidTool(*t);
    const int n = int(*t);
    if (n == m_tool)
        return finish();
    m_savedXy = { m_mpos[0], m_mpos[1] };
    say("Saved XY position: X" + fixed(m_mpos[0]) + " Y" + fixed(m_mpos[1]));
    announceChange(n);
    say("ok");
    if (!dropTool())
        return; // halted
    if (n == Limits::kEmptySpindle) {
        if (m_timing.changeMs > 0)
            return later(m_timing.changeMs, [this] { returnTo(m_savedXy[0], m_savedXy[1]); });
        return returnTo(m_savedXy[0], m_savedXy[1]);
    }
    const std::optional<double> tlo = inRack(n) ? std::nullopt : h;
    if (m_timing.changeMs > 0) {
        m_waitingForOperator = !inRack(n);
        return later(m_timing.changeMs, [this, n, tlo] { pickTool(n, tlo); });
    }
    pickTool(n, tlo);
}

// The tool in the spindle goes back in its slot (and the slot's sensor must then see it), or is taken out by
// hand. False when the machine halted.
bool CarveraEmulator::dropTool()
{
    if (m_tool == Limits::kEmptySpindle)
        return true;
    const bool toRack = inRack(m_tool);
    echo("M497.1");
    echo("G53 G0 Z" + fixed(kClearanceZ));
    for (const RackSlot &slot : std::as_const(m_rack)) {
        if (slot.tool == m_tool) {
            echo("G53 G0 X" + fixed(slot.x) + " Y" + fixed(slot.y));
            echo("G53 G0 Z" + fixed(slot.z));
        }
    }
    say("M490.2");
    say("ATC loosed!");
    say("ok");
    echo("M493.2 T-1");
    m_tool = Limits::kEmptySpindle;
    if (toRack) {
        say("M492.1");
        if (m_rackEmpty) {
            haltWith(
                "ERROR: Unexpected tool absence detected, please check tool rack!", HaltReason::AtcNoTool);
            return false;
        }
        say("ok");
    }
    echo("G53 G0 Z" + fixed(kClearanceZ));
    return true;
}

void CarveraEmulator::pickTool(int tool, std::optional<double> tlo)
{
    m_waitingForOperator = false;
    for (const RackSlot &slot : std::as_const(m_rack)) {
        if (slot.tool == tool) {
            echo("G53 G0 X" + fixed(slot.x) + " Y" + fixed(slot.y));
            echo("G53 G0 Z" + fixed(slot.z));
        }
    }
    if (inRack(tool)) {
        say("M492.1"); // is there a tool in the slot?
        if (m_rackEmpty)
            return haltWith(
                "ERROR: Unexpected tool absence detected, please check tool rack!", HaltReason::AtcNoTool);
        say("ok");
    }
    say("M490.1");
    say("ATC clamped!");
    say("ok");
    echo("M493.2 T" + QByteArray::number(tool));
    m_tool = tool;
    if (!tlo)
        return calibrate(Calibration::AfterChange, 0.0);
    say("Tool is now installed and TLO set as " + fixed(*tlo) + '.');
    say("ok");
    say("M493.3 Z" + fixed(*tlo));
    m_curMz = *tlo;
    m_tlo = *tlo;
    reportTlo();
    say("ok");
    returnTo(m_savedXy[0], m_savedXy[1]);
}

// The stock firmware says one line for a drop and a pick; the community firmware one for each.
void CarveraEmulator::announceChange(int newTool)
{
    const QByteArray oldT = 'T' + QByteArray::number(m_tool);
    const QByteArray newT = 'T' + QByteArray::number(newTool);
    const bool dropping = m_tool != Limits::kEmptySpindle;
    if (m_firmware == Firmware::Stock && dropping && newTool != Limits::kEmptySpindle)
        return say("Start atc, old tool: " + oldT + ", new tool: " + newT);
    if (dropping)
        say((inRack(m_tool) ? "Start dropping current tool: " : "Start manually dropping current tool: ")
            + oldT);
    if (newTool == Limits::kEmptySpindle)
        return;
    say((inRack(newTool) ? "Start picking new tool: " : "Start manually picking new tool: ") + newT);
}

void CarveraEmulator::invalidTool(double tool)
{
    haltWith((m_firmware == Firmware::Stock ? "ALARM: Invalid tool: T" : "ERROR: Invalid tool: T")
            + numberBytes(tool),
        HaltReason::AtcToolInvalid);
}

} // namespace Toffee
