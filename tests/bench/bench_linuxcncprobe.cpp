// SPDX-License-Identifier: GPL-3.0-or-later
// A probe's overhead in Toffee over LinuxCNC's own time (issue 37). LinuxCNC itself (TOFFEE_LINUXCNC_PEER, as the
// suite runs it) with linuxcncrsh on TCP, a tool on its simulated setter; each round, in turns:
//  - Toffee: LinuxCncController::probe() over MachineLink and a TcpTransport (the state read, the setter cycle
//    through MDI, the contact printed back, G10 L1 and G43 H written, the offset in force and tool.tbl read back),
//    timed from the call to its result;
//  - the yardstick: a raw client (a blocking QTcpSocket, after its own hello, echo off and enable) sending the
//    very lines Toffee sent in its first probe, each once the one before is answered (one line each), timed from
//    the first line to the last answer.
// Both pay LinuxCNC's motion, which is most of it; the difference is what Toffee adds (its event loop, parsing,
// checks, the file read back). Median and spread of each, and the overhead in ms and as a ratio.
//   toffee-bench-linuxcnc-probe [ROUNDS]   (default 5)
#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTcpSocket>
#include <QTimer>

#include "serial/linuxcnc/linuxcnccontroller.h"
#include "serial/machine/machinelink.h"
#include "serial/transport/tcptransport.h"
#include "tests/support/linuxcncpeer.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

[[noreturn]] void fail(const QString &message)
{
    std::fprintf(stderr, "toffee-bench-linuxcnc-probe: %s\n", qPrintable(message));
    std::exit(1);
}

// Runs the event loop until `done` is called; fails after a minute.
SessionResult await(const std::function<void(MachineController::Done)> &start)
{
    QEventLoop loop;
    std::optional<SessionResult> result;
    QTimer::singleShot(60000, &loop, [] { fail(u"no answer within a minute"_s); });
    start([&](const SessionResult &r) {
        result = r;
        loop.quit();
    });
    if (!result)
        loop.exec();
    return *result;
}

struct ToffeeSide
{
    TcpTransport transport;
    MachineLink link { &transport };
    LinuxCncController controller { &link };

    explicit ToffeeSide(quint16 port)
        : transport(TcpTransport::Address { u"127.0.0.1"_s, port })
    {
        transport.setAsksFirst(false); // LinuxCNC chosen: linuxcncrsh is asked nothing before its hello
        controller.setToolSetter(ToolSetter::parse(u"10,10,-140,3000,200"_s).value());
    }
};

// One probe by a raw client replaying `lines`: milliseconds from the first line to the last answer.
double replay(quint16 port, const QList<QByteArray> &lines)
{
    QTcpSocket socket;
    socket.connectToHost(u"127.0.0.1"_s, port);
    if (!socket.waitForConnected(5000))
        fail(u"the raw client could not connect"_s);
    QByteArray buffer;
    // One answer line each (set replies end "\n\r": empty lines skipped), echo off first (its own echo and
    // ACK read past); the opening is not timed.
    const auto answer = [&socket, &buffer](const QByteArray &line) {
        socket.write(line + '\n');
        for (;;) {
            buffer.replace('\r', '\n');
            const qsizetype end = buffer.indexOf('\n');
            if (end >= 0) {
                const QByteArray said = buffer.left(end).trimmed();
                buffer.remove(0, end + 1);
                if (said.isEmpty() || said.startsWith("set ") || said.startsWith("hello "))
                    continue;
                return;
            }
            if (!socket.waitForReadyRead(60000))
                fail(u"the raw client got no answer to "_s + QString::fromUtf8(line));
            buffer += socket.readAll();
        }
    };
    for (const QByteArray &line : { QByteArray("hello EMC bench 1.0"), QByteArray("set verbose on"),
             QByteArray("set echo off"), QByteArray("set enable EMCTOO"), QByteArray("set set_wait done") })
        answer(line);
    QElapsedTimer clock;
    clock.start();
    for (const QByteArray &line : lines)
        answer(line);
    const double ms = double(clock.nsecsElapsed()) / 1e6;
    socket.disconnectFromHost();
    return ms;
}

double median(QList<double> v)
{
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v.at(v.size() / 2) : (v.at(v.size() / 2 - 1) + v.at(v.size() / 2)) / 2.0;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const int rounds = argc > 1 ? std::max(1, QByteArray(argv[1]).toInt()) : 5;
    if (const QString why = LinuxCncPeer::skipReason(); !why.isEmpty()) {
        std::printf("toffee-bench-linuxcnc-probe: skipped: %s\n", qPrintable(why));
        return 0;
    }
    LinuxCncPeer peer({ { 1, 30.0 } });
    if (!peer.started() || !peer.makeReady())
        fail(u"LinuxCNC did not start: "_s + peer.errors());

    QList<QByteArray> lines; // what Toffee sent for its first probe, real-time bytes aside
    QList<double> toffee;
    QList<double> raw;
    for (int round = 0; round <= rounds; ++round) { // round 0 warms both up and records the lines
        {
            ToffeeSide t(peer.port());
            if (const SessionResult r = await([&](auto done) { t.controller.connectToMachine(done); });
                !r.ok())
                fail(r.message);
            if (const SessionResult r = await([&](auto done) { t.controller.selectTool(1, done); }); !r.ok())
                fail(r.message);
            QList<QByteArray> sent;
            QObject::connect(
                &t.link, &MachineLink::lineSent, &t.link, [&](const QByteArray &l) { sent << l; });
            QElapsedTimer clock;
            clock.start();
            const SessionResult r = await([&](auto done) { t.controller.probe(done); });
            const double ms = double(clock.nsecsElapsed()) / 1e6;
            if (!r.ok())
                fail(r.message);
            if (round == 0)
                lines = sent;
            else
                toffee << ms;
            t.link.close();
        }
        const double ms = replay(peer.port(), lines);
        if (round > 0)
            raw << ms;
    }
    const double t = median(toffee);
    const double r = median(raw);
    std::printf("a probe on LinuxCNC itself (%d lines: its state, the setter cycle through MDI, the contact "
                "printed back, G10 L1, G43 H, the offset in force read back), median of %d:\n",
        int(lines.size()), rounds);
    std::printf("  raw client, the same lines:  %8.1f ms  (%.1f to %.1f)\n", r,
        *std::min_element(raw.cbegin(), raw.cend()), *std::max_element(raw.cbegin(), raw.cend()));
    std::printf("  Toffee's probe():            %8.1f ms  (%.1f to %.1f)\n", t,
        *std::min_element(toffee.cbegin(), toffee.cend()), *std::max_element(toffee.cbegin(), toffee.cend()));
    std::printf("  overhead: %.1f ms, %.3fx\n", t - r, t / r);
    return 0;
}
