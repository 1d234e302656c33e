// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/carvera/carverareplies.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include <QCoreApplication>
#include <QList>

#include "model/gcode/gcodewords.h"
#include "model/textparsing.h"
#include "model/toolvalidation.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr qint64 kEmptySpindle = Limits::kEmptySpindle; // "T-1 empty spindle" (docs/CARVERA.md)

// "a,b,c" into up to three numbers; the status report has five axes, the first three are X Y Z.
bool plausible(double millimetres)
{
    return std::isfinite(millimetres) && std::fabs(millimetres) <= kMaxMachineMillimetres;
}

// Three positions, each one a machine can be at (a status of MPos 1e308 is garbage, not a place).
bool parseAxes(QByteArrayView text, std::array<double, 3> &out)
{
    int i = 0;
    for (QByteArrayView part : splitView(text, ',')) {
        const auto v = parseDecimal(part.trimmed());
        if (!v || !plausible(*v))
            return false;
        if (i < 3)
            out[size_t(i)] = *v;
        ++i;
    }
    return i >= 3;
}

// The number between `open` and `close` after `from`, e.g. "[" "]".
std::optional<double> bracketed(QByteArrayView line, qsizetype &from)
{
    const qsizetype open = line.indexOf('[', from);
    if (open < 0)
        return std::nullopt;
    const qsizetype close = line.indexOf(']', open);
    if (close < 0)
        return std::nullopt;
    from = close + 1;
    return parseDecimal(line.sliced(open + 1, close - open - 1).trimmed());
}

} // namespace

ReplyKind classifyReply(QByteArrayView line)
{
    line = line.trimmed();
    // "ok - ignore: [B2]" is the firmware's "ok" to a line it does not read as a command.
    if (line == "ok" || line.startsWith("ok - ignore: ["))
        return ReplyKind::Ok;
    if (line.startsWith("error:"))
        return ReplyKind::Error;
    if (line.startsWith("ALARM:"))
        return ReplyKind::Alarm;
    // "Machine has not been homed" is the stock firmware's halting line without a prefix (CARVERA.md: M491 on
    // an unhomed machine, halt 2); the community firmware says "ERROR: Machine has not been homed. …".
    if (line.startsWith("ERROR:") || line == "Machine has not been homed")
        return ReplyKind::HaltError;
    if (line.startsWith('<') && line.endsWith('>'))
        return ReplyKind::Status;
    return ReplyKind::Other;
}

bool isScriptDone(QByteArrayView line)
{
    return line.trimmed() == "Done ATC";
}

ReplyEnd replyEndFor(QByteArrayView line)
{
    line = line.trimmed();
    if (line.isEmpty())
        return ReplyEnd::Ok;
    if (line == "version")
        return ReplyEnd::Line;
    // The firmware's shell (SimpleShell): $G, $# and $H end with "ok"; $X says nothing when the machine is
    // not halted; $I, $J, $S, $F and $O print what they print and no "ok"; any other $ is "error:Invalid
    // statement"; its lower-case commands (version, echo, ls, …) are answered without "ok".
    if (line.front() == '$') {
        const char second = line.size() > 1 ? line.at(1) : '\0';
        return second == 'G' || second == '#' || second == 'H' ? ReplyEnd::Ok : ReplyEnd::Quiet;
    }
    if (line.front() >= 'a' && line.front() <= 'z')
        return ReplyEnd::Quiet;
    if (const auto block = GCodeBlock::read(line);
        block && (block.value().has('M', 491) || block.value().has('M', 491.1) || block.value().has('M', 6)))
        return ReplyEnd::Script;
    return ReplyEnd::Ok;
}

QString replyMessage(QByteArrayView line)
{
    line = line.trimmed();
    const qsizetype colon = line.indexOf(':');
    return QString::fromUtf8(colon < 0 ? line : line.sliced(colon + 1)).trimmed();
}

std::optional<MachineStatus> parseStatusReport(QByteArrayView line)
{
    line = line.trimmed();
    if (!line.startsWith('<') || !line.endsWith('>') || line.size() < 3)
        return std::nullopt;
    const QList<QByteArrayView> fields = splitView(line.sliced(1, line.size() - 2), '|');
    MachineStatus status;
    status.state = QString::fromLatin1(fields.front());
    if (status.state.isEmpty())
        return std::nullopt;
    for (QChar c : std::as_const(status.state)) {
        if (!c.isLetter())
            return std::nullopt;
    }
    bool hasMpos = false;
    for (qsizetype i = 1; i < fields.size(); ++i) {
        const QByteArrayView field = fields.at(i);
        const qsizetype colon = field.indexOf(':');
        if (colon < 0)
            continue; // a field without a name: skipped like any unknown field
        const QByteArrayView name = field.first(colon);
        const QByteArrayView value = field.sliced(colon + 1);
        if (name == "MPos") {
            if (!parseAxes(value, status.mpos))
                return std::nullopt;
            hasMpos = true;
        } else if (name == "WPos") {
            if (!parseAxes(value, status.wpos))
                return std::nullopt;
        } else if (name == "T") {
            const QList<QByteArrayView> parts = splitView(value, ',');
            const auto tool = parseInteger(parts.front());
            const auto tlo = parts.size() > 1 ? parseDecimal(parts.at(1)) : std::nullopt;
            // T-1 is the empty spindle. The firmware takes M493.2 T-2 or T1000000 and then reports that
            // number: the report still holds the state and the position, but no tool (taken as an int it
            // would wrap round to some other tool).
            if (!tool || parts.size() < 2 || !tlo || !plausible(*tlo))
                return std::nullopt; // garbled
            if (tool && *tool >= kEmptySpindle && *tool <= Limits::kMaxToolNumber)
                status.tool = int(*tool);
            status.tlo = *tlo;
        } else if (name == "H") {
            const auto reason = parseInteger(value);
            if (!reason || *reason < 0 || *reason > std::numeric_limits<int>::max())
                return std::nullopt;
            status.haltReason = int(*reason);
        }
    }
    if (!hasMpos)
        return std::nullopt;
    return status;
}

namespace {

// The report's two numbers, whatever their size.
std::optional<OffsetReport> readTloReport(QByteArrayView line)
{
    line = line.trimmed();
    if (!line.startsWith("current tool offset [") || !line.contains("] , reference tool offset ["))
        return std::nullopt;
    qsizetype from = 0;
    const auto current = bracketed(line, from);
    const auto reference = bracketed(line, from);
    if (!current || !reference || from != line.size())
        return std::nullopt;
    return OffsetReport { *current, *reference };
}

bool plausible(const OffsetReport &report)
{
    return plausible(report.currentMz) && plausible(report.referenceMz);
}

} // namespace

std::optional<OffsetReport> parseTloReport(QByteArrayView line)
{
    const auto report = readTloReport(line);
    if (!report || !plausible(*report))
        return std::nullopt;
    return report;
}

bool isImplausibleTloReport(QByteArrayView line)
{
    const auto report = readTloReport(line);
    return report && !plausible(*report);
}

std::optional<ProbeResult> parseProbeResult(QByteArrayView line)
{
    line = line.trimmed();
    if (!line.startsWith("[PRB:") || !line.endsWith(']'))
        return std::nullopt;
    const QByteArrayView body = line.sliced(5, line.size() - 6);
    const qsizetype colon = body.lastIndexOf(':');
    if (colon < 0)
        return std::nullopt;
    std::array<double, 3> axes {};
    const QList<QByteArrayView> parts = splitView(body.first(colon), ',');
    if (parts.size() != 3 || !parseAxes(body.first(colon), axes))
        return std::nullopt;
    const QByteArrayView flag = body.sliced(colon + 1);
    if (flag != "ok" && flag != "1" && flag != "0" && flag != "fail")
        return std::nullopt;
    return ProbeResult { axes[0], axes[1], axes[2], flag == "ok" || flag == "1" };
}

std::optional<BreakTestReading> parseBreakTest(QByteArrayView line)
{
    line = line.trimmed();
    if (!line.startsWith("Old:"))
        return std::nullopt;
    const qsizetype comma = line.indexOf(',');
    if (comma < 0)
        return std::nullopt;
    const QByteArrayView rest = line.sliced(comma + 1).trimmed();
    if (!rest.startsWith("new:"))
        return std::nullopt;
    const auto oldTlo = parseDecimal(line.sliced(4, comma - 4).trimmed());
    const auto newTlo = parseDecimal(rest.sliced(4).trimmed());
    if (!oldTlo || !newTlo || !plausible(*oldTlo) || !plausible(*newTlo))
        return std::nullopt;
    return BreakTestReading { *oldTlo, *newTlo };
}

QString haltReasonName(int reason)
{
    static const char *const names[]
        = { "MANUAL", "HOME_FAIL", "PROBE_FAIL", "CALIBRATE_FAIL", "ATC_HOME_FAIL", "ATC_TOOL_INVALID",
              "ATC_NO_TOOL", "ATC_HAS_TOOL", "SPINDLE_OVERHEATED", "SOFT_LIMIT", "COVER_OPEN",
              "PROBE_INVALID", "E_STOP", "POWER_OVERHEATED", "NON_HOME", "CRASH_DETECTED" };
    if (reason >= 1 && reason <= 16)
        return QString::fromLatin1(names[reason - 1]) + u" ("_s + QString::number(reason) + u')';
    return tr("halt reason %1").arg(reason);
}

QString haltMeaning(int reason)
{
    switch (reason) {
    case 1:
        return tr("The machine was stopped (Stop, Ctrl-X or the stop button).");
    case 2:
        return tr("Homing failed, or the machine has not been homed.");
    case 3:
        return tr("The probe did not touch within its safety margin: the tool may be missing, broken or much "
                  "shorter than expected.");
    case 4:
        return tr(
            "Measuring on the tool setter failed: the setter was not touched (the tool may be missing or "
            "much "
            "shorter than expected), a break test found the tool broken, or the tolerance was too small.");
    case 5:
        return tr("The tool changer could not home.");
    case 6:
        return tr("The tool asked for is not a valid tool.");
    case 7:
        return tr("The tool changer found no tool where one should be (an empty rack pocket), or was given "
                  "no tool.");
    case 8:
        return tr("The spindle already holds a tool.");
    case 9:
        return tr("The spindle overheated.");
    case 10:
        return tr("A move went beyond the machine's travel (soft limit).");
    case 11:
        return tr("The cover is open.");
    case 12:
        return tr("The probe is not valid.");
    case 13:
        return tr("The emergency stop is pressed.");
    case 14:
        return tr("The power supply overheated.");
    case 15:
        return tr("The machine has not been homed.");
    case 16:
        return tr("A crash was detected.");
    default:
        return tr("The machine halted (reason %1).").arg(reason);
    }
}

QString haltRecovery(int reason)
{
    if (reason >= 21 && reason <= 26)
        return tr("This halt needs a reset of the controller.");
    if (reason == 41)
        return tr("This halt needs the machine switched off and on again.");
    return tr("Check the machine, then Unlock ($X).");
}

QString haltLineMeaning(QStringView message)
{
    if (message.startsWith(u"Calibrate fail"))
        return tr("The tool setter was never touched: the tool may be missing, broken or much shorter than "
                  "expected. Check the spindle, then Unlock.");
    if (message.startsWith(u"Probe failed to trigger"))
        return haltMeaning(3) + u' ' + haltRecovery(3);
    if (message.startsWith(u"Machine has not been homed"))
        return tr("Unlock, home the machine, then try again.");
    if (message.startsWith(u"Invalid tool") || message.contains(u"not defined in tool slots"))
        return haltMeaning(6) + u' ' + haltRecovery(6);
    return {};
}

std::optional<FirmwareInfo> parseVersion(QByteArrayView line)
{
    line = line.trimmed();
    constexpr QByteArrayView kPrefix = "version = ";
    if (!line.startsWith(kPrefix))
        return std::nullopt;
    const QByteArrayView version = line.sliced(kPrefix.size()).trimmed();
    if (version.isEmpty() || version.size() > 64)
        return std::nullopt;
    for (char c : version) {
        if (c < 0x21 || c > 0x7e)
            return std::nullopt;
    }
    FirmwareInfo info;
    info.version = QString::fromLatin1(version);
    // A plain release number, two to four numbers and dots (Makera's 1.0.5), is the stock firmware's; any
    // other name a build was given is the community firmware's. A community build named like a release
    // would be taken for the stock one, which is offered less (no break test), never more.
    const QList<QByteArrayView> parts = splitView(version, '.');
    const bool plainRelease = parts.size() >= 2 && parts.size() <= 4
        && std::all_of(parts.cbegin(), parts.cend(), [](QByteArrayView part) {
               return !part.isEmpty() && part.size() <= 4
                   && std::all_of(part.cbegin(), part.cend(),
                       [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
           });
    info.kind = plainRelease ? FirmwareInfo::Kind::Stock : FirmwareInfo::Kind::Community;
    return info;
}

ReplyGrammar carveraGrammar()
{
    return { classifyReply,
        [](QByteArrayView line, const std::optional<MachineStatus> &) { return parseStatusReport(line); },
        isScriptDone, replyMessage, haltLineMeaning, nullptr };
}

std::optional<ProbeResult> lastProbe(const QList<QByteArray> &lines)
{
    std::optional<ProbeResult> found;
    for (const QByteArray &line : lines) {
        if (auto p = parseProbeResult(line))
            found = p;
    }
    return found;
}

RepeatedMeasurement repeatedMeasurement(const QList<QByteArray> &lines)
{
    RepeatedMeasurement out;
    for (const QByteArray &raw : lines) {
        const QByteArray line = raw.trimmed();
        const bool each = line.startsWith("TLO value from measurement ");
        const bool used = line.startsWith("Using TLO value from measurement ");
        if (!each && !used)
            continue;
        const qsizetype colon = line.lastIndexOf(':');
        const auto value = colon < 0 ? std::nullopt : parseDecimal(line.mid(colon + 1).trimmed());
        if (!value || !std::isfinite(*value) || std::fabs(*value) > kMaxMachineMillimetres)
            continue;
        if (each)
            out.tlos << *value;
        else
            out.using_ = *value;
    }
    return out;
}

} // namespace Toffee
