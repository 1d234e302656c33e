// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli's machine options: which machine, and how it is reached (part of readMachineOptions).
#include <QHostAddress>

#include "app/cli/machineoptions.h"
#include "model/textparsing.h"
#include "serial/transport/serialporttransport.h"
#include "serial/transport/tcptransport.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

std::optional<double> decimalOption(const Invocation &call, const QString &name)
{
    return parseDecimal(call.option(name).toUtf8());
}

Result<void> choosePort(const Invocation &call, MachineOptions &)
{
    const int named = int(call.has(u"port"_s)) + int(call.has(u"host"_s)) + int(call.has(u"emulator"_s));
    if (named != 1)
        return Error { u"say which machine: --port DEVICE, --host HOST[:PORT] or --emulator."_s };
    return {};
}

Result<void> readTarget(const Invocation &call, MachineOptions &o)
{
    o.target = ConnectionTarget {};
    o.target.emulator = call.has(u"emulator"_s);
    o.target.port = call.option(u"port"_s);
    o.target.baud = SerialPortTransport::kDefaultBaud;
    if (call.has(u"protocol"_s)) {
        const auto protocol = StreamTransport::parseProtocol(call.option(u"protocol"_s));
        if (!protocol)
            return Error { u"--protocol must be auto, text or framed."_s };
        if (o.target.emulator)
            return Error { u"--protocol is for --port and --host: the built-in emulator has no wire."_s };
        o.target.protocol = *protocol;
    }
    if (call.has(u"controller"_s)) {
        const auto kind = controllerKindFromName(call.option(u"controller"_s).trimmed());
        if (!kind)
            return Error { u"--controller must be auto, carvera, grblhal or linuxcnc."_s };
        if (o.target.emulator && *kind != ControllerKind::Carvera && *kind != ControllerKind::Auto)
            return Error { u"the built-in emulator is a Carvera; %1 is reached with --port or --host."_s.arg(
                controllerKindTitle(*kind)) };
        if (*kind == ControllerKind::LinuxCnc && call.has(u"port"_s))
            return Error {
                u"LinuxCNC is reached over the network, through linuxcncrsh: give --host HOST[:PORT] "
                "(port 5007 when not given)."_s
            };
        o.target.controller = *kind;
    }
    if (call.has(u"ini"_s)) {
        if (o.target.controller != ControllerKind::LinuxCnc)
            return Error { u"--ini is LinuxCNC's INI file: give it with --controller linuxcnc."_s };
        o.target.linuxCncIni = call.option(u"ini"_s);
    }
    // linuxcncrsh's enable password: from the environment, never from the command line, where every user
    // of the computer could read it.
    o.target.enablePassword = qEnvironmentVariable("TOFFEE_LINUXCNC_PASSWORD").toUtf8();
    if (call.has(u"host"_s)) {
        const QString host = call.option(u"host"_s).trimmed();
        const auto address = TcpTransport::parseAddress(host, defaultTcpPort(o.target.controller));
        // A bare IPv6 address is refused, since its last group cannot be told from a port: say how to write
        // it.
        if (!address && QHostAddress(host).protocol() == QAbstractSocket::IPv6Protocol)
            return Error { address.error().message
                + u" An IPv6 address goes in brackets: [%1], or [%1]:PORT with a port."_s.arg(host) };
        if (!address)
            return address.error();
        o.target.host = address.value().host;
        o.target.tcpPort = address.value().port;
    }
    if (call.has(u"setter"_s)) {
        auto setter = ToolSetter::parse(call.option(u"setter"_s).trimmed());
        if (!setter)
            return Error { u"--setter: "_s + setter.error().message };
        o.target.setter = setter.value();
    }
    if (call.has(u"baud"_s)) {
        const auto b = parseInteger(call.option(u"baud"_s).toUtf8());
        if (!b || *b < 50 || *b > 4000000)
            return Error { u"--baud must be a baud rate such as 115200."_s };
        o.target.baud = int(*b);
    }
    if (call.has(u"timeout"_s)) {
        const auto t = decimalOption(call, u"timeout"_s);
        if (!t || *t <= 0 || *t > 3600)
            return Error { u"--timeout must be a number of seconds, above 0."_s };
        o.target.timeoutMs = int(*t * 1000);
    }
    return {};
}

} // namespace Toffee::Cli
