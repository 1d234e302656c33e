// SPDX-License-Identifier: GPL-3.0-or-later
// What grblHAL's replies say, as plain values: pure functions over one line each, bounded, trusting nothing
// (../shared/GRBLHAL.md; grblHAL's report.c is the reference for the shapes).
#pragma once

#include <array>
#include <map>
#include <optional>

#include <QByteArrayView>
#include <QMap>
#include <QString>

namespace Toffee::GrblHal {

// A line longer than this is refused whole: grblHAL's longest ($I's, a tool with a name) are a few hundred
// characters, and its receive buffer is 1024.
inline constexpr qsizetype kMaxLineLength = 2048;
// At most this many tools are kept from one $# (grblHAL's own table holds at most 32; an SD card's more).
inline constexpr int kMaxTools = 1000;
// X Y Z A B C U V W: grblHAL has at least 3 axes and at most 9 letters for them.
inline constexpr int kMinAxes = 3;
inline constexpr int kMaxAxes = 9;
// A tool's name as Toffee keeps a description.
inline constexpr qsizetype kMaxNameLength = 255;

// One value per axis, X Y Z first, as grblHAL prints positions and offsets ("0.000,0.000,-12.345").
struct AxisValues
{
    std::array<double, kMaxAxes> values {};
    int count = 0;

    [[nodiscard]] double x() const { return values[0]; }
    [[nodiscard]] double y() const { return values[1]; }
    [[nodiscard]] double z() const { return values[2]; }
    friend bool operator==(const AxisValues &, const AxisValues &) = default;
};

// "a,b,c[,…]": 3 to kMaxAxes finite numbers within kMaxMachineMillimetres.
[[nodiscard]] std::optional<AxisValues> parseAxisValues(QByteArrayView text);

// What $I says of the build. Lines it does not know are skipped.
struct BuildInfo
{
    QString
        firmware; // "grblHAL" from [FIRMWARE:grblHAL]; empty when the controller did not say (classic Grbl)
    QString version; // "1.1f.20260817" from [VER:1.1f.20260817:]
    QString buildName; // what [VER:…:] holds after the version's colon ($I=text sets it); often empty
    int toolTableSize = 0; // the last field of [OPT:…] (0: no tool table in the controller)
    bool toolChange = false; // M6 is carried out: TC (manual) or ATC=n in [NEWOPT:…]
    bool automaticToolChanger = false; // ATC=n in [NEWOPT:…]
    QString axes; // "XYZ" from [AXS:3:XYZ]

    [[nodiscard]] bool isGrblHal() const { return firmware == u"grblHAL"; }
    [[nodiscard]] bool hasToolTable() const { return toolTableSize > 0; }
};

// Takes $I's lines one by one. A malformed or repeated known line is refused (and counted), the first one
// standing; unknown lines are skipped.
class BuildInfoBuilder
{
public:
    // Whether the line was one of $I's that Toffee reads, and well formed.
    bool addLine(QByteArrayView line);
    [[nodiscard]] const BuildInfo &info() const { return m_info; }
    // Whether [VER:…] and [OPT:…] were both read: enough to know the tool table's size.
    [[nodiscard]] bool hasVersionAndOptions() const { return m_seenVersion && m_seenOptions; }
    [[nodiscard]] int refusedLines() const { return m_refused; }

private:
    BuildInfo m_info;
    bool m_seenVersion = false;
    bool m_seenOptions = false;
    bool m_seenFirmware = false;
    bool m_seenNewOptions = false;
    bool m_seenAxes = false;
    int m_refused = 0;
};

// One tool of the controller's table: "[T:3|0.000,0.000,-12.345|1.500|6,0,0||3]".
struct ToolEntry
{
    int number = 0;
    AxisValues offset; // the tool length offset is offset.z()
    double radius = 0.0;
    QString name; // may be empty
    std::optional<int> pocket; // absent when the controller has none for the tool
};

// "[G54:x,y,z]" … "[G59.3:…]", "[G28:…]", "[G30:…]", "[G92:…]" (a rotation after a second colon is skipped).
struct WorkOffset
{
    QString name; // "G54", "G59.1", "G28", "G92"
    AxisValues values;
};

// "[PRB:x,y,z:1]": the last probe's machine position, and whether it touched.
struct ProbeReport
{
    AxisValues position;
    bool touched = false;
};

[[nodiscard]] std::optional<ToolEntry> parseToolEntry(QByteArrayView line);
[[nodiscard]] std::optional<WorkOffset> parseWorkOffset(QByteArrayView line);
// "[TLO:x,y,z]", or "[TLO:z]" on a build with a single tool length axis (then z() is that value).
[[nodiscard]] std::optional<AxisValues> parseToolLengthOffset(QByteArrayView line);
[[nodiscard]] std::optional<ProbeReport> parseProbeReport(QByteArrayView line);

// What $# says, gathered line by line. A malformed line, a repeated offset or tool (the first one stands) and
// tools beyond kMaxTools are refused and counted: a report with refusals is not to be trusted whole.
struct ParameterReport
{
    QMap<QString, AxisValues> workOffsets;
    std::map<int, ToolEntry> tools;
    std::optional<AxisValues> toolLengthOffset; // [TLO:…], the offset in force
    std::optional<ProbeReport> probe; // [PRB:…]
    std::optional<double> toolLengthReference; // [TLR:z], present only while a reference is set
    int refusedLines = 0;

    // Whether the line was one of $#'s and taken.
    bool addLine(QByteArrayView line);
};

enum class State { Unknown, Idle, Run, Hold, Jog, Alarm, Door, Check, Home, Sleep, Tool };

// "<Idle|MPos:0.000,0.000,-72.000|Bf:100,1023|FS:0,0|Pn:P|WCO:0.000,0.000,-12.345|A:|T:3|TLR:0>". grblHAL
// sends WCO, T and TLR only now and then (when they change, and every few reports): absent here means not
// said in this report, not zero.
struct StatusReport
{
    State state = State::Unknown;
    QString stateName; // as the controller wrote it, without the substate ("Hold")
    std::optional<int> substate; // Hold:n, Door:n, Run:n, Alarm:n (the alarm, when the controller says it)
    std::optional<AxisValues> machinePosition; // MPos
    std::optional<AxisValues> workPosition; // WPos
    std::optional<AxisValues> workCoordinateOffset; // WCO, including the tool length offset in force
    std::optional<int> tool; // T
    std::optional<bool> toolLengthReferenceSet; // TLR
    bool probeTriggered = false; // P in Pn
    QString pins; // Pn's letters ("P", "XZ", "D")

    [[nodiscard]] bool isAlarm() const { return state == State::Alarm; }
};

// Refuses a report without MPos or WPos, a known field written wrong, a field given twice, and a state word
// that is not a word; skips fields it does not know. An unknown state word is State::Unknown, never Idle.
[[nodiscard]] std::optional<StatusReport> parseStatusReport(QByteArrayView line);

enum class ReplyKind {
    Ok, // "ok": the line was done
    Error, // "error:N": the line was refused
    Alarm, // "ALARM:N": the controller halted; motion is refused (error:9) until $X or a reset
    Message, // "[MSG:…]"
    Status, // "<…>"
    Greeting, // "GrblHAL 1.1f ['$' or '$HELP' for help]": the controller (re)started, its tool and TLO
              // forgotten
    Report, // any other "[…]" ($#, $I, $G lines, [echo:…])
    Other, // settings lines ($130=300.000), blank lines, garbage
};

struct Reply
{
    ReplyKind kind = ReplyKind::Other;
    std::optional<int> code; // error:N and ALARM:N; empty when the number is missing or not a number
};

[[nodiscard]] Reply classifyReply(QByteArrayView line);
// Whether the line ends the controller's answer to a command line ("ok" or "error:N"). ALARM:N does not: the
// probing line that raised it is still answered ("ALARM:5", "[PRB:…:0]", "ok"; seen on grblHAL).
[[nodiscard]] bool endsCommand(QByteArrayView line);
// The text of "[MSG:Caution: Unlocked]", or nothing when the line is not a message.
[[nodiscard]] std::optional<QString> parseMessage(QByteArrayView line);

// What ALARM:N means and what to do, in an operator's words; a general sentence for numbers Toffee does not
// know.
[[nodiscard]] QString alarmMeaning(int alarm);
// What error:N means and what to do, likewise.
[[nodiscard]] QString errorMeaning(int error);

} // namespace Toffee::GrblHal
