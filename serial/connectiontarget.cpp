// SPDX-License-Identifier: GPL-3.0-or-later
// A connection target's transport and controller, and its names: what MachineConnection makes for a target.
#include "serial/machineconnection.h"

#include "serial/carvera/machinesession.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/emulator/emulatortransport.h"
#include "serial/grblhal/grblhalcontroller.h"
#include "serial/linuxcnc/linuxcnccontroller.h"
#include "serial/transport/serialporttransport.h"
#include "serial/transport/tcptransport.h"

using namespace Qt::StringLiterals;

namespace Toffee {

std::unique_ptr<LineTransport> makeTransport(const ConnectionTarget &target)
{
    if (target.emulator) {
        auto transport = std::make_unique<EmulatorTransport>();
        CarveraEmulator *machine = transport->emulator();
        if (target.emulatorStock)
            machine->setFirmware(CarveraEmulator::Firmware::Stock);
        if (target.emulatorPaced)
            machine->setTiming(CarveraEmulator::realisticTiming());
        return transport;
    }
    // The transport's first question is harmless to every controller, and checks a forced protocol.
    const auto protocol = target.protocol;
    if (target.isNetwork()) {
        auto transport
            = std::make_unique<TcpTransport>(TcpTransport::Address { target.host, target.tcpPort });
        transport->setConnectTimeoutMs(target.timeoutMs);
        transport->setProtocol(protocol);
        // linuxcncrsh answers nothing before its hello: chosen, it is asked nothing first; not yet known, a
        // machine that answers nothing opens to be asked the hello.
        transport->setAsksFirst(target.controller != ControllerKind::LinuxCnc);
        transport->setOpensSilent(target.controller == ControllerKind::Auto);
        return transport;
    }
    auto transport = std::make_unique<SerialPortTransport>(target.port, target.baud);
    transport->setProtocol(protocol);
    return transport;
}

std::unique_ptr<MachineController> makeController(MachineLink *link, ControllerKind kind)
{
    if (kind == ControllerKind::GrblHal)
        return std::make_unique<GrblHalController>(link);
    if (kind == ControllerKind::LinuxCnc)
        return std::make_unique<LinuxCncController>(link);
    return std::make_unique<MachineSession>(link);
}

quint16 defaultTcpPort(ControllerKind kind)
{
    return kind == ControllerKind::LinuxCnc ? LinuxCnc::kDefaultPort : TcpTransport::kDefaultPort;
}

std::optional<ControllerKind> controllerKindFromName(const QString &name)
{
    for (const ControllerKind kind : controllerKinds()) {
        if (name == controllerKindName(kind))
            return kind;
    }
    return std::nullopt;
}

ControllerKind ConnectionTarget::knownController() const
{
    return emulator ? ControllerKind::Carvera : controller;
}

QString ConnectionTarget::name() const
{
    if (emulator)
        return u"emulator"_s;
    if (isNetwork())
        return TcpTransport::Address { host, tcpPort }.text();
    return port;
}

} // namespace Toffee
