// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-emulator: a Carvera on a pseudo-terminal, for QSerialPort, toffee-cli --port, or a terminal program;
// and with --listen on a TCP port too, as over Wi-Fi, announcing itself by its beacon with --announce.
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QTextStream>

#include "model/limits.h"
#include "model/textparsing.h"
#include "serial/emulator/beaconsender.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/emulator/ptyserver.h"
#include "serial/emulator/tcpserver.h"

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
    QCommandLineOption listen { u"listen"_s,
        u"Also serve the console on TCP, as over Wi-Fi: [HOST:]PORT (host 127.0.0.1 unless given; port 0 "
        u"takes a "
        u"free one). Prints \"tcp HOST:PORT\" after the device path."_s,
        u"[HOST:]PORT"_s };
    QCommandLineOption framed { u"framed"_s,
        u"Frame every byte as Makera's current firmware does (86 68 ... 55 AA), on the terminal and TCP "
        u"alike; "
        u"--firmware stock does it unless --plain."_s };
    QCommandLineOption plain { u"plain"_s,
        u"With --firmware stock: Makera's firmware before 1.0.4, in plain text, version 1.0.1 (the stock "
        u"firmware is otherwise its current one: framed, version 1.0.5)."_s };
    QCommandLineOption announce { u"announce"_s,
        u"Send the Wi-Fi beacon (NAME,IP,PORT,BUSY) once a second to UDP 127.0.0.1:PORT (a machine's is "
        u"3333); "
        u"needs --listen."_s,
        u"PORT"_s };
    QCommandLineOption name { u"name"_s, u"The machine's name in its beacon (default Carvera_Emulator)."_s,
        u"NAME"_s, u"Carvera_Emulator"_s };
    QCommandLineOption fault { u"fault"_s,
        u"A one-shot fault: drop-ok, no-answer, garble, close, fail-probe, delay:MS or break:MM, "
        u"optionally @PREFIX to hit the first command starting with PREFIX (repeatable)."_s,
        u"KIND[@PREFIX]"_s };

    void addTo(QCommandLineParser &parser) const
    {
        parser.addOptions({ link, tool, broken, probeMs, changeMs, moveMs, firmware, slotFile, repeatability,
            reference, notHomed, emptyRack, spindle, halted, listen, framed, plain, announce, name, fault });
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
        if (!tool || *tool < Toffee::Limits::kEmptySpindle || *tool > Toffee::Limits::kMaxToolNumber)
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

// --listen and --announce: the console on TCP, and the beacon that says where it is.
Problem serveNetwork(CarveraEmulator &emulator, const QCommandLineParser &parser, const Options &o,
    bool framed, std::unique_ptr<Toffee::TcpServer> &tcp, std::unique_ptr<Toffee::BeaconSender> &beacon)
{
    if (!parser.isSet(o.listen))
        return parser.isSet(o.announce) ? Problem(u"--announce needs --listen: the beacon says where the TCP "
                                                  u"console is."_s)
                                        : std::nullopt;
    const QString value = parser.value(o.listen);
    const QString host = value.contains(u':') ? value.section(u':', 0, -2) : u"127.0.0.1"_s;
    const auto port = Toffee::parseInteger(value.section(u':', -1).toUtf8());
    const QHostAddress address(host);
    if (!port || *port < 0 || *port > 65535 || address.isNull())
        return u"--listen %1: give [HOST:]PORT, such as 2222 or 127.0.0.1:0."_s.arg(value);
    tcp = std::make_unique<Toffee::TcpServer>(&emulator, framed);
    if (!tcp->listen(address, quint16(*port)))
        return u"--listen %1: %2"_s.arg(value, tcp->errorString());
    std::printf("tcp %s:%u\n", qPrintable(tcp->address().toString()), unsigned(tcp->port()));
    std::fflush(stdout);
    if (!parser.isSet(o.announce))
        return std::nullopt;
    const auto to = Toffee::parseInteger(parser.value(o.announce).toUtf8());
    if (!to || *to < 1 || *to > 65535)
        return u"--announce takes a UDP port, such as 3333."_s;
    const QString name = parser.value(o.name);
    Toffee::Beacon b { name,
        tcp->address() == QHostAddress::AnyIPv4 ? u"127.0.0.1"_s : tcp->address().toString(), tcp->port(),
        false };
    if (!Toffee::Beacon::parse(b.format()))
        return u"--name %1: a name of up to %2 printable characters, without commas."_s.arg(name).arg(
            Toffee::Beacon::kMaxNameLength);
    beacon = std::make_unique<Toffee::BeaconSender>(b, QHostAddress::LocalHost, quint16(*to));
    QObject::connect(
        tcp.get(), &Toffee::TcpServer::busyChanged, beacon.get(), &Toffee::BeaconSender::setBusy);
    beacon->start();
    return std::nullopt;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(u"toffee-emulator"_s);
    QCoreApplication::setApplicationVersion(QStringLiteral(TOFFEE_VERSION));
    QCommandLineParser parser;
    parser.setApplicationDescription(u"A Carvera controller on a pseudo-terminal (and with --listen on a TCP "
                                     u"port, as over Wi-Fi). Prints the "
                                     u"device path, then serves until stopped."_s);
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
    // Makera's current firmware frames every byte; --plain is the one before 1.0.4.
    const bool stock = parser.value(options.firmware) == u"stock";
    if (parser.isSet(options.plain) && (!stock || parser.isSet(options.framed)))
        return usageError(u"--plain goes with --firmware stock, and not with --framed."_s);
    const bool framed = parser.isSet(options.framed) || (stock && !parser.isSet(options.plain));
    if (framed && stock)
        emulator.setVersion(CarveraEmulator::kFramedStockVersion);
    Toffee::PtyServer server(&emulator, parser.value(options.link));
    server.setFramed(framed);
    QObject::connect(&server, &Toffee::PtyServer::deviceChanged, &app, [](const QString &path) {
        std::printf("%s\n", qPrintable(path));
        std::fflush(stdout);
    });
    if (!server.start())
        return usageError(server.errorString());
    if (!server.errorString().isEmpty())
        QTextStream(stderr) << "toffee-emulator: " << server.errorString() << '\n';
    std::unique_ptr<Toffee::TcpServer> tcp;
    std::unique_ptr<Toffee::BeaconSender> beacon;
    if (const Problem problem = serveNetwork(emulator, parser, options, framed, tcp, beacon))
        return usageError(*problem);
    return QCoreApplication::exec();
}
