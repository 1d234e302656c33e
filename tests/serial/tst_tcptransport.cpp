// SPDX-License-Identifier: GPL-3.0-or-later
// TcpTransport, the Wi-Fi link, on real sockets on 127.0.0.1: the addresses it takes, each way connecting
// fails and what it says then, the socket options that notice a vanished machine, a peer that closes, resets
// or falls silent while a command waits, and Makera's frames with garbage between them. The peer is the test:
// a QTcpServer, or a POSIX listener that never accepts.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <thread>

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>

#include "serial/carvera/carverareplies.h"
#include "serial/machine/machinelink.h"
#include "serial/machineconnection.h"
#include "serial/transport/tcptransport.h"
#include "serial/wire/makeraframe.h"
#include "tests/support/firstquestion.h"
#include "tests/support/silentlistener.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::SilentListener;

namespace {

// Runs the event loop until `done` or `ms` pass; true when done. Woken by the event that changes things, not
// by QTest::qWaitFor's 10 ms naps, so that elapsed times measure the transport rather than the test.
bool runUntil(const std::function<bool()> &done, int ms)
{
    QElapsedTimer clock;
    clock.start();
    QTimer deadline; // wakes the wait below at the latest
    deadline.setSingleShot(true);
    deadline.setTimerType(Qt::PreciseTimer);
    deadline.start(ms);
    while (!done()) {
        // Once the deadline has fired no event may come to wake the wait (a coarse timer fires early).
        if (clock.elapsed() >= ms || !deadline.isActive())
            return done();
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    }
    return true;
}

// The machine's end: a listener on 127.0.0.1 that accepts one client and reads what it sends.
struct Peer
{
    QTcpServer server;
    QTcpSocket *socket = nullptr;

    Peer() { server.listen(QHostAddress::LocalHost, 0); }
    [[nodiscard]] TcpTransport::Address address() const { return { u"127.0.0.1"_s, server.serverPort() }; }
    bool accept()
    {
        if (!runUntil([this] { return server.hasPendingConnections(); }, 3000))
            return false;
        socket = server.nextPendingConnection();
        return socket != nullptr;
    }
    // The first question answered as a plain-text machine answers it.
    bool answer()
    {
        return Test::answerFirstQuestion(
            [this] { return socket->readAll(); }, [this](const QByteArray &b) { socket->write(b); });
    }
    // What the client sent until it ends with `end` (or 3 s pass).
    QByteArray readUntil(QByteArrayView end)
    {
        QByteArray got;
        runUntil(
            [&] {
                got += socket->readAll();
                return got.endsWith(end);
            },
            3000);
        return got;
    }
};

// This process's TCP socket whose local end is 127.0.0.1:`port`: the transport keeps its QTcpSocket to
// itself, and what counts is what the kernel was told about the socket anyway.
int socketWithLocalPort(quint16 port)
{
    for (int fd = 0; fd < 1024; ++fd) {
        sockaddr_in a {};
        socklen_t size = sizeof a;
        if (::getsockname(fd, reinterpret_cast<sockaddr *>(&a), &size) == 0 && a.sin_family == AF_INET
            && ntohs(a.sin_port) == port)
            return fd;
    }
    return -1;
}

int intOption(int fd, int level, int name)
{
    int value = -1;
    socklen_t size = sizeof value;
    return ::getsockopt(fd, level, name, &value, &size) == 0 ? value : -2;
}

// A link opened on `peer`'s first client, in plain text (the test speaks for the machine), without status
// polls; false when it did not open.
bool openLink(Peer &peer, MachineLink &link)
{
    link.setPollInterval(0);
    QSignalSpy opened(&link, &MachineLink::opened);
    link.open();
    return peer.accept() && peer.answer() && runUntil([&] { return !opened.isEmpty(); }, 3000);
}

// A Carvera's link in plain text on `peer` (the test speaks for the machine): open it with openLink.
struct PlainLink
{
    TcpTransport transport;
    MachineLink link { &transport };

    explicit PlainLink(const Peer &peer)
        : transport(peer.address())
    {
        transport.setProtocol(StreamTransport::Protocol::Text);
        link.setGrammar(carveraGrammar());
    }
};

} // namespace

class TestTcpTransport : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // Which controller a target is: the one chosen, or none yet (found by asking on connecting, whatever the
    // port: grblHAL's 23 is no longer taken for grblHAL); the built-in emulator is a Carvera. The transport
    // keeps the protocol chosen for every controller: its first question is harmless to each.
    void theControllerIsChosenOrAsked_data()
    {
        QTest::addColumn<QString>("host");
        QTest::addColumn<int>("port");
        QTest::addColumn<int>("chosen");
        const int autoKind = int(ControllerKind::Auto);
        const int carvera = int(ControllerKind::Carvera);
        const int grblhal = int(ControllerKind::GrblHal);
        QTest::newRow("serial port, auto") << QString() << 0 << autoKind;
        QTest::newRow("serial port, grblHAL chosen") << QString() << 0 << grblhal;
        QTest::newRow("TCP 2222, auto") << u"192.168.1.57"_s << 2222 << autoKind;
        QTest::newRow("TCP 23, auto") << u"192.168.1.60"_s << 23 << autoKind;
        QTest::newRow("TCP 23, the Carvera chosen") << u"192.168.1.60"_s << 23 << carvera;
        QTest::newRow("TCP 8080, grblHAL chosen") << u"10.0.0.5"_s << 8080 << grblhal;
    }
    void theControllerIsChosenOrAsked()
    {
        QFETCH(QString, host);
        QFETCH(int, port);
        QFETCH(int, chosen);
        ConnectionTarget target;
        target.emulator = false;
        target.host = host;
        target.port = host.isEmpty() ? u"/dev/ttyACM0"_s : QString();
        if (port > 0)
            target.tcpPort = quint16(port);
        target.controller = ControllerKind(chosen);
        QCOMPARE(int(target.knownController()), chosen);
        const auto transport = makeTransport(target);
        const auto *stream = qobject_cast<const StreamTransport *>(transport.get());
        QVERIFY(stream);
        QCOMPARE(stream->protocol(), StreamTransport::Protocol::Auto);
        // The built-in emulator is a Carvera whatever is chosen.
        target.emulator = true;
        QCOMPARE(target.knownController(), ControllerKind::Carvera);
    }

    void parsesAddresses_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("host");
        QTest::addColumn<int>("port");
        QTest::newRow("host only") << u"carvera.local"_s << u"carvera.local"_s << 2222;
        QTest::newRow("IPv4 only") << u"192.168.1.57"_s << u"192.168.1.57"_s << 2222;
        QTest::newRow("host:port") << u"192.168.1.57:2323"_s << u"192.168.1.57"_s << 2323;
        QTest::newRow("spaces around") << u"  carvera.local:1 "_s << u"carvera.local"_s << 1;
        QTest::newRow("port 65535") << u"c:65535"_s << u"c"_s << 65535;
        QTest::newRow("[::1]:2222") << u"[::1]:2222"_s << u"::1"_s << 2222;
        QTest::newRow("[IPv6] bare") << u"[fe80::1]"_s << u"fe80::1"_s << 2222;
        QTest::newRow("[IPv6]:port") << u"[2001:db8::57]:80"_s << u"2001:db8::57"_s << 80;
    }
    void parsesAddresses()
    {
        QFETCH(QString, text);
        QFETCH(QString, host);
        QFETCH(int, port);
        const auto address = TcpTransport::parseAddress(text);
        QVERIFY2(address.ok(), qPrintable(address.ok() ? QString() : address.error().message));
        QCOMPARE(address.value().host, host);
        QCOMPARE(int(address.value().port), port);
    }

    // Refused with a message that names what was given, so that a typo in a script is found. An IPv6 address
    // without brackets too: its last group could be a port (toffee-cli says how to write it).
    void refusesWhatIsNoAddress_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("says");
        const QString usage = u"give HOST or HOST:PORT"_s;
        QTest::newRow("empty") << QString() << usage;
        QTest::newRow("spaces") << u"   "_s << usage;
        QTest::newRow("port 0") << u"carvera.local:0"_s << usage;
        QTest::newRow("port 70000") << u"carvera.local:70000"_s << usage;
        QTest::newRow("port 65536") << u"carvera.local:65536"_s << usage;
        QTest::newRow("host:") << u"carvera.local:"_s << usage;
        QTest::newRow(":port") << u":2222"_s << usage;
        QTest::newRow("a:b:c") << u"a:b:c"_s << usage;
        QTest::newRow("port +22") << u"c:+22"_s << usage;
        QTest::newRow("port -1") << u"c:-1"_s << usage;
        QTest::newRow("port x") << u"c:twentytwo"_s << usage;
        QTest::newRow("a space inside") << u"my carvera:2222"_s << usage;
        QTest::newRow("[unclosed") << u"[::1:2222"_s << usage;
        QTest::newRow("[IPv4]") << u"[192.168.1.57]:2222"_s << usage;
        QTest::newRow("[::1]x") << u"[::1]x"_s << usage;
        QTest::newRow("[::1]:") << u"[::1]:"_s << usage;
        QTest::newRow("[::1]:0") << u"[::1]:0"_s << usage;
        QTest::newRow("IPv6 bare") << u"::1"_s << usage;
        QTest::newRow("IPv6 and a port, bare") << u"fe80::1:2222"_s << usage;
        QTest::newRow("a long name") << QString(254, u'a') << usage;
    }
    void refusesWhatIsNoAddress()
    {
        QFETCH(QString, text);
        QFETCH(QString, says);
        const auto address = TcpTransport::parseAddress(text);
        QVERIFY(!address.ok());
        const QString message = address.error().message;
        QVERIFY2(message.contains(u'"' + text.trimmed() + u'"'), qPrintable(message));
        QVERIFY2(message.contains(says), qPrintable(message));
    }

    // A closed port on a reachable host answers at once (RST): no waiting out the connect limit.
    void refusedConnectionFailsAtOnce()
    {
        QTcpServer closed;
        QVERIFY(closed.listen(QHostAddress::LocalHost, 0));
        const quint16 port = closed.serverPort();
        closed.close();
        TcpTransport transport({ u"127.0.0.1"_s, port });
        QSignalSpy errors(&transport, &LineTransport::errorOccurred);
        QSignalSpy opened(&transport, &LineTransport::opened);
        QElapsedTimer clock;
        clock.start();
        transport.open();
        QVERIFY(runUntil([&] { return !errors.isEmpty(); }, 3000));
        QVERIFY2(clock.elapsed() < 1000, qPrintable(QString::number(clock.elapsed())));
        const QString said = errors.front().front().toString();
        QVERIFY2(said.contains(u"Nothing answers at 127.0.0.1:%1 (the connection was refused)"_s.arg(port)),
            qPrintable(said));
        QVERIFY2(said.contains(u"a Carvera listens on 2222"_s), qPrintable(said));
        QVERIFY(!transport.isOpen());
        QTest::qWait(100); // nothing more comes of it
        QCOMPARE(errors.size(), 1);
        QCOMPARE(opened.size(), 0);
    }

    // A name no resolver knows (.invalid is reserved never to resolve, RFC 6761) is said to be one.
    void unknownHostIsSaidToBeOne()
    {
        TcpTransport transport({ u"no-such-carvera.invalid"_s, 2222 });
        QSignalSpy errors(&transport, &LineTransport::errorOccurred);
        transport.open();
        QVERIFY(runUntil([&] { return !errors.isEmpty(); }, 6000));
        const QString said = errors.front().front().toString();
        QVERIFY2(said.startsWith(u"no-such-carvera.invalid is not a host name this computer can find"_s),
            qPrintable(said));
        QVERIFY(!transport.isOpen());
    }

    // A machine switched off does not refuse, it says nothing: the connect gives up after its limit (5 s
    // unless set), said with the address, instead of the system's two minutes. A coarse timer could fire 5 %
    // early; the limit is a promise to wait that long.
    void connectGivesUpAfterItsLimit_data()
    {
        QTest::addColumn<int>("limitMs");
        QTest::addColumn<int>("expectedMs");
        QTest::addColumn<QString>("says");
        QTest::newRow("default") << 0 << TcpTransport::kConnectTimeoutMs << u"within 5 s"_s;
        QTest::newRow("1.5 s") << 1500 << 1500 << u"within 1.5 s"_s;
    }
    void connectGivesUpAfterItsLimit()
    {
        QFETCH(int, limitMs);
        QFETCH(int, expectedMs);
        QFETCH(QString, says);
        SilentListener silent;
        QVERIFY(silent.full);
        TcpTransport transport({ u"127.0.0.1"_s, silent.port });
        if (limitMs > 0)
            transport.setConnectTimeoutMs(limitMs);
        QSignalSpy errors(&transport, &LineTransport::errorOccurred);
        QSignalSpy opened(&transport, &LineTransport::opened);
        QElapsedTimer clock;
        clock.start();
        transport.open();
        QVERIFY(runUntil([&] { return !errors.isEmpty(); }, expectedMs + 3000));
        const qint64 elapsed = clock.elapsed();
        QVERIFY2(elapsed >= expectedMs && elapsed < expectedMs + 500, qPrintable(QString::number(elapsed)));
        const QString said = errors.front().front().toString();
        QVERIFY2(said.startsWith(u"127.0.0.1:%1 did not answer %2"_s.arg(silent.port).arg(says)),
            qPrintable(said));
        QVERIFY2(said.contains(u"switched on and on this network"_s), qPrintable(said));
        QVERIFY(!transport.isOpen());
        QCOMPARE(opened.size(), 0);
    }

    // What notices a machine that vanished (switched off, out of Wi-Fi range) in seconds: keepalives after
    // 2 s of silence, one a second, three unanswered; data unacknowledged for 5 s; and no Nagle delay on a
    // command's few bytes. Read back from the kernel; the peer's own socket, left as the system makes it,
    // shows that the reading tells them apart.
    void tunesTheConnectedSocket()
    {
        Peer peer;
        auto transport = std::make_unique<TcpTransport>(peer.address());
        transport->setProtocol(StreamTransport::Protocol::Text);
        QSignalSpy opened(transport.get(), &LineTransport::opened);
        transport->open();
        QVERIFY(peer.accept());
        QVERIFY(peer.answer());
        QVERIFY(runUntil([&] { return !opened.isEmpty(); }, 3000));
        const quint16 local = peer.socket->peerPort();
        const int fd = socketWithLocalPort(local);
        QVERIFY(fd >= 0);
        QCOMPARE(intOption(fd, SOL_SOCKET, SO_KEEPALIVE), 1);
        QCOMPARE(intOption(fd, IPPROTO_TCP, TCP_KEEPIDLE), TcpTransport::kKeepAliveIdleS);
        QCOMPARE(intOption(fd, IPPROTO_TCP, TCP_KEEPINTVL), TcpTransport::kKeepAliveIntervalS);
        QCOMPARE(intOption(fd, IPPROTO_TCP, TCP_KEEPCNT), TcpTransport::kKeepAliveCount);
        QCOMPARE(intOption(fd, IPPROTO_TCP, TCP_USER_TIMEOUT), TcpTransport::kUnacknowledgedMs);
        QCOMPARE(intOption(fd, IPPROTO_TCP, TCP_NODELAY), 1);
        QCOMPARE(TcpTransport::kKeepAliveIdleS, 2);
        QCOMPARE(TcpTransport::kKeepAliveIntervalS, 1);
        QCOMPARE(TcpTransport::kKeepAliveCount, 3);
        QCOMPARE(TcpTransport::kUnacknowledgedMs, 5000);

        const int untuned = int(peer.socket->socketDescriptor());
        QCOMPARE(intOption(untuned, SOL_SOCKET, SO_KEEPALIVE), 0);
        QCOMPARE(intOption(untuned, IPPROTO_TCP, TCP_USER_TIMEOUT), 0);
        QCOMPARE(intOption(untuned, IPPROTO_TCP, TCP_NODELAY), 0);

        // Gone with the transport, the connection ends: a machine serves one client at a time and says busy
        // while one is connected, so a connection left behind would keep it from the next.
        transport.reset();
        QVERIFY(runUntil([&] { return peer.socket->state() == QAbstractSocket::UnconnectedState; }, 3000));
        QCOMPARE(socketWithLocalPort(local), -1);
    }

    // The machine closes the connection (switched off cleanly, restarted, another program took it) while a
    // command waits: the command fails at once, not at its 5 s limit, in words that say what happened.
    // A receiver that holds the event loop (the window's modal box opened from a status or an alarm: its own
    // loop runs inside the handler) does not stop the reading: the status reports keep coming while it is
    // open, and in order. Before, the socket said nothing more until the handler returned ("no status report
    // for 17 s" while the machine was idle).
    void aReceiverHoldingTheEventLoopDoesNotStopTheReading()
    {
        Peer peer;
        PlainLink plain(peer);
        QVERIFY(openLink(peer, plain.link));
        MachineLink &link = plain.link;
        int sent = 0;
        connect(peer.socket, &QTcpSocket::readyRead, &peer.server, [&peer, &sent] {
            for (const char c : peer.socket->readAll()) {
                if (c == '?')
                    peer.socket->write(QByteArray("<Idle|MPos:0.000,0.000,") + QByteArray::number(++sent)
                        + ".000|WPos:0.000,0.000,0.000>\r\n");
            }
        });
        QList<double> seen;
        int seenInside = 0;
        bool inside = false;
        connect(&link, &MachineLink::statusChanged, &link, [&](const MachineStatus &status) {
            seen << status.mpos[2];
            if (inside)
                ++seenInside;
            if (seen.size() != 1)
                return;
            inside = true;
            QEventLoop modal; // as QMessageBox::exec runs one
            QTimer::singleShot(1500, &modal, &QEventLoop::quit);
            modal.exec();
            inside = false;
        });
        link.setPollInterval(100);
        QVERIFY(runUntil([&] { return seen.size() >= 20; }, 5000));
        QVERIFY2(seenInside >= 8, qPrintable(QString::number(seenInside)));
        for (qsizetype i = 0; i < seen.size(); ++i)
            QCOMPARE(seen.at(i), double(i + 1)); // each once, in the order sent
    }

    void peerClosingFailsTheCommandAtOnce()
    {
        Peer peer;
        PlainLink plain(peer);
        QVERIFY(openLink(peer, plain.link));
        TcpTransport &transport = plain.transport;
        MachineLink &link = plain.link;
        QSignalSpy closed(&link, &MachineLink::closed);
        std::optional<CommandReply> reply;
        link.send("M493.4", MachineLink::kDefaultTimeoutMs, [&reply](const CommandReply &r) { reply = r; });
        QCOMPARE(peer.readUntil("\n"), QByteArray("M493.4\n"));
        QElapsedTimer clock;
        clock.start();
        peer.socket->disconnectFromHost();
        QVERIFY(runUntil([&] { return reply.has_value(); }, 3000));
        QVERIFY2(clock.elapsed() < 500, qPrintable(QString::number(clock.elapsed())));
        QCOMPARE(reply->status, CommandReply::Status::LinkLost);
        QVERIFY2(reply->message.contains(u"while it ran \"M493.4\""_s), qPrintable(reply->message));
        const QString address = u"127.0.0.1:%1"_s.arg(peer.server.serverPort());
        QVERIFY2(reply->message.contains(u"The machine at %1 closed the connection"_s.arg(address)),
            qPrintable(reply->message));
        QVERIFY(!transport.isOpen());
        QCOMPARE(closed.size(), 1);
        // This side closed too, and said so to the machine, which can serve the next client.
        QVERIFY(runUntil([&] { return peer.socket->state() == QAbstractSocket::UnconnectedState; }, 3000));
    }

    // The connection is reset (RST: the machine lost power mid-stream, a router dropped it): the same at
    // once, said as a lost link.
    void peerResettingFailsTheCommandAtOnce()
    {
        Peer peer;
        PlainLink plain(peer);
        QVERIFY(openLink(peer, plain.link));
        TcpTransport &transport = plain.transport;
        MachineLink &link = plain.link;
        std::optional<CommandReply> reply;
        link.send(
            "M491", MachineLink::kMotionTimeoutMs, [&reply](const CommandReply &r) { reply = r; },
            ReplyEnd::Script);
        QCOMPARE(peer.readUntil("\n"), QByteArray("M491\n"));
        const ::linger reset { 1, 0 };
        QCOMPARE(
            ::setsockopt(int(peer.socket->socketDescriptor()), SOL_SOCKET, SO_LINGER, &reset, sizeof reset),
            0);
        QElapsedTimer clock;
        clock.start();
        peer.socket->abort();
        QVERIFY(runUntil([&] { return reply.has_value(); }, 3000));
        QVERIFY2(clock.elapsed() < 500, qPrintable(QString::number(clock.elapsed())));
        QCOMPARE(reply->status, CommandReply::Status::LinkLost);
        const QString address = u"127.0.0.1:%1"_s.arg(peer.server.serverPort());
        QVERIFY2(reply->message.contains(
                     u"The link to %1 was lost (%2)"_s.arg(address, qt_error_string(ECONNRESET))),
            qPrintable(reply->message));
        QVERIFY2(reply->message.contains(u"switched off or left the network"_s), qPrintable(reply->message));
        QVERIFY2(!reply->message.contains(u"closed the connection"_s), qPrintable(reply->message));
        QVERIFY(!transport.isOpen());
    }

    // A peer that took the connection and then says nothing (half-open as the client sees it: a machine
    // hung, or gone without a word while the kernel on its side still acknowledges): the command fails at its
    // own limit, and the link is closed, since a late answer could be taken for the next command's.
    // Keepalives and TCP_USER_TIMEOUT are for a peer whose kernel is gone too, which loopback cannot play:
    // what they are set to is tunesTheConnectedSocket's.
    void silentPeerFailsTheCommandAtItsLimit()
    {
        Peer peer;
        PlainLink plain(peer);
        QVERIFY(openLink(peer, plain.link));
        TcpTransport &transport = plain.transport;
        MachineLink &link = plain.link;
        std::optional<CommandReply> reply;
        QElapsedTimer clock;
        clock.start();
        link.send("M493.4", 1000, [&reply](const CommandReply &r) { reply = r; });
        QCOMPARE(peer.readUntil("\n"), QByteArray("M493.4\n"));
        QVERIFY(runUntil([&] { return reply.has_value(); }, 4000));
        const qint64 elapsed = clock.elapsed();
        QVERIFY2(elapsed >= 1000 && elapsed < 1500, qPrintable(QString::number(elapsed)));
        QCOMPARE(reply->status, CommandReply::Status::Timeout);
        QVERIFY2(reply->message.startsWith(u"The machine did not answer \"M493.4\" within 1.0 s"_s),
            qPrintable(reply->message));
        QVERIFY(!transport.isOpen());
        QVERIFY(runUntil([&] { return peer.socket->state() == QAbstractSocket::UnconnectedState; }, 3000));
    }

    // A peer that floods (lines nobody asked for, as fast as loopback carries them) while a command waits:
    // the transport reads a slice at a time and lets the event loop run between, so the command's 1 s limit
    // still ends it about on time (a flood once made one read of 300 MB and a 3 s limit 6 s).
    void aFloodIsReadASliceAtATimeAndTheLimitHolds()
    {
        const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in address {};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        QVERIFY(::bind(listener, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0);
        QVERIFY(::listen(listener, 1) == 0);
        socklen_t length = sizeof address;
        QVERIFY(::getsockname(listener, reinterpret_cast<sockaddr *>(&address), &length) == 0);
        std::atomic_bool stop = false;
        std::atomic<qint64> sent = 0;
        std::thread flood([&] {
            const int peer = ::accept(listener, nullptr, nullptr);
            if (peer < 0)
                return;
            // The first question answered as a plain machine does, then the flood.
            const QByteArray question = StreamTransport::firstQuestion();
            QByteArray got;
            char buffer[256];
            while (!got.contains(question)) {
                const ssize_t n = ::recv(peer, buffer, sizeof buffer, 0);
                if (n <= 0)
                    return;
                got.append(buffer, n);
            }
            got.remove(0, got.indexOf(question) + question.size());
            ::send(peer, Test::kPlainStatus, std::strlen(Test::kPlainStatus), MSG_NOSIGNAL);
            while (!got.contains('\n')) {
                const ssize_t n = ::recv(peer, buffer, sizeof buffer, 0);
                if (n <= 0)
                    return;
                got.append(buffer, n);
            }
            ::send(peer, "ok\r\n", 4, MSG_NOSIGNAL);
            QByteArray chunk;
            for (int i = 0; i < 4096; ++i)
                chunk += "ALARM: Hard limit\n";
            while (!stop) {
                const ssize_t n = ::send(peer, chunk.constData(), size_t(chunk.size()), MSG_NOSIGNAL);
                if (n <= 0)
                    break;
                sent += n;
            }
            ::close(peer);
        });
        TcpTransport transport(TcpTransport::Address { u"127.0.0.1"_s, ntohs(address.sin_port) });
        transport.setProtocol(StreamTransport::Protocol::Text);
        MachineLink link(&transport);
        link.setGrammar(carveraGrammar());
        link.setPollInterval(0);
        std::optional<CommandReply> reply;
        QElapsedTimer clock;
        link.open();
        QVERIFY(runUntil([&] { return link.isOpen(); }, 4000));
        clock.start();
        link.send("M493.4", 1000, [&reply](const CommandReply &r) { reply = r; });
        const bool ended = runUntil([&] { return reply.has_value(); }, 10000);
        const qint64 elapsed = clock.elapsed();
        stop = true;
        transport.close();
        flood.join();
        ::close(listener);
        QVERIFY(ended);
        qInfo("%lld MB flooded; the 1 s limit ended the command after %lld ms", sent / 1000000, elapsed);
        QVERIFY2(sent > 10'000'000, qPrintable(QString::number(sent)));
        QCOMPARE(reply->status, CommandReply::Status::Timeout);
        QVERIFY2(elapsed < 2500, qPrintable(QString::number(elapsed)));
    }

    // Over TCP, as on a serial port, the framed firmware's bytes may come with noise between its frames
    // (boot text, a broken frame, a stray header byte): found by the transport as framed, and every command
    // still understood, nothing of the noise taken for the machine's words.
    void understandsFramesWithGarbageBetweenThem()
    {
        Peer peer;
        TcpTransport transport(peer.address());
        MachineLink link(&transport);
        link.setGrammar(carveraGrammar());
        link.setPollInterval(0);
        QSignalSpy opened(&link, &MachineLink::opened);
        QSignalSpy lines(&link, &MachineLink::lineReceived);
        link.open();
        QVERIFY(peer.accept());
        const QByteArray query = StreamTransport::firstQuestion();
        QCOMPARE(peer.readUntil(query), query);
        QByteArray broken = MakeraFrame::encode(MakeraFrame::Output, "bad crc\n");
        broken[broken.size() - 3] = char(broken.at(broken.size() - 3) ^ 0x5a);
        peer.socket->write("boot text\r\n" + broken + "\x86"
            + MakeraFrame::encode(MakeraFrame::Status, "<Idle|MPos:0,0,0|T:2,9.652,-1,0>\n") + "\x55\xaa");
        QVERIFY(runUntil([&] { return !opened.isEmpty(); }, 3000));
        QCOMPARE(transport.mode(), ConsoleStream::Mode::Framed);

        std::optional<CommandReply> reply;
        link.send("M493.4", MachineLink::kDefaultTimeoutMs, [&reply](const CommandReply &r) { reply = r; });
        const QByteArray command = MakeraFrame::encode(MakeraFrame::Command, "M493.4");
        QCOMPARE(peer.readUntil(command), command);
        const QByteArray answer = "\x86\x68junk"
            + MakeraFrame::encode(MakeraFrame::Reply, "current tool offset [") + QByteArray("\r\n\x00\xff", 4)
            + broken + MakeraFrame::encode(MakeraFrame::Reply, "9.652] , reference tool offset ") + "noise"
            + MakeraFrame::encode(MakeraFrame::Reply, "[-115.340]\r\n")
            + MakeraFrame::encode(MakeraFrame::Reply, "ok\r\n") + "trailing noise";
        for (qsizetype i = 0; i < answer.size(); i += 5) { // split anywhere
            peer.socket->write(answer.mid(i, 5));
            peer.socket->flush();
        }
        QVERIFY(runUntil([&] { return reply.has_value(); }, 3000));
        QVERIFY2(reply->ok(), qPrintable(reply->message));
        QCOMPARE(reply->lines,
            QList<QByteArray> { "current tool offset [9.652] , reference tool offset [-115.340]" });
        QStringList heard;
        for (const auto &l : std::as_const(lines))
            heard << QString::fromLatin1(l.front().toByteArray());
        QCOMPARE(heard,
            (QStringList { u"current tool offset [9.652] , reference tool offset [-115.340]"_s, u"ok"_s }));
        const auto &counts = transport.stream().frameCounts();
        QCOMPARE(counts.badCrc, 1);
        QVERIFY2(counts.strayBytes >= 20, qPrintable(QString::number(counts.strayBytes)));
        QVERIFY(transport.isOpen());
    }

    // A protocol chosen is checked by the first question before anything else is sent: plain text chosen for
    // a framed machine is refused, and nothing plain reaches it (over TCP plain bytes leave the framed
    // firmware deaf); frames chosen for a plain machine are refused after the line end that a plain machine
    // takes harmlessly; each chosen rightly opens.
    void aChosenProtocolIsCheckedFirst_data()
    {
        QTest::addColumn<int>("chosen");
        QTest::addColumn<bool>("machineFramed");
        using Protocol = StreamTransport::Protocol;
        QTest::newRow("text chosen, a framed machine") << int(Protocol::Text) << true;
        QTest::newRow("frames chosen, a plain machine") << int(Protocol::Framed) << false;
        QTest::newRow("text chosen, a plain machine") << int(Protocol::Text) << false;
        QTest::newRow("frames chosen, a framed machine") << int(Protocol::Framed) << true;
    }
    void aChosenProtocolIsCheckedFirst()
    {
        QFETCH(int, chosen);
        QFETCH(bool, machineFramed);
        const bool chosenFramed = StreamTransport::Protocol(chosen) == StreamTransport::Protocol::Framed;
        Peer peer;
        TcpTransport transport(peer.address());
        transport.setProtocol(StreamTransport::Protocol(chosen));
        QSignalSpy opened(&transport, &LineTransport::opened);
        QSignalSpy errors(&transport, &LineTransport::errorOccurred);
        transport.open();
        QVERIFY(peer.accept());
        const QByteArray question = StreamTransport::firstQuestion();
        QCOMPARE(peer.readUntil(question), question);
        QByteArray after;
        if (machineFramed) {
            peer.socket->write(MakeraFrame::encode(MakeraFrame::Reply, "version = 1.0.5\n"));
        } else {
            peer.socket->write("<Idle|MPos:0,0,0|T:1,0.000,-1,0>\r\n");
            after = peer.readUntil("\n");
            QCOMPARE(after, QByteArray("\n"));
            peer.socket->write("ok - ignore: [\x86h]\r\n");
        }
        QVERIFY(runUntil([&] { return !opened.isEmpty() || !errors.isEmpty(); }, 3000));
        if (chosenFramed == machineFramed) {
            QCOMPARE(opened.size(), 1);
            QCOMPARE(
                transport.mode(), machineFramed ? ConsoleStream::Mode::Framed : ConsoleStream::Mode::Text);
            return;
        }
        QCOMPARE(opened.size(), 0);
        const QString said = errors.front().front().toString();
        QVERIFY2(said.contains(machineFramed ? u"speaks Makera's frames"_s : u"speaks plain text"_s)
                && said.contains(u"Nothing more was sent"_s, Qt::CaseInsensitive),
            qPrintable(said));
        QVERIFY(!transport.isOpen());
        runUntil([] { return false; }, 300);
        QCOMPARE(peer.socket->readAll(), QByteArray()); // nothing after the question (and its line end)
    }

    // The first question is harmless to grblHAL too: none of its bytes is one of grblHAL's real-time commands
    // that acts (grbl.h: reset, stop, cycle start, feed hold, door, jog cancel, the toggles, the overrides,
    // coolant, tool acknowledge, macros), and it holds no line end; its '?' asks for a status report and
    // 0xA2 for the PID log, both reports. (The earlier A1 frame of a bare '?' toggled grblHAL's mist
    // coolant.)
    void theFirstQuestionHoldsNothingGrblHalActsOn()
    {
        QSet<uchar> acts = { 0x03, 0x14, 0x18, 0x19, '~', '!', '%', '\n', '\r', 0x81, 0x82, 0x84, 0x85, 0xA0,
            0xA1, 0xA3, 0xA4 };
        for (const auto &[first, last] : { std::pair { 0x88, 0x8C }, { 0x90, 0x9E }, { 0xB0, 0xB7 } }) {
            for (int c = first; c <= last; ++c)
                acts.insert(uchar(c));
        }
        const QByteArray question = StreamTransport::firstQuestion();
        QCOMPARE(question.front(), char(0x86)); // a frame's header: dropped by grblHAL, not acted on
        for (qsizetype i = 1; i < question.size(); ++i)
            QVERIFY2(!acts.contains(uchar(question.at(i))),
                qPrintable(u"byte %1 is 0x%2"_s.arg(i).arg(int(uchar(question.at(i))), 2, 16, QChar(u'0'))));
        QCOMPARE(question.count('?'), 1);
        const auto frames = MakeraFrame::Decoder().feed(question);
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames.front().type, MakeraFrame::Command);
        QCOMPARE(frames.front().payload, QByteArray("version ?"));
    }
};

QTEST_GUILESS_MAIN(TestTcpTransport)
#include "tst_tcptransport.moc"
