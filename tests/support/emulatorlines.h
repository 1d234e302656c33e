// SPDX-License-Identifier: GPL-3.0-or-later
// Talking to an in-process CarveraEmulator line by line, as the emulator tests do.
#pragma once

#include <QTest>

#include "serial/carvera/carverareplies.h"
#include "serial/emulator/carveraemulator.h"

namespace Toffee::Test {

// Sends one line and returns its whole reply, ended as the firmware ends it (replyEndFor): "ok" or
// "error:", a script's "Done ATC" or, after a halt, the next "ok", `version`'s one line; a command that
// may say nothing ($X) gets 300 ms. What did not end in `ms` ends with "TEST: no terminator".
inline QList<QByteArray> command(CarveraEmulator &emulator, const QByteArray &line, int ms = 2000)
{
    const ReplyEnd end = replyEndFor(line);
    QList<QByteArray> out;
    bool done = false;
    bool halted = false;
    bool running = false; // a script said it starts
    auto c = QObject::connect(&emulator, &CarveraEmulator::lineSent, &emulator, [&](const QByteArray &l) {
        if (done || l.startsWith('<'))
            return;
        out.append(l);
        const ReplyKind kind = classifyReply(l);
        halted = halted || kind == ReplyKind::Alarm || kind == ReplyKind::HaltError;
        if (kind == ReplyKind::Error)
            done = true;
        else if (kind == ReplyKind::Ok)
            done = halted || end != ReplyEnd::Script || !running;
        else if (end == ReplyEnd::Line && !halted)
            done = true;
        else if (end == ReplyEnd::Script)
            done = isScriptDone(l) || (running = true, false);
    });
    emulator.receiveLine(line);
    const bool ended
        = end == ReplyEnd::Quiet ? (QTest::qWait(300), true) : QTest::qWaitFor([&] { return done; }, ms);
    if (!ended)
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
