// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cmath>
#include <optional>

#include <QByteArrayView>
#include <QString>

#include "model/limits.h"

namespace Toffee {

// What the controller's replies say, as plain values. Parsed by the pure functions below.

struct MachineStatus
{
    QString state; // Idle, Run, Hold, Alarm, Home, Sleep, Pause, Wait, Tool
    std::array<double, 3> mpos { 0, 0, 0 }; // machine X Y Z
    std::array<double, 3> wpos { 0, 0, 0 }; // work X Y Z
    std::optional<int> tool; // T: active tool
    std::optional<double> tlo; // T: its tool length offset
    std::optional<int> haltReason; // H: present only while halted

    [[nodiscard]] bool isAlarm() const { return state == u"Alarm" || haltReason.has_value(); }
};

// M493.4 (and M493.3): "current tool offset [cur] , reference tool offset [ref]". TLO = cur - ref.
struct TloReading
{
    double currentMz = 0.0;
    double referenceMz = 0.0;
    // At the machine's resolution (it reports 0.001 mm): -105.688 - -72.3 is -33.388, not
    // -33.388000000000005.
    [[nodiscard]] double tlo() const { return std::round((currentMz - referenceMz) * 1000.0) / 1000.0; }
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
// The text after "error:", "ALARM:" or "ERROR:", trimmed.
[[nodiscard]] QString replyMessage(QByteArrayView line);

[[nodiscard]] std::optional<MachineStatus> parseStatusReport(QByteArrayView line);
// Refuses values beyond kMaxMachineMillimetres, as no machine has them.
[[nodiscard]] std::optional<TloReading> parseTloReport(QByteArrayView line);
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

} // namespace Toffee
