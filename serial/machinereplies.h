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
    // Makera's stock firmware prints no M493.4 report: its TLO comes from the status report's T: field alone,
    // and then currentMz holds the TLO, referenceMz is 0 and neither MCS Z is known.
    bool onlyTlo = false;
    // The MCS Zs, when the machine reported them.
    [[nodiscard]] std::optional<double> knownReferenceMz() const
    {
        return onlyTlo ? std::nullopt : std::optional<double>(referenceMz);
    }
    [[nodiscard]] std::optional<double> knownCurrentMz() const
    {
        return onlyTlo ? std::nullopt : std::optional<double>(currentMz);
    }
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

// Which firmware the controller runs, from its answer to `version` ("version = %s"): the community
// firmware's versions end in "c" (2.1.0c), Makera's stock firmware's do not (1.0.1). What each can do
// differs (docs/CARVERA.md § 7); an unknown firmware is offered only what both do.
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
