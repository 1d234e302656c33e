// SPDX-License-Identifier: GPL-3.0-or-later
// An emulator behind the in-process transport, a link and a session: the whole serial stack, no port.
#pragma once

#include <QTest>

#include "serial/emulator/carveraemulator.h"
#include "serial/emulatortransport.h"
#include "serial/machinelink.h"
#include "serial/machinesession.h"

namespace Toffee::Test {

struct SessionHarness
{
    CarveraEmulator emulator;
    EmulatorTransport transport { &emulator };
    MachineLink link { &transport };
    MachineSession session { &link };
    QList<QByteArray> sent; // every command line the link sent

    SessionHarness()
    {
        QObject::connect(
            &link, &MachineLink::lineSent, &link, [this](const QByteArray &l) { sent.append(l); });
    }

    // Runs one operation to its end (or gives up after `ms`, which no operation should need).
    SessionResult run(const std::function<void(MachineSession::Done)> &operation, int ms = 10000)
    {
        std::optional<SessionResult> result;
        operation([&result](const SessionResult &r) { result = r; });
        if (!QTest::qWaitFor([&result] { return result.has_value(); }, ms)) {
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
};

} // namespace Toffee::Test
