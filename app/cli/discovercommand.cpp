// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli discover: the Carveras heard on this computer's networks, by their Wi-Fi beacons.
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonObject>
#include <QTimer>

#include "app/cli/cli.h"
#include "model/textparsing.h"
#include "serial/transport/beaconlistener.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

int discoverMachines(Invocation &call)
{
    if (!call.arguments.isEmpty())
        return fail(call, u"discover takes no arguments."_s, BadInput);
    double seconds = 3.0; // a machine announces itself once a second
    if (call.has(u"seconds"_s)) {
        const auto s = parseDecimal(call.option(u"seconds"_s).toUtf8());
        if (!s || *s <= 0 || *s > 600)
            return fail(call, u"--seconds must be a number of seconds, above 0 and at most 600."_s, BadInput);
        seconds = *s;
    }
    quint16 port = Beacon::kDiscoveryPort;
    if (call.has(u"discovery-port"_s)) {
        const auto p = parseInteger(call.option(u"discovery-port"_s).toUtf8());
        if (!p || *p < 1 || *p > 65535)
            return fail(call, u"--discovery-port must be a UDP port, 1 to 65535."_s, BadInput);
        port = quint16(*p);
    }
    BeaconListener listener;
    if (!listener.listen(port))
        return fail(call,
            u"Cannot listen on UDP port %1 (%2): another program may hold it without sharing it. Close it, "
            u"or "
            "give another port with --discovery-port."_s.arg(port)
                .arg(listener.errorString()),
            LinkFailure);
    QEventLoop loop;
    // A precise timer: a coarse one may end 5 % early (4.75 s of 5).
    QTimer::singleShot(int(seconds * 1000), Qt::PreciseTimer, &loop, &QEventLoop::quit);
    loop.exec();

    const QList<BeaconListener::Machine> machines = listener.machines();
    if (call.json) {
        QJsonArray list;
        for (const BeaconListener::Machine &m : machines)
            list.append(QJsonObject { { u"name"_s, m.beacon.name }, { u"address"_s, m.beacon.address },
                { u"port"_s, int(m.beacon.port) }, { u"busy"_s, m.beacon.busy } });
        printJson(call, QJsonObject { { u"machines"_s, list }, { u"dropped"_s, listener.dropped() } });
    } else if (machines.isEmpty()) {
        call.out
            << u"No Carvera heard on UDP port %1 in %2 s. A machine announces itself once a second when "
               "its Wi-Fi is on: check that it is switched on and on this computer's network (or its own "
               "access point), and that no firewall blocks UDP port %1."_s.arg(port)
                   .arg(seconds)
            << Qt::endl;
    } else {
        for (const BeaconListener::Machine &m : machines) {
            call.out << m.beacon.name << "  " << m.beacon.address << ':' << m.beacon.port << "  "
                     << (m.beacon.busy ? u"busy: another program is connected to it"_s : u"free"_s)
                     << Qt::endl;
        }
    }
    if (listener.dropped() > 0)
        call.err
            << u"toffee-cli: %1 announcement(s) were not listed: a sender announced more than %2 names, or "
               "more than %3 machines were heard (a flood, or a misbehaving device). Each machine that "
               "announces itself from its own address is listed."_s.arg(listener.dropped())
                   .arg(BeaconListener::kMaxNamesPerSender)
                   .arg(BeaconListener::kMaxMachines)
            << Qt::endl;
    if (listener.ignored() > 0)
        call.err << u"toffee-cli: %1 datagram(s) on UDP port %2 were no Carvera's beacon and were ignored."_s
                        .arg(listener.ignored())
                        .arg(port)
                 << Qt::endl;
    return Success;
}

} // namespace Toffee::Cli
