// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cmath>
#include <optional>

#include <QByteArrayView>
#include <QCoreApplication>
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
};

// Which firmware the controller runs, from its answer to `version` ("version = %s"). Makera's stock firmware
// says a plain release number (1.0.1, 1.0.5); the community firmware says whatever its build was named
// (2.1.0c, 2.1.0c-simulator, Dev-78afb9f, pr-355-78afb9f, vcommunity_1.0.5alpha6, v1.0.3c1.0.6), so anything
// but a plain release number is the community's. What each can do differs (docs/CARVERA.md); a machine that
// says nothing is offered only what both do.
struct FirmwareInfo
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::FirmwareInfo)

public:
    enum class Kind { Unknown, Community, Stock };
    Kind kind = Kind::Unknown;
    QString version; // as the machine printed it; empty when it did not say

    // M491.1 compares and halts (stock: a plain calibration that adopts whatever it measures).
    [[nodiscard]] bool hasBreakTest() const { return kind == Kind::Community; }
    // M493.3 sets the TLO and M493.4 reports it (stock: both ignored without a word).
    [[nodiscard]] bool hasManualOffset() const { return kind != Kind::Stock; }
    // "Makera stock firmware 1.0.1", for people.
    [[nodiscard]] QString description() const;
};

[[nodiscard]] std::optional<FirmwareInfo> parseVersion(QByteArrayView line);

// What kind of line the controller sent.
enum class ReplyKind {
    Ok, // exactly "ok"
    Error, // "error:<text>": the command was refused
    Alarm, // "ALARM: <text>": the machine halted
    HaltError, // "ERROR: <text>": the firmware's halting errors (break test, no tool)
    Status, // "<...>"
    Other, // anything else: echo, information, or garbage; kept for the console
};

[[nodiscard]] ReplyKind classifyReply(QByteArrayView line);
// "Done ATC": the end of a script the firmware ran (M491, M491.1, M6).
[[nodiscard]] bool isScriptDone(QByteArrayView line);
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

// How the Carvera's reply to `line` ends: a script for M491, M491.1 and M6, one line for `version`, possibly
// nothing for its other shell commands ($X, a lower-case word), "ok" for the rest.
[[nodiscard]] ReplyEnd replyEndFor(QByteArrayView line);
// The text after "error:", "ALARM:" or "ERROR:", trimmed.
[[nodiscard]] QString replyMessage(QByteArrayView line);

[[nodiscard]] std::optional<MachineStatus> parseStatusReport(QByteArrayView line);
// Refuses values beyond kMaxMachineMillimetres, as no machine has them.
[[nodiscard]] std::optional<OffsetReport> parseTloReport(QByteArrayView line);
// Whether `line` is a well-formed offset report whose values no machine can have.
[[nodiscard]] bool isImplausibleTloReport(QByteArrayView line);
[[nodiscard]] std::optional<ProbeResult> parseProbeResult(QByteArrayView line);
// Refuses values beyond kMaxMachineMillimetres, like parseTloReport.
[[nodiscard]] std::optional<BreakTestReading> parseBreakTest(QByteArrayView line);

// "PROBE_FAIL (3)" for an operator; the firmware's halt reasons 1-16, 21-26 and 41.
[[nodiscard]] QString haltReasonName(int reason);
// What the halt means, in words an operator acts on (not the firmware's name).
[[nodiscard]] QString haltMeaning(int reason);
// Whether $X clears it (1-16), or it needs a reset (21-26) or a power cycle (41).
[[nodiscard]] QString haltRecovery(int reason);
// What a halting line the firmware prints means and what to do, for the lines Toffee knows ("Calibrate
// fail!", "Probe failed to trigger …", "Machine has not been homed …", "Invalid tool: T…"); empty for others,
// whose meaning the status report's halt reason gives.
[[nodiscard]] QString haltLineMeaning(QStringView message);

} // namespace Toffee
