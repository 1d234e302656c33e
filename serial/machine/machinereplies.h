// SPDX-License-Identifier: GPL-3.0-or-later
// What a controller's replies say, as plain values every controller's words are read into (the Carvera's in
// serial/carvera/carverareplies.h, grblHAL's in serial/grblhal/grblhalreplies.h).
#pragma once

#include <array>
#include <cmath>
#include <optional>

#include <QByteArrayView>
#include <QCoreApplication>
#include <QList>
#include <QString>

#include "model/limits.h"

namespace Toffee {

// What the controller's replies say, as plain values. Parsed by the pure functions below.

struct MachineStatus
{
    QString state; // Idle, Run, Hold, Alarm, Home, Sleep, Pause, Wait, Tool
    std::array<double, 3> mpos { 0, 0, 0 }; // machine X Y Z
    std::array<double, 3> wpos { 0, 0, 0 }; // work X Y Z
    std::optional<int> tool; // T: active tool; none when the field is absent, or holds no tool number
    std::optional<double> tlo; // T: the tool length offset in force
    std::optional<int> haltReason; // H: present only while halted

    [[nodiscard]] bool isAlarm() const { return state == u"Alarm" || haltReason.has_value(); }
};

// M493.4 (and M493.3): "current tool offset [cur] , reference tool offset [ref]". Only after a probe is
// cur - ref the TLO: after M493.3 Z<v> the firmware prints v as "current" (and v is the TLO), so the TLO in
// force is the status report's, never this difference (docs/CARVERA.md).
struct OffsetReport
{
    double currentMz = 0.0;
    double referenceMz = 0.0;
};

// The machine's offsets as Toffee concludes them: the TLO in force, as the status report's T: field carries
// it (the firmware's own value), the reference tool's MCS Z (M493.4's second number; Makera's stock firmware
// reports none), and the current tool's MCS Z on the setter (M493.4's first number, only when it is one: when
// current - reference is the TLO in force, as after a probe).
struct TloReading
{
    double tloInForce = 0.0;
    std::optional<double> referenceMz;
    std::optional<double> currentMz;
    // Each touch's machine Z, in the order made, when the tool was touched more than once (the Carvera's
    // M491 R; Toffee's cycle with a tool's touches): currentMz is the highest, the longest edge's.
    QList<double> touches = {};

    // At the machine's resolution (it reports 0.001 mm): never -33.388000000000005.
    [[nodiscard]] double tlo() const { return std::round(tloInForce * 1000.0) / 1000.0; }
    [[nodiscard]] std::optional<double> knownReferenceMz() const { return referenceMz; }
    [[nodiscard]] std::optional<double> knownCurrentMz() const { return currentMz; }
    // The TLO in force and M493.4's report: the current MCS Z is kept only when the report agrees with it.
    [[nodiscard]] static TloReading from(double tloInForce, const std::optional<OffsetReport> &report);
};

// "[PRB:x,y,z:ok]" (or ":1" / ":0" as grbl writes it).
struct ProbeResult
{
    double x = 0.0, y = 0.0, z = 0.0;
    bool triggered = false;
};

// M491.1: "Old: %.3f , new: %.3f".
struct BreakTestReading
{
    double oldTlo = 0.0;
    double newTlo = 0.0;
    QList<double> touches = {}; // as TloReading's: newTlo is the highest touch's
};

// Which controller and firmware the machine runs, and what it can do, as it said on connecting. The Carvera
// answers `version` ("version = %s"): Makera's stock firmware a plain release number (1.0.1, 1.0.5), the
// community firmware whatever its build was named (2.1.0c, 2.1.0c-simulator, Dev-78afb9f, pr-355-78afb9f,
// vcommunity_1.0.5alpha6, v1.0.3c1.0.6), so anything but a plain release number is the community's
// (parseVersion, serial/carvera). grblHAL answers `$I` ([VER:…], [OPT:…] with its tool table's size,
// [FIRMWARE:grblHAL]). What each can do differs (docs/CARVERA.md, docs/GRBLHAL.md); a machine that says
// nothing is offered only what all do.
struct FirmwareInfo
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::FirmwareInfo)

public:
    enum class Kind { Unknown, Community, Stock, GrblHal, LinuxCnc };
    Kind kind = Kind::Unknown;
    QString version; // as the machine printed it; empty when it did not say
    int toolTableSize = 0; // grblHAL: how many tools its own table holds (0: none; then G43.1 applies TLOs)

    [[nodiscard]] bool isCarvera() const { return kind == Kind::Community || kind == Kind::Stock; }
    [[nodiscard]] bool isGrblHal() const { return kind == Kind::GrblHal; }
    [[nodiscard]] bool isLinuxCnc() const { return kind == Kind::LinuxCnc; }
    // A break test that compares and stops: the community firmware's M491.1; grblHAL's as Toffee runs it (a
    // probe compared here). Makera's stock M491.1 is a plain calibration that adopts whatever it measures.
    [[nodiscard]] bool hasBreakTest() const
    {
        return kind == Kind::Community || kind == Kind::GrblHal || kind == Kind::LinuxCnc;
    }
    // A TLO can be set by hand: M493.3 (stock: ignored without a word), grblHAL's G10 L1 or G43.1.
    [[nodiscard]] bool hasManualOffset() const { return kind != Kind::Stock; }
    // The controller keeps a table of tools of its own (grblHAL built with N_TOOLS).
    // LinuxCNC's tool.tbl, written with G10 L1 (read from the file: linuxcncrsh has no command for it).
    [[nodiscard]] bool hasToolTable() const
    {
        return (kind == Kind::GrblHal && toolTableSize > 0) || kind == Kind::LinuxCnc;
    }
    // The Carvera's automatic tool changer, with its rack of six.
    [[nodiscard]] bool hasRack() const { return isCarvera(); }
    // "Makera stock firmware 1.0.1", "grblHAL 1.1f.20260817", for people.
    [[nodiscard]] QString description() const;
};

// One tool of a controller's own table (grblHAL's G10 L1 entries, read back with $#).
struct ControllerTool
{
    int tool = 0;
    double tlo = 0.0;
    double radius = 0.0;
    friend bool operator==(const ControllerTool &, const ControllerTool &) = default;
};

// What kind of line the controller sent.
enum class ReplyKind {
    Ok, // exactly "ok"
    Error, // "error:<text>": the command was refused
    Alarm, // "ALARM: <text>": the machine halted
    HaltError, // "ERROR: <text>": the firmware's halting errors (break test, no tool)
    Status, // "<...>"
    Other, // anything else: echo, information, or garbage; kept for the console
};

// How a command's reply ends, as the controller answers that kind of command (replyEndFor() says which, for
// the Carvera's words).
enum class ReplyEnd {
    Ok, // a G/M line: "ok" (or "error:") ends it
    // A shell command that prints one line and no "ok" (the Carvera's `version`): its first line ends it.
    Line,
    // A command that runs a script (the Carvera's M491, M491.1, M6): the firmware answers "ok" at once,
    // then echoes each line of its script with an "ok" of its own; "Done ATC" ends it, or, after a halt, the
    // "ok" of the line that halted. An "ok" with nothing before it ends it too (nothing to run: M6 to the
    // tool in the spindle).
    Script,
    // A shell command that may print nothing at all (the Carvera's $X when not halted): it ends with "ok" or
    // "error:", or when the machine has been silent for kQuietMs.
    Quiet,
};

} // namespace Toffee
