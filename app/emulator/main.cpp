// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-emulator: a Carvera on a pseudo-terminal, for QSerialPort, toffee-cli --port, or a terminal program.
#include <cmath>
#include <cstdio>
#include <limits>

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QTextStream>

#include "model/textparsing.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/emulator/ptyserver.h"

using namespace Qt::StringLiterals;
using Toffee::CarveraEmulator;

namespace {

// "2=44.312" into (2, 44.312).
std::optional<std::pair<int, double>> toolValue(const QString &text)
{
    const auto parts = text.split(u'=');
    if (parts.size() != 2)
        return std::nullopt;
    const auto tool = Toffee::parseInteger(parts.at(0).toUtf8());
    const auto value = Toffee::parseDecimal(parts.at(1).toUtf8());
    if (!tool || !value)
        return std::nullopt;
    return std::pair { int(*tool), *value };
}

std::optional<CarveraEmulator::Fault> faultFromName(const QString &name)
{
    if (name == u"drop-ok")
        return CarveraEmulator::Fault::DropOk;
    if (name == u"no-answer")
        return CarveraEmulator::Fault::NoAnswer;
    if (name == u"garble")
        return CarveraEmulator::Fault::Garble;
    if (name == u"close")
        return CarveraEmulator::Fault::CloseLink;
    if (name == u"fail-probe")
        return CarveraEmulator::Fault::FailProbe;
    if (name.startsWith(u"delay:"))
        return CarveraEmulator::Fault::Delay;
    if (name.startsWith(u"break:"))
        return CarveraEmulator::Fault::BreakTool;
    return std::nullopt;
}

int usageError(const QString &message)
{
    QTextStream(stderr) << "toffee-emulator: " << message << '\n';
    return 2;
}

// The command line's options, each once.
struct Options
{
    static constexpr int kProbeMs = CarveraEmulator::realisticTiming().probeMs;
    static constexpr int kChangeMs = CarveraEmulator::realisticTiming().changeMs;

    QCommandLineOption link { u"link"_s, u"Also make a symbolic link to the device at PATH."_s, u"PATH"_s };
    QCommandLineOption tool { u"tool"_s, u"The physical length of tool N in mm (repeatable)."_s,
        u"N=LENGTH"_s };
    QCommandLineOption broken { u"break-tool"_s, u"Tool N is MM shorter than its length (repeatable)."_s,
        u"N=MM"_s };
    QCommandLineOption probeMs { u"probe-ms"_s,
        u"How long a probing cycle takes (default %1)."_s.arg(kProbeMs), u"MS"_s, QString::number(kProbeMs) };
    QCommandLineOption changeMs { u"change-ms"_s,
        u"How long a rack change takes before the new tool is measured (default %1)."_s.arg(kChangeMs),
        u"MS"_s, QString::number(kChangeMs) };
    QCommandLineOption firmware { u"firmware"_s,
        u"The firmware to answer as: community or stock (default community)."_s, u"NAME"_s, u"community"_s };
    QCommandLineOption slotFile { u"slots"_s,
        u"The rack's slots from a custom_tool_slots.txt (`number x y [z]` a line) instead of the C1's T1-T6."_s,
        u"FILE"_s };
    QCommandLineOption repeatability { u"repeatability"_s,
        u"How far apart repeated measurements of a tool trigger, in mm (default 0)."_s, u"MM"_s, u"0"_s };
    QCommandLineOption moveMs { u"move-ms"_s, u"How long any other command takes (default 0)."_s, u"MS"_s,
        u"0"_s };
    QCommandLineOption reference { QStringList { u"reference"_s, u"fixed-reference"_s },
        u"The reference tool MCS Z the machine is calibrated with (default %1, a C1's factory calibration)."_s
            .arg(CarveraEmulator::kFactoryReferenceMz),
        u"MZ"_s };
    QCommandLineOption notHomed { u"not-homed"_s, u"Start unhomed: probing halts until $H."_s };
    QCommandLineOption emptyRack {
        u"empty-rack"_s,
        u"The rack's slots hold no tools: a pick halts (\"Unexpected tool absence\"), as on the test peer."_s
    };
    QCommandLineOption spindle { u"spindle"_s, u"The tool in the spindle at start (default 1; -1 empty)."_s,
        u"N"_s };
    QCommandLineOption halted { u"halted"_s, u"Start halted with this reason (1-16)."_s, u"REASON"_s };
    QCommandLineOption fault { u"fault"_s,
        u"A one-shot fault: drop-ok, no-answer, garble, close, fail-probe, delay:MS or break:MM, "
        u"optionally @PREFIX to hit the first command starting with PREFIX (repeatable)."_s,
        u"KIND[@PREFIX]"_s };

    void addTo(QCommandLineParser &parser) const
    {
        parser.addOptions({ link, tool, broken, probeMs, changeMs, moveMs, firmware, slotFile, repeatability,
            reference, notHomed, emptyRack, spindle, halted, fault });
    }
};

// What is wrong with an option, or nothing.
using Problem = std::optional<QString>;

Problem configureTools(CarveraEmulator &emulator, const QCommandLineParser &parser, const Options &o)
{
    for (const QString &value : parser.values(o.tool)) {
        const auto tv = toolValue(value);
        if (!tv)
            return u"--tool %1: write N=LENGTH, e.g. 3=52.5."_s.arg(value);
        emulator.setToolLength(tv->first, tv->second);
    }
    for (const QString &value : parser.values(o.broken)) {
        const auto tv = toolValue(value);
        if (!tv)
            return u"--break-tool %1: write N=MM, e.g. 2=0.5."_s.arg(value);
        emulator.breakTool(tv->first, tv->second);
    }
    return std::nullopt;
}

Problem configureMachine(CarveraEmulator &emulator, const QCommandLineParser &parser, const Options &o)
{
    const auto probe = Toffee::parseInteger(parser.value(o.probeMs).toUtf8());
    const auto move = Toffee::parseInteger(parser.value(o.moveMs).toUtf8());
    const auto change = Toffee::parseInteger(parser.value(o.changeMs).toUtf8());
    constexpr qint64 kMaxMs = std::numeric_limits<int>::max();
    for (const auto &ms : { probe, move, change }) {
        if (!ms || *ms < 0 || *ms > kMaxMs)
            return u"--probe-ms, --move-ms and --change-ms take milliseconds."_s;
    }
    emulator.setTiming({ int(*probe), int(*move), int(*change) });
    if (parser.isSet(o.reference)) {
        const auto mz = Toffee::parseDecimal(parser.value(o.reference).toUtf8());
        if (!mz || std::fabs(*mz) > 1000.0)
            return u"--reference takes an MCS Z in mm."_s;
        emulator.setReference(*mz);
    }
    emulator.setHomed(!parser.isSet(o.notHomed));
    emulator.setRackEmpty(parser.isSet(o.emptyRack));
    if (parser.isSet(o.spindle)) {
        const auto tool = Toffee::parseInteger(parser.value(o.spindle).toUtf8());
        if (!tool || *tool < -1 || *tool > 999999)
            return u"--spindle takes a tool number, or -1 for an empty spindle."_s;
        emulator.setToolInSpindle(int(*tool));
    }
    if (parser.isSet(o.halted)) {
        const auto reason = Toffee::parseInteger(parser.value(o.halted).toUtf8());
        if (!reason || *reason < 1)
            return u"--halted takes a halt reason, e.g. 3."_s;
        emulator.halt(int(*reason));
    }
    return std::nullopt;
}

Problem configureFirmware(CarveraEmulator &emulator, const QCommandLineParser &parser, const Options &o)
{
    const QString firmware = parser.value(o.firmware);
    if (firmware != u"community" && firmware != u"stock")
        return u"--firmware %1: use community or stock."_s.arg(firmware);
    emulator.setFirmware(
        firmware == u"stock" ? CarveraEmulator::Firmware::Stock : CarveraEmulator::Firmware::Community);
    const auto repeatability = Toffee::parseDecimal(parser.value(o.repeatability).toUtf8());
    if (!repeatability || *repeatability < 0 || *repeatability > 1.0)
        return u"--repeatability takes millimetres, 0 to 1."_s;
    emulator.setRepeatability(*repeatability);
    if (!parser.isSet(o.slotFile))
        return std::nullopt;
    const QString path = parser.value(o.slotFile);
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return u"--slots %1: %2"_s.arg(path, file.errorString());
    auto rack = CarveraEmulator::parseToolSlots(file.readAll());
    if (!rack) {
        Toffee::Error error = rack.error();
        error.file = path;
        return u"--slots "_s + error.text();
    }
    emulator.setRack(rack.takeValue());
    return std::nullopt;
}

Problem configureFaults(CarveraEmulator &emulator, const QCommandLineParser &parser, const Options &o)
{
    for (const QString &value : parser.values(o.fault)) {
        const QString kind = value.section(u'@', 0, 0);
        const QString prefix = value.contains(u'@') ? value.section(u'@', 1) : QString();
        const auto f = faultFromName(kind);
        const qsizetype colon = kind.indexOf(u':');
        const auto amount
            = colon < 0 ? std::optional<double>(0.0) : Toffee::parseDecimal(kind.mid(colon + 1).toUtf8());
        if (!f || !amount)
            return u"--fault %1: use drop-ok, no-answer, garble, close, fail-probe, delay:MS or "
                   u"break:MM."_s.arg(value);
        emulator.injectFault(*f, prefix.toUtf8(), *amount);
    }
    return std::nullopt;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(u"toffee-emulator"_s);
    QCoreApplication::setApplicationVersion(QStringLiteral(TOFFEE_VERSION));
    QCommandLineParser parser;
    parser.setApplicationDescription(
        u"A Carvera controller on a pseudo-terminal. Prints the device path, then "
        u"serves until stopped."_s);
    parser.addHelpOption();
    parser.addVersionOption();
    const Options options;
    options.addTo(parser);
    parser.process(app);

    CarveraEmulator emulator;
    for (auto configure : { configureTools, configureMachine, configureFirmware, configureFaults }) {
        if (const Problem problem = configure(emulator, parser, options))
            return usageError(*problem);
    }
    Toffee::PtyServer server(&emulator, parser.value(options.link));
    QObject::connect(&server, &Toffee::PtyServer::deviceChanged, &app, [](const QString &path) {
        std::printf("%s\n", qPrintable(path));
        std::fflush(stdout);
    });
    if (!server.start())
        return usageError(server.errorString());
    if (!server.errorString().isEmpty())
        QTextStream(stderr) << "toffee-emulator: " << server.errorString() << '\n';
    return QCoreApplication::exec();
}
