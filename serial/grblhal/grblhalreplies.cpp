// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/grblhal/grblhalreplies.h"

#include <algorithm>
#include <cmath>

#include <QList>

#include "model/limits.h"
#include "model/textparsing.h"

using namespace Qt::StringLiterals;

namespace Toffee::GrblHal {

namespace {

bool plausible(double millimetres)
{
    return std::isfinite(millimetres) && std::fabs(millimetres) <= kMaxMachineMillimetres;
}

// The line without its line end, or empty when it is too long to be grblHAL's.
QByteArrayView bounded(QByteArrayView line)
{
    return line.size() > kMaxLineLength ? QByteArrayView() : line.trimmed();
}

// The text between "[NAME:" and the closing "]", or nothing.
std::optional<QByteArrayView> bracketBody(QByteArrayView line, QByteArrayView name)
{
    line = bounded(line);
    if (line.size() < name.size() + 3 || line.front() != '[' || line.back() != ']'
        || !line.sliced(1).startsWith(name) || line.at(name.size() + 1) != ':')
        return std::nullopt;
    return line.sliced(name.size() + 2, line.size() - name.size() - 3);
}

std::optional<int> boundedInteger(QByteArrayView text, qint64 min, qint64 max)
{
    const auto value = parseInteger(text);
    if (!value || *value < min || *value > max)
        return std::nullopt;
    return int(*value);
}

std::optional<double> plausibleDecimal(QByteArrayView text)
{
    const auto value = parseDecimal(text);
    if (!value || !plausible(*value))
        return std::nullopt;
    return value;
}

bool isPrintable(QByteArrayView text)
{
    for (char c : text) {
        if (uchar(c) < 0x20 || c == 0x7f)
            return false;
    }
    return true;
}

bool isWord(QByteArrayView text, qsizetype maxLength)
{
    if (text.isEmpty() || text.size() > maxLength)
        return false;
    for (char c : text) {
        if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')))
            return false;
    }
    return true;
}

// Text for people: valid UTF-8 without control characters, at most maxChars characters.
std::optional<QString> boundedText(QByteArrayView bytes, qsizetype maxChars)
{
    if (!isPrintable(bytes))
        return std::nullopt;
    auto text = decodeUtf8(bytes);
    if (!text || text->size() > maxChars)
        return std::nullopt;
    return text;
}

} // namespace

std::optional<AxisValues> parseAxisValues(QByteArrayView text)
{
    if (text.count(',') >= kMaxAxes)
        return std::nullopt;
    AxisValues axes;
    for (QByteArrayView part : splitView(text, ',')) {
        const auto value = plausibleDecimal(part);
        if (!value)
            return std::nullopt;
        axes.values[size_t(axes.count++)] = *value;
    }
    if (axes.count < kMinAxes)
        return std::nullopt;
    return axes;
}

bool BuildInfoBuilder::addLine(QByteArrayView line)
{
    const QByteArrayView text = line.size() > kMaxLineLength ? line.first(kMaxLineLength) : line.trimmed();
    const auto refuse = [this] {
        ++m_refused;
        return false;
    };
    // A repeated line is refused: the first one stands.
    const auto once = [&refuse](bool &seen) {
        if (seen)
            return refuse();
        seen = true;
        return true;
    };
    if (text.startsWith("[VER:")) {
        // "1.1f.20260817:" and the build's name, which may itself hold colons.
        const auto body = bracketBody(line, "VER");
        const qsizetype colon = body ? body->indexOf(':') : -1;
        const QByteArrayView version = colon < 0 ? QByteArrayView() : body->first(colon);
        const auto name = colon < 0 ? std::nullopt : boundedText(body->sliced(colon + 1), kMaxNameLength);
        if (version.isEmpty() || version.size() > 32 || !isPrintable(version) || !name)
            return refuse();
        if (!once(m_seenVersion))
            return false;
        m_info.version = QString::fromLatin1(version);
        m_info.buildName = *name;
        return true;
    }
    if (text.startsWith("[OPT:")) {
        // "VNML+,100,1024": options, planner blocks, receive buffer; grblHAL adds the axes and the tools.
        const auto body = bracketBody(line, "OPT");
        const QList<QByteArrayView> fields = body ? splitView(*body, ',') : QList<QByteArrayView>();
        if (fields.size() < 3 || fields.size() > 8 || fields.front().size() > 64
            || !isPrintable(fields.front()))
            return refuse();
        for (qsizetype i = 1; i < fields.size(); ++i) {
            if (!boundedInteger(fields.at(i), 0, Limits::kMaxToolNumber))
                return refuse();
        }
        if (!once(m_seenOptions))
            return false;
        m_info.toolTableSize
            = fields.size() >= 5 ? *boundedInteger(fields.back(), 0, Limits::kMaxToolNumber) : 0;
        return true;
    }
    if (text.startsWith("[NEWOPT:")) {
        const auto body = bracketBody(line, "NEWOPT");
        if (!body || !isPrintable(*body))
            return refuse();
        bool toolChange = false;
        bool atc = false;
        for (QByteArrayView option : splitView(*body, ',')) {
            if (option == "TC")
                toolChange = true;
            else if (option.startsWith("ATC="))
                toolChange = atc = true;
        }
        if (!once(m_seenNewOptions))
            return false;
        m_info.toolChange = toolChange;
        m_info.automaticToolChanger = atc;
        return true;
    }
    if (text.startsWith("[FIRMWARE:")) {
        const auto body = bracketBody(line, "FIRMWARE");
        if (!body || !isWord(*body, 32))
            return refuse();
        if (!once(m_seenFirmware))
            return false;
        m_info.firmware = QString::fromLatin1(*body);
        return true;
    }
    if (text.startsWith("[AXS:")) {
        const auto body = bracketBody(line, "AXS");
        const qsizetype colon = body ? body->indexOf(':') : -1;
        const auto count = colon < 0 ? std::nullopt : boundedInteger(body->first(colon), kMinAxes, kMaxAxes);
        const QByteArrayView letters = colon < 0 ? QByteArrayView() : body->sliced(colon + 1);
        if (!count || letters.size() != *count || !isWord(letters, kMaxAxes))
            return refuse();
        if (!once(m_seenAxes))
            return false;
        m_info.axes = QString::fromLatin1(letters);
        return true;
    }
    return false;
}

std::optional<ToolEntry> parseToolEntry(QByteArrayView line)
{
    // "[T:n|x,y,z|radius|6,0,0|name]" or with "|pocket" after the name (report.c). A name holding "|" (which
    // grblHAL does not forbid) cannot be told from a pocket: such a line is refused.
    const auto body = bracketBody(line, "T");
    if (!body)
        return std::nullopt;
    const QList<QByteArrayView> parts = splitView(*body, '|');
    if (parts.size() < 5 || parts.size() > 6)
        return std::nullopt;
    const auto number = boundedInteger(parts.at(0), Limits::kMinToolNumber, Limits::kMaxToolNumber);
    const auto offset = parseAxisValues(parts.at(1));
    const auto radius = plausibleDecimal(parts.at(2));
    const auto name = boundedText(parts.at(4), kMaxNameLength);
    if (!number || !offset || !radius || !name || parts.at(3).size() > 32 || !isPrintable(parts.at(3)))
        return std::nullopt;
    ToolEntry tool { *number, *offset, *radius, *name, std::nullopt };
    if (parts.size() == 6) {
        tool.pocket = boundedInteger(parts.at(5), Limits::kMinPocket, Limits::kMaxPocket);
        if (!tool.pocket)
            return std::nullopt;
    }
    return tool;
}

std::optional<WorkOffset> parseWorkOffset(QByteArrayView line)
{
    static constexpr std::array<QByteArrayView, 12> kNames { "G54", "G55", "G56", "G57", "G58", "G59",
        "G59.1", "G59.2", "G59.3", "G28", "G30", "G92" };
    line = bounded(line);
    const qsizetype colon = line.indexOf(':');
    if (colon < 2 || line.front() != '[' || line.back() != ']')
        return std::nullopt;
    const QByteArrayView name = line.sliced(1, colon - 1);
    if (std::find(kNames.begin(), kNames.end(), name) == kNames.end())
        return std::nullopt;
    QByteArrayView values = line.sliced(colon + 1, line.size() - colon - 2);
    // A build with rotation adds ":degrees" to G54-G59.3.
    if (const qsizetype rotation = values.indexOf(':'); rotation >= 0) {
        if (!parseDecimal(values.sliced(rotation + 1)))
            return std::nullopt;
        values = values.first(rotation);
    }
    const auto axes = parseAxisValues(values);
    if (!axes)
        return std::nullopt;
    return WorkOffset { QString::fromLatin1(name), *axes };
}

std::optional<AxisValues> parseToolLengthOffset(QByteArrayView line)
{
    const auto body = bracketBody(line, "TLO");
    if (!body)
        return std::nullopt;
    if (!body->contains(',')) {
        const auto z = plausibleDecimal(*body);
        if (!z)
            return std::nullopt;
        AxisValues axes;
        axes.count = kMinAxes;
        axes.values[2] = *z;
        return axes;
    }
    return parseAxisValues(*body);
}

std::optional<ProbeReport> parseProbeReport(QByteArrayView line)
{
    const auto body = bracketBody(line, "PRB");
    if (!body)
        return std::nullopt;
    const qsizetype colon = body->lastIndexOf(':');
    if (colon < 0)
        return std::nullopt;
    const QByteArrayView flag = body->sliced(colon + 1);
    const auto position = parseAxisValues(body->first(colon));
    if (!position || (flag != "0" && flag != "1"))
        return std::nullopt;
    return ProbeReport { *position, flag == "1" };
}

bool ParameterReport::addLine(QByteArrayView line)
{
    const QByteArrayView text = bounded(line);
    const auto refuse = [this] {
        ++refusedLines;
        return false;
    };
    if (text.startsWith("[T:")) {
        const auto tool = parseToolEntry(text);
        if (!tool || int(tools.size()) >= kMaxTools || tools.count(tool->number))
            return refuse();
        tools.emplace(tool->number, *tool);
        return true;
    }
    if (text.startsWith("[TLO:")) {
        const auto tlo = parseToolLengthOffset(text);
        if (!tlo || toolLengthOffset)
            return refuse();
        toolLengthOffset = tlo;
        return true;
    }
    if (text.startsWith("[PRB:")) {
        const auto prb = parseProbeReport(text);
        if (!prb || probe)
            return refuse();
        probe = prb;
        return true;
    }
    if (const auto body = bracketBody(text, "TLR")) {
        const auto z = plausibleDecimal(*body);
        if (!z || toolLengthReference)
            return refuse();
        toolLengthReference = z;
        return true;
    }
    if (text.startsWith("[G5") || text.startsWith("[G28:") || text.startsWith("[G30:")
        || text.startsWith("[G92:")) {
        if (text.startsWith("[G51:"))
            return false; // the scaling in force, not an offset
        const auto offset = parseWorkOffset(text);
        if (!offset || workOffsets.contains(offset->name))
            return refuse();
        workOffsets.insert(offset->name, offset->values);
        return true;
    }
    if (line.size() > kMaxLineLength && line.startsWith('['))
        return refuse();
    return false;
}

namespace {

struct StateName
{
    QByteArrayView name;
    State state;
};

constexpr std::array<StateName, 10> kStates { { { "Idle", State::Idle }, { "Run", State::Run },
    { "Hold", State::Hold }, { "Jog", State::Jog }, { "Alarm", State::Alarm }, { "Door", State::Door },
    { "Check", State::Check }, { "Home", State::Home }, { "Sleep", State::Sleep },
    { "Tool", State::Tool } } };

} // namespace

std::optional<StatusReport> parseStatusReport(QByteArrayView line)
{
    line = bounded(line);
    if (line.size() < 3 || line.front() != '<' || line.back() != '>')
        return std::nullopt;
    const QList<QByteArrayView> fields = splitView(line.sliced(1, line.size() - 2), '|');
    StatusReport status;
    {
        QByteArrayView word = fields.front();
        if (const qsizetype colon = word.indexOf(':'); colon >= 0) {
            status.substate = boundedInteger(word.sliced(colon + 1), 0, 999);
            if (!status.substate)
                return std::nullopt;
            word = word.first(colon);
        }
        if (!isWord(word, 16))
            return std::nullopt;
        status.stateName = QString::fromLatin1(word);
        for (const StateName &known : kStates) {
            if (known.name == word)
                status.state = known.state;
        }
    }
    enum Seen { MPos = 1, WPos = 2, Wco = 4, Tool = 8, Tlr = 16, Pins = 32 };
    int seen = 0;
    const auto first = [&seen](Seen field) {
        const bool again = seen & field;
        seen |= field;
        return !again;
    };
    for (qsizetype i = 1; i < fields.size(); ++i) {
        const QByteArrayView field = fields.at(i);
        const qsizetype colon = field.indexOf(':');
        const QByteArrayView name = colon < 0 ? field : field.first(colon);
        const QByteArrayView value = colon < 0 ? QByteArrayView() : field.sliced(colon + 1);
        if (name == "MPos" || name == "WPos" || name == "WCO") {
            const Seen which = name == "MPos" ? MPos : (name == "WPos" ? WPos : Wco);
            const auto axes = parseAxisValues(value);
            if (!axes || !first(which))
                return std::nullopt;
            (which == MPos ? status.machinePosition
                           : (which == WPos ? status.workPosition : status.workCoordinateOffset))
                = axes;
        } else if (name == "T") {
            status.tool = boundedInteger(value, Limits::kMinToolNumber, Limits::kMaxToolNumber);
            if (!status.tool || !first(Tool))
                return std::nullopt;
        } else if (name == "TLR") {
            if ((value != "0" && value != "1") || !first(Tlr))
                return std::nullopt;
            status.toolLengthReferenceSet = value == "1";
        } else if (name == "Pn") {
            if (!isWord(value, 32) || !first(Pins))
                return std::nullopt;
            status.pins = QString::fromLatin1(value);
            status.probeTriggered = value.contains('P');
        }
    }
    if (!status.machinePosition && !status.workPosition)
        return std::nullopt;
    return status;
}

Reply classifyReply(QByteArrayView line)
{
    line = bounded(line);
    const auto code = [&line](qsizetype from) {
        return boundedInteger(line.sliced(from), 0, 999);
    };
    if (line == "ok")
        return { ReplyKind::Ok, std::nullopt };
    if (line.startsWith("error:"))
        return { ReplyKind::Error, code(6) };
    if (line.startsWith("ALARM:"))
        return { ReplyKind::Alarm, code(6) };
    if (line.startsWith("[MSG:") && line.endsWith(']'))
        return { ReplyKind::Message, std::nullopt };
    if (line.startsWith('<') && line.endsWith('>'))
        return { ReplyKind::Status, std::nullopt };
    if ((line.startsWith("GrblHAL ") || line.startsWith("Grbl ")) && line.contains("['$'"))
        return { ReplyKind::Greeting, std::nullopt };
    if (line.startsWith('[') && line.endsWith(']'))
        return { ReplyKind::Report, std::nullopt };
    return { ReplyKind::Other, std::nullopt };
}

bool endsCommand(QByteArrayView line)
{
    const ReplyKind kind = classifyReply(line).kind;
    return kind == ReplyKind::Ok || kind == ReplyKind::Error;
}

std::optional<QString> parseMessage(QByteArrayView line)
{
    const auto body = bracketBody(line, "MSG");
    if (!body)
        return std::nullopt;
    return boundedText(*body, kMaxLineLength);
}

} // namespace Toffee::GrblHal
