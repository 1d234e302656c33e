// SPDX-License-Identifier: GPL-3.0-or-later
// TcpTransport, the Wi-Fi link, on real sockets on 127.0.0.1: the addresses it takes, each way connecting
// fails and what it says then, the socket options that notice a vanished machine, the protocol chosen or
// asked for. When the machine's end misbehaves: tst_tcpfaults. The peer is the test: a QTcpServer
// (tests/support/tcppeer.h), or a POSIX listener that never accepts.
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

#include "tests/support/tcppeer.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using namespace Toffee::Test;

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
