// SPDX-License-Identifier: GPL-3.0-or-later
// An emulator behind a transport, a link and a session: the whole machine stack. In process (no port), or
// over a real TCP socket on 127.0.0.1 to the emulator's own TCP server, in plain text or in Makera's frames,
// found by the transport as on a machine.
#pragma once

#include <memory>

#include <QEventLoop>
#include <QHostAddress>
#include <QTest>
#include <QTimer>

#include "serial/carvera/machinesession.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/emulator/emulatortransport.h"
#include "serial/emulator/tcpserver.h"
#include "serial/machine/machinelink.h"
#include "serial/transport/tcptransport.h"

namespace Toffee::Test {

struct SessionHarness
{
    enum class Wire { InProcess, TcpText, TcpFramed };

    CarveraEmulator emulator;
    std::unique_ptr<TcpServer> server;
    std::unique_ptr<LineTransport> transport;
    MachineLink link;
    MachineSession session { &link };
    QList<QByteArray> sent; // every command line the link sent

    explicit SessionHarness(Wire wire = Wire::InProcess)
        : server(wire == Wire::InProcess ? nullptr : serve(emulator, wire == Wire::TcpFramed))
        , transport(server ? std::unique_ptr<LineTransport>(std::make_unique<TcpTransport>(
                        TcpTransport::Address { QStringLiteral("127.0.0.1"), server->port() }))
                           : std::make_unique<EmulatorTransport>(&emulator))
        , link(transport.get())
    {
        QObject::connect(
            &link, &MachineLink::lineSent, &link, [this](const QByteArray &l) { sent.append(l); });
    }

    // Runs one operation to its end (or gives up after `ms`, which no operation should need).
    SessionResult run(const std::function<void(MachineSession::Done)> &operation, int ms = 10000)
    {
        // A local event loop, not QTest::qWaitFor: that sleeps 10 ms between its turns, which over a socket
        // is 10 ms a hop, more than a fault's scaled-down limit.
        std::optional<SessionResult> result;
        QEventLoop loop;
        QTimer limit;
        limit.setSingleShot(true);
        QObject::connect(&limit, &QTimer::timeout, &loop, &QEventLoop::quit);
        operation([&result, &loop](const SessionResult &r) {
            result = r;
            loop.quit();
        });
        if (!result) {
            limit.start(ms);
            loop.exec();
        }
        if (!result) {
            SessionResult hung;
            hung.outcome = SessionResult::Outcome::LinkFailure;
            hung.message = QStringLiteral("TEST: the operation never finished");
            return hung;
        }
        return *result;
    }

    SessionResult connect()
    {
        return run([this](MachineSession::Done done) { session.connectToMachine(done); });
    }

private:
    static std::unique_ptr<TcpServer> serve(CarveraEmulator &emulator, bool framed)
    {
        auto server = std::make_unique<TcpServer>(&emulator, framed);
        if (!server->listen(QHostAddress::LocalHost, 0))
            qFatal("cannot listen on 127.0.0.1: %s", qPrintable(server->errorString()));
        return server;
    }
};

} // namespace Toffee::Test
