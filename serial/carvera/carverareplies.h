// SPDX-License-Identifier: GPL-3.0-or-later
// The Carvera's words: its replies read by pure functions (docs/CARVERA.md), and the grammar MachineLink
// reads them by. The values they give are every controller's (serial/machine/machinereplies.h).
#pragma once

#include <optional>

#include <QByteArrayView>
#include <QString>

#include "serial/machine/machinelink.h"
#include "serial/machine/machinereplies.h"

namespace Toffee {

// How MachineLink reads the Carvera's lines (every Carvera controller, MachineSession, sets it).
[[nodiscard]] ReplyGrammar carveraGrammar();

[[nodiscard]] std::optional<FirmwareInfo> parseVersion(QByteArrayView line);

[[nodiscard]] ReplyKind classifyReply(QByteArrayView line);
// "Done ATC": the end of a script the firmware ran (M491, M491.1, M6).
[[nodiscard]] bool isScriptDone(QByteArrayView line);
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
// A probe's result among a script's lines: the last one (the firmware probes fast, then slowly, and takes the
// second).
[[nodiscard]] std::optional<ProbeResult> lastProbe(const QList<QByteArray> &lines);
// M491 R<n>'s summary (the community firmware's M493.1 R<n>, ATCHandler.cpp): "TLO value from measurement
// %d: %.3f" for each pass, oldest first, and "Using TLO value from measurement %d: %.3f" (the highest, the
// longest edge's; the firmware then stores the lowest, the shortest edge's). Empty when the reply has none.
struct RepeatedMeasurement
{
    QList<double> tlos; // each pass's TLO, in the order made
    std::optional<double> using_;
};
[[nodiscard]] RepeatedMeasurement repeatedMeasurement(const QList<QByteArray> &lines);
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
