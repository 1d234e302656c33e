// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-emulator: a Carvera on a pseudo-terminal, for QSerialPort, toffee-cli --port, or a terminal program.
#include <cstdio>

#include <QCommandLineParser>
#include <QCoreApplication>
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
    QCommandLineOption link { u"link"_s, u"Also make a symbolic link to the device at PATH."_s, u"PATH"_s };
    QCommandLineOption tool { u"tool"_s, u"The physical length of tool N in mm (repeatable)."_s,
        u"N=LENGTH"_s };
    QCommandLineOption broken { u"break-tool"_s, u"Tool N is MM shorter than its length (repeatable)."_s,
        u"N=MM"_s };
    QCommandLineOption probeMs { u"probe-ms"_s, u"How long a probing cycle takes (default 2000)."_s, u"MS"_s,
        u"2000"_s };
    QCommandLineOption moveMs { u"move-ms"_s, u"How long any other command takes (default 0)."_s, u"MS"_s,
        u"0"_s };
    QCommandLineOption fixedReference { u"fixed-reference"_s,
        u"Firmware 2.1.0c: the reference tool MCS Z is configured, not probed."_s, u"MZ"_s };
    QCommandLineOption notHomed { u"not-homed"_s, u"Start unhomed: probing halts until $H."_s };
    QCommandLineOption halted { u"halted"_s, u"Start halted with this reason (1-16)."_s, u"REASON"_s };
    QCommandLineOption fault { u"fault"_s,
        u"A one-shot fault: drop-ok, no-answer, garble, close, fail-probe, delay:MS or break:MM, "
        u"optionally @PREFIX to hit the first command starting with PREFIX (repeatable)."_s,
        u"KIND[@PREFIX]"_s };

    void addTo(QCommandLineParser &parser) const
    {
        parser.addOptions({ link, tool, broken, probeMs, moveMs, fixedReference, notHomed, halted, fault });
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
    if (!probe || !move || *probe < 0 || *move < 0)
        return u"--probe-ms and --move-ms take milliseconds."_s;
    emulator.setTiming({ int(*probe), int(*move) });
    if (parser.isSet(o.fixedReference)) {
        const auto mz = Toffee::parseDecimal(parser.value(o.fixedReference).toUtf8());
        if (!mz)
            return u"--fixed-reference takes an MCS Z in mm."_s;
        emulator.setProfile(CarveraEmulator::Profile::FixedReference, *mz);
    }
    emulator.setHomed(!parser.isSet(o.notHomed));
    if (parser.isSet(o.halted)) {
        const auto reason = Toffee::parseInteger(parser.value(o.halted).toUtf8());
        if (!reason || *reason < 1)
            return u"--halted takes a halt reason, e.g. 3."_s;
        emulator.halt(int(*reason));
    }
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
    QCommandLineParser parser;
    parser.setApplicationDescription(
        u"A Carvera controller on a pseudo-terminal. Prints the device path, then "
        u"serves until stopped."_s);
    parser.addHelpOption();
    const Options options;
    options.addTo(parser);
    parser.process(app);

    CarveraEmulator emulator;
    for (auto configure : { configureTools, configureMachine, configureFaults }) {
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
