// SPDX-License-Identifier: GPL-3.0-or-later
// A probe's overhead in Toffee over grblHAL's own time (issue 29). grblHAL itself (TOFFEE_GRBLHAL_PEER, as
// the suite runs it) on TCP, a tool on its modelled setter; each round, in turns:
//  - Toffee: GrblHalController::probe() over MachineLink and a TcpTransport (the setter cycle, G4 P0, the
//    G10 L1 and G43 H written, $# read back), timed from the call to its result;
//  - the yardstick: a raw client (a blocking QTcpSocket) sending the very lines Toffee sent in its first
//  probe,
//    each once the one before is answered ("ok" or "error:"), timed from the first line to the last answer.
// Both pay the machine's motion, which is most of it; the difference is what Toffee adds (its status polls,
// parsing, checks). Median and spread of each, and the overhead in ms and as a ratio.
//   toffee-bench-grblhal-probe [ROUNDS]   (default 5)
#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTcpSocket>
#include <QTimer>

#include "serial/grblhal/grblhalcontroller.h"
#include "serial/machine/machinelink.h"
#include "serial/transport/tcptransport.h"
#include "tests/support/grblhalpeer.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

[[noreturn]] void fail(const QString &message)
{
    std::fprintf(stderr, "toffee-bench-grblhal-probe: %s\n", qPrintable(message));
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
    GrblHalController controller { &link };

    explicit ToffeeSide(quint16 port)
        : transport(TcpTransport::Address { u"127.0.0.1"_s, port })
    {
        transport.setProtocol(StreamTransport::Protocol::Text);
        controller.setToolSetter(ToolSetter::parse(u"0,0,-120,3000,300"_s).value());
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
    QElapsedTimer clock;
    clock.start();
    for (const QByteArray &line : lines) {
        socket.write(line + '\n');
        for (;;) {
            const qsizetype end = buffer.indexOf('\n');
            if (end >= 0) {
                const QByteArray answer = buffer.left(end).trimmed();
                buffer.remove(0, end + 1);
                if (answer == "ok" || answer.startsWith("error:"))
                    break;
                continue;
            }
            if (!socket.waitForReadyRead(60000))
                fail(u"the raw client got no answer to "_s + QString::fromUtf8(line));
            buffer += socket.readAll();
        }
    }
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
    if (GrblHalPeer::script().isEmpty()) {
        std::printf("toffee-bench-grblhal-probe: skipped: %s\n", qPrintable(GrblHalPeer::skipReason()));
        return 0;
    }
    GrblHalPeer peer;
    if (!peer.started() || !peer.writeSetter(-100.0, { { 1, 30.0 } }))
        fail(u"grblHAL did not start: "_s + peer.errors());

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
    std::printf("a probe on grblHAL itself (%d lines: the setter cycle, G4 P0, G10 L1, G43 H, $# read back), "
                "median of %d:\n",
        int(lines.size()), rounds);
    std::printf("  raw client, the same lines:  %8.1f ms  (%.1f to %.1f)\n", r,
        *std::min_element(raw.cbegin(), raw.cend()), *std::max_element(raw.cbegin(), raw.cend()));
    std::printf("  Toffee's probe():            %8.1f ms  (%.1f to %.1f)\n", t,
        *std::min_element(toffee.cbegin(), toffee.cend()), *std::max_element(toffee.cbegin(), toffee.cend()));
    std::printf("  overhead: %.1f ms, %.3fx\n", t - r, t / r);
    return 0;
}
