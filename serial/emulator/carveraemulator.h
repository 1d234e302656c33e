// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <optional>

#include <QHash>
#include <QList>
#include <QObject>
#include <QTimer>

#include "model/gcode/gcodeinterpreter.h"
#include "model/gcode/gcodewords.h"
#include "model/result.h"

namespace Toffee {

// A Carvera controller as its firmware behaves (docs/CARVERA.md, checked against the community firmware
// itself in ../shared/peers/carvera): it keeps positions, the configured reference tool MCS Z, the TLO in
// force and the current tool's MCS Z as the firmware keeps them (M493.3 Z sets both to Z), a tool setter, the
// physical length of each tool (so a broken tool really measures shorter) and the halt state, and answers
// with the firmware's own lines: a shell command without "ok", a probing or tool-changing script acknowledged
// at once and echoed line by line, each with its "ok", to "Done ATC". Not a mock: tests and toffee-emulator
// drive it.
class CarveraEmulator final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(CarveraEmulator)

public:
    enum class Fault {
        DropOk, // the command runs but its "ok" never comes
        NoAnswer, // the command is swallowed: no output, no "ok"
        Garble, // the command's first reply line arrives mangled
        CloseLink, // the link drops when the command arrives
        FailProbe, // the probe does not trigger: ALARM, halt 3
        Delay, // the command is answered `amount` milliseconds late
        BreakTool, // the tool in the spindle loses `amount` mm as the command arrives
    };
    // The two firmwares differ in what they answer (docs/CARVERA.md § 7).
    enum class Firmware { Community, Stock };
    struct Timing
    {
        int probeMs = 0; // how long a probing cycle takes
        int moveMs = 0; // how long any other command takes
        int changeMs = 0; // how long a rack change takes before the new tool is measured
    };
    struct RackSlot
    {
        int tool = 0;
        double x = 0.0;
        double y = 0.0;
        double z = 0.0;
    };

    // The machine is a C1 as the firmware's config on the test peer's SD card sets it up (the setter at
    // Y-54.480, probed down to Z-154.400, from Z-3.000); the spindle nose itself would touch the
    // setter at MCS Z -150, and a tool of length L triggers L higher.
    static constexpr double kNoseTriggerZ = -150.0;
    static constexpr double kZTravelLimit = -154.4; // the probe gives up here
    static constexpr double kClearanceZ = -3.0;
    static constexpr qsizetype kMaxLineBytes = 4096;
    // What `version` answers (`version = %s`, no "ok"): a community build's name, Makera's release number.
    static constexpr char kCommunityVersion[] = "2.1.0c-emulator";
    static constexpr char kStockVersion[] = "1.0.1";
    // Makera's current firmware, which frames every byte (its version when the emulator speaks frames).
    static constexpr char kFramedStockVersion[] = "1.0.5";
    static constexpr int kMaxRepeats = 255; // M491 R<n>: the firmware keeps n in a byte
    // What the firmware prints after each halt; its numbers mean nothing (the firmware's own build prints a
    // host address there).
    static constexpr char kHaltLine[] = "Halt Happened at Line: 0,percent: 0, time: 0";

    explicit CarveraEmulator(QObject *parent = nullptr);

    // The reference tool MCS Z the machine is calibrated with (a setting of the firmware, kept in its
    // EEPROM): a C1's factory calibration on the test peer's SD card is -115.340. Probing never changes it.
    static constexpr double kFactoryReferenceMz = -115.34;
    void setReference(double mz) { m_refMz = mz; }
    void setTiming(Timing timing) { m_timing = timing; }
    // About as long as a C1 takes: a probing cycle 8 s, a rack change 15 s (Toffee's estimate).
    [[nodiscard]] static constexpr Timing realisticTiming() { return { 8000, 0, 15000 }; }
    void setFirmware(Firmware firmware) { m_firmware = firmware; }
    // What `version` answers, instead of the firmware's default.
    void setVersion(const QByteArray &version) { m_version = version; }
    [[nodiscard]] Firmware firmware() const { return m_firmware; }
    // How far apart repeated measurements of one tool trigger (M491 R<n>); 0 measures the same every time.
    void setRepeatability(double millimetres) { m_repeatability = millimetres; }
    // The C1's six slots, T1-T6; the rack at start.
    [[nodiscard]] static QList<RackSlot> defaultRack();
    void setRack(QList<RackSlot> rack) { m_rack = std::move(rack); }
    [[nodiscard]] const QList<RackSlot> &rack() const { return m_rack; }
    [[nodiscard]] bool inRack(int tool) const;
    // The community firmware's custom_tool_slots.txt: `number x y [z]` a line, `#` comments.
    [[nodiscard]] static Result<QList<RackSlot>> parseToolSlots(const QByteArray &text);
    void setToolLength(int tool, double millimetres) { m_lengths.insert(tool, millimetres); }
    // The rack's slots hold no tools (the test peer's SD card): a pick from the rack finds none and halts.
    void setRackEmpty(bool empty) { m_rackEmpty = empty; }
    // The tool in the spindle as the machine starts (T1 unless set; -1 empty, as a fresh C1).
    void setToolInSpindle(int tool) { m_tool = tool; }
    [[nodiscard]] double toolLength(int tool) const;
    void breakTool(int tool, double millimetres) { m_lengths.insert(tool, toolLength(tool) - millimetres); }
    // A one-shot fault on the next command that starts with `prefix` (any command when empty).
    void injectFault(Fault fault, const QByteArray &prefix = {}, double amount = 0);
    void setHomed(bool homed) { m_homed = homed; }
    void halt(int reason);

    [[nodiscard]] int tool() const { return m_tool; }
    [[nodiscard]] bool isHalted() const { return m_haltReason != 0; }
    [[nodiscard]] int haltReason() const { return m_haltReason; }
    [[nodiscard]] double referenceMz() const { return m_refMz; }
    [[nodiscard]] double currentMz() const { return m_curMz; }
    // The TLO in force, as the status report's T: field carries it.
    [[nodiscard]] double tlo() const { return m_tlo; }
    // Waiting for the operator to change a tool by hand (the status report says "Tool").
    [[nodiscard]] bool isWaitingForOperator() const { return m_waitingForOperator; }
    [[nodiscard]] QByteArray statusReport() const;

    // Whether a command is running or waiting.
    [[nodiscard]] bool isBusy() const { return m_busy || !m_queue.isEmpty(); }

public Q_SLOTS:
    // Bytes as they come down the wire, split as the firmware splits them: '?' and Ctrl-X act at once, '!'
    // and '~' at a line's start, '\r' ends a line like '\n', and a line stops growing at kMaxLineBytes.
    void receiveBytes(QByteArrayView bytes);
    // Forgets a half-received line (a new client).
    void resetInput() { m_input.clear(); }
    // One command line, without its line end.
    void receiveLine(const QByteArray &line);
    // A real-time character: '?' status, 0x18 abort, '!' hold, '~' resume.
    void receiveRealtime(char c);

Q_SIGNALS:
    void lineSent(const QByteArray &line);
    void linkClosed();

private:
    struct PendingFault
    {
        Fault fault;
        QByteArray prefix;
        double amount = 0;
    };

    // The firmware's halt reasons (the status report's H: field) that the emulator raises.
    enum class HaltReason {
        Manual = 1,
        HomeFail = 2,
        ProbeFail = 3,
        CalibrateFail = 4,
        AtcToolInvalid = 6,
        AtcNoTool = 7,
        SoftLimit = 10,
        ProbeInvalid = 12,
    };
    // The C1's soft endstops in machine coordinates (its config.txt: soft_endstop.x_min -364, y_min -250,
    // z_min -135; Robot.cpp: every max -1), enabled on a homed machine. A move that would end beyond one,
    // going towards it, halts before it starts (Robot::append_milestone).
    static constexpr std::array<double, 3> kSoftMin { -364.0, -250.0, -135.0 };
    static constexpr std::array<double, 3> kSoftMax { -1.0, -1.0, -1.0 };
    // An M-code's handler gets the block and the line as received (for the "Unsupported command" echo).
    using Handler = void (CarveraEmulator::*)(const GCodeBlock &block, const QByteArray &line);
    struct MCommand
    {
        double code;
        Handler run;
    };
    static const std::array<MCommand, 8> kMCommands;

    void processNext();
    void execute(const QByteArray &line);
    bool shellCommand(const QByteArray &line);
    void systemCommand(const QByteArray &line);
    void say(const QByteArray &line);
    // A line of a running script, echoed as the firmware echoes it, with its "ok".
    void echo(const QByteArray &line);
    void finish();
    // The end of a script: "Done ATC", and no "ok".
    void finishScript();
    // The end of a command the firmware answers without "ok" (its shell).
    void endSilently();
    void refuse(const QByteArray &line, const QByteArray &why = {});
    void haltWith(const QByteArray &message, HaltReason reason);
    void later(int ms, std::function<void()> step);

    void probeTool(const GCodeBlock &block, const QByteArray &line);
    void breakTest(const GCodeBlock &block, const QByteArray &line);
    void takeProbe(const GCodeBlock &block, const QByteArray &line);
    void selectTool(const GCodeBlock &block, const QByteArray &line);
    void setTlo(const GCodeBlock &block, const QByteArray &line);
    void showOffsets(const GCodeBlock &block, const QByteArray &line);
    void changeTool(const GCodeBlock &block, const QByteArray &line);
    void invalidTool(double tool);
    [[nodiscard]] static bool plausible(std::optional<double> millimetres);
    [[nodiscard]] static bool isToolNumber(double t);
    void announceChange(int newTool);
    [[nodiscard]] QByteArray toolField() const;
    void move(const QByteArray &line);

    // What kind of measurement a probing script makes.
    enum class Calibration { Measure, BreakTest, AfterChange };
    void calibrate(Calibration kind, double tolerance, int repeats = 0);
    void saveXy();
    void unknownCommand(const QByteArray &line);
    void pickTool(int tool, std::optional<double> tlo);
    [[nodiscard]] bool dropTool();
    [[nodiscard]] bool probeFails(double trigger);
    void failProbe();
    // M491 R<n>: each measurement's trigger, and where the spindle returns after the last.
    struct Repeats
    {
        int count = 0;
        double trigger = 0.0;
        double startX = 0.0;
        double startY = 0.0;
        QList<double> triggers;
    };
    void measureRepeatedly(Repeats repeats);
    void returnTo(double x, double y);
    void reportOffsets();
    void reportTlo();
    void takeTlo(double currentMz);

    Firmware m_firmware = Firmware::Community;

    QByteArray m_version;
    Timing m_timing;
    double m_repeatability = 0.0;
    QList<RackSlot> m_rack = defaultRack();
    QHash<int, double> m_lengths;
    QList<PendingFault> m_faults;
    QList<QByteArray> m_queue;
    QByteArray m_input; // the line being received
    QTimer m_step; // the running command's next step, if it takes time
    std::function<void()> m_stepAction;
    bool m_busy = false;
    bool m_dropOk = false;
    bool m_garble = false;
    bool m_failThisProbe = false; // a fail-probe fault aimed at the running command
    int m_printed = 0; // lines the running command printed
    bool m_held = false;

    bool m_homed = true;
    int m_haltReason = 0;
    std::array<double, 3> m_mpos { -2.0, -2.0, -2.0 };
    std::array<double, 3> m_wcs { 0.0, 0.0, 0.0 }; // G54, zero as on a fresh C1
    std::array<double, 2> m_setter { -4.965, -54.48 };
    // M491 X<dx> Y<dy>: the one-off touch-off point from the setter's, until the next M491 (community only).
    std::array<double, 2> m_oneOff { 0.0, 0.0 };
    int m_tool = 1;
    double m_refMz = kFactoryReferenceMz;
    double m_curMz = 0.0; // "current tool offset": the tool's MCS Z on the setter, or Z after M493.3 Z
    double m_tlo = 0.0; // in force: 0 until something is measured or set
    bool m_waitingForOperator = false;
    bool m_rackEmpty = false;
    std::array<double, 2> m_savedXy { 0.0, 0.0 };
    std::optional<double> m_lastProbeZ;
    // Motion and work offsets go through the same interpreter as `toffee-cli simulate`.
    GCodeInterpreter m_motion { Dialect::Carvera };
};

} // namespace Toffee
