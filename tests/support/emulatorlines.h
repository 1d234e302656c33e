// SPDX-License-Identifier: GPL-3.0-or-later
// Talking to an in-process CarveraEmulator line by line, as the emulator tests do.
#pragma once

#include <QTest>

#include "serial/emulator/carveraemulator.h"

namespace Toffee::Test {

// Sends one line and returns everything up to and including its "ok" or error (or what came in `ms`).
inline QList<QByteArray> command(CarveraEmulator &emulator, const QByteArray &line, int ms = 2000)
{
    QList<QByteArray> out;
    bool done = false;
    auto c = QObject::connect(&emulator, &CarveraEmulator::lineSent, &emulator, [&](const QByteArray &l) {
        out.append(l);
        done = done || l == "ok" || l.startsWith("error:");
    });
    emulator.receiveLine(line);
    if (!QTest::qWaitFor([&] { return done; }, ms))
        out.append("TEST: no terminator");
    QObject::disconnect(c);
    return out;
}

// The status report the emulator answers '?' with.
inline QByteArray status(CarveraEmulator &emulator)
{
    QByteArray report;
    auto c = QObject::connect(
        &emulator, &CarveraEmulator::lineSent, &emulator, [&](const QByteArray &l) { report = l; });
    emulator.receiveRealtime('?');
    QObject::disconnect(c);
    return report;
}

} // namespace Toffee::Test
