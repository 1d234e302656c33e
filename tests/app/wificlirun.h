// SPDX-License-Identifier: GPL-3.0-or-later
// What tst_wificli.cpp and tst_wifidiscover.cpp share: a run's JSON, the emulator on a TCP port, the machines
// discover lists.
#pragma once

#include "serial/transport/beaconlistener.h"
#include "tests/support/processes.h"
#include "tests/support/silentlistener.h"
#include <QElapsedTimer>
#include <QHostAddress>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QUdpSocket>
#include <memory>

namespace Toffee::Test {

using namespace Qt::StringLiterals;

inline QJsonObject json(const Run &run)
{
    return QJsonDocument::fromJson(run.out.trimmed().split('\n').last()).object();
}

inline QString fixed3(const QJsonValue &v)
{
    return QString::number(v.toDouble(), 'f', 3);
}

// A UDP port nothing uses now (never 3333, where a real machine may be heard): the system picks it.
inline quint16 freeUdpPort()
{
    QUdpSocket socket;
    return socket.bind(QHostAddress::AnyIPv4, 0) ? socket.localPort() : 0;
}

// A TCP port on 127.0.0.1 where nothing listens.
inline quint16 closedTcpPort()
{
    QTcpServer server;
    return server.listen(QHostAddress::LocalHost, 0) ? server.serverPort() : 0;
}

// toffee-cli started and left to run, so that several runs, or a run and what the test sends meanwhile,
// overlap.
inline std::unique_ptr<QProcess> startCli(const QStringList &arguments)
{
    auto process = std::make_unique<QProcess>();
    process->start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"), arguments);
    return process;
}

// Its end (waited for unless it came already), and how long it took since `clock` started.
inline Run finish(QProcess &process, qint64 *elapsedMs = nullptr, const QElapsedTimer *clock = nullptr)
{
    Run run;
    if (process.state() != QProcess::NotRunning && !process.waitForFinished(60000)) {
        process.kill();
        process.waitForFinished();
        run.err = "TEST: toffee-cli did not finish";
        return run;
    }
    if (elapsedMs && clock)
        *elapsedMs = clock->elapsed();
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

// The machines a `discover --json` heard, by name.
inline QJsonArray machines(const Run &run)
{
    return json(run)[u"machines"_s].toArray();
}

} // namespace Toffee::Test
