// SPDX-License-Identifier: GPL-3.0-or-later
// Which controller answers, found before anything of one controller's is sent, against the controllers
// themselves (../shared/peers): grblHAL over TCP on a port that is not its 23 and over a pseudo-terminal, the
// Carvera's firmware plain and framed over its UART and its Wi-Fi port. Asking changes nothing (grblHAL's
// coolant, which the old framed status query toggled, stays off); a protocol chosen wrongly is refused before
// it can leave the framed firmware deaf; a Carvera chosen for grblHAL, classic Grbl and a controller that is
// neither are refused by name with nothing more sent.
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>

#include "serial/machineconnection.h"
#include "serial/transport/streamtransport.h"
#include "tests/support/carverapeer.h"
#include "tests/support/grblhalpeer.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::CarveraPeer;
using Toffee::Test::GrblHalPeer;

namespace {

struct Outcome
{
    bool connected = false;
    QString message;
};

Outcome connectTo(MachineConnection &connection, const ConnectionTarget &target, int limitMs = 20000)
{
    QSignalSpy failed(&connection, &MachineConnection::connectFailed);
    connection.connectTo(target);
    (void)QTest::qWaitFor(
        [&] { return connection.state() == MachineConnection::State::Connected || !failed.isEmpty(); },
        limitMs);
    return { connection.state() == MachineConnection::State::Connected,
        failed.isEmpty() ? QString() : failed.front().front().toString() };
}

// One line through the connected link, and what it answered.
QList<QByteArray> ask(MachineConnection &connection, const QByteArray &line)
{
    std::optional<CommandReply> reply;
    connection.link()->send(line, 5000, [&reply](const CommandReply &r) { reply = r; });
    (void)QTest::qWaitFor([&] { return reply.has_value(); }, 6000);
    return reply ? reply->lines : QList<QByteArray> {};
}

ConnectionTarget hostTarget(const QString &address)
{
    ConnectionTarget target;
    target.emulator = false;
    const auto parsed = TcpTransport::parseAddress(address);
    target.host = parsed.value().host;
    target.tcpPort = parsed.value().port;
    return target;
}

ConnectionTarget portTarget(const QString &port)
{
    ConnectionTarget target;
    target.emulator = false;
    target.port = port;
    return target;
}

// A machine on 127.0.0.1 that answers '?' with a status report and each line as `answer` says; it keeps
// every line it was sent ('?' taken out, as a controller takes its real-time bytes).
// A console that answers nothing unasked-for, as LinuxCNC's linuxcncrsh (2.9) does: only its hello, when
// `answersHello`; every line it was sent is kept.
class SilentConsole : public QObject
{
public:
    QTcpServer server;
    QList<QByteArray> lines;
    bool answersHello = true;

    SilentConsole()
    {
        server.listen(QHostAddress::LocalHost, 0);
        connect(&server, &QTcpServer::newConnection, this, [this] {
            QTcpSocket *socket = server.nextPendingConnection();
            connect(socket, &QTcpSocket::readyRead, this, [this, socket] {
                m_buffer += socket->readAll();
                for (qsizetype end; (end = m_buffer.indexOf('\n')) >= 0;) {
                    const QByteArray line = m_buffer.left(end);
                    m_buffer.remove(0, end + 1);
                    lines << line;
                    if (answersHello && line == "hello EMC toffee 1.0")
                        socket->write("HELLO ACK EMCNETSVR 1.1\r\n");
                }
            });
        });
    }
    [[nodiscard]] quint16 port() const { return server.serverPort(); }

private:
    QByteArray m_buffer;
};

class OtherController : public QObject
{
public:
    QTcpServer server;
    QList<QByteArray> lines;
    std::function<QByteArray(const QByteArray &)> answer;
    // grblHAL answers the frame's 0xA2 (a real-time request for a PID log it lacks) with "error:20", in no
    // fixed order with the status report: when set, it comes after the status, just before the next answer.
    bool lateRealTimeError = false;

    OtherController()
    {
        server.listen(QHostAddress::LocalHost, 0);
        connect(&server, &QTcpServer::newConnection, this, [this] {
            QTcpSocket *socket = server.nextPendingConnection();
            connect(socket, &QTcpSocket::readyRead, this, [this, socket] {
                m_buffer += socket->readAll();
                for (qsizetype a; lateRealTimeError && (a = m_buffer.indexOf('\xa2')) >= 0;) {
                    m_buffer.remove(a, 1);
                    m_realTimeErrors += "error:20\r\n";
                }
                for (qsizetype q; (q = m_buffer.indexOf('?')) >= 0;) {
                    m_buffer.remove(q, 1);
                    socket->write("<Idle|MPos:0.000,0.000,0.000|FS:0,0>\r\n");
                }
                for (qsizetype end; (end = m_buffer.indexOf('\n')) >= 0;) {
                    const QByteArray line = m_buffer.left(end);
                    m_buffer.remove(0, end + 1);
                    lines << line;
                    if (m_realTimeErrors.isEmpty()) {
                        socket->write(answer(line));
                        continue;
                    }
                    // The real-time error first, the line's own answer a moment later, read apart.
                    socket->write(std::exchange(m_realTimeErrors, {}));
                    QTimer::singleShot(50, socket, [socket, a = answer(line)] { socket->write(a); });
                }
            });
        });
    }
    [[nodiscard]] QString address() const { return u"127.0.0.1:%1"_s.arg(server.serverPort()); }

private:
    QByteArray m_buffer;
    QByteArray m_realTimeErrors;
};

} // namespace

class TestControllerDetection : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void findsGrblHalOnAnyPortAndLinkAndChangesNothing_data()
    {
        QTest::addColumn<bool>("pty");
        QTest::newRow("TCP, not port 23") << false;
        QTest::newRow("a pseudo-terminal") << true;
    }
    void findsGrblHalOnAnyPortAndLinkAndChangesNothing()
    {
        if (GrblHalPeer::script().isEmpty())
            QSKIP(qPrintable(GrblHalPeer::skipReason()));
        QFETCH(bool, pty);
        GrblHalPeer peer({}, pty ? GrblHalPeer::Link::Pty : GrblHalPeer::Link::Tcp);
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        QVERIFY(pty || peer.port() != 23);
        MachineConnection connection;
        QList<ControllerKind> prepared;
        connection.setPreparer([&prepared](const MachineIdentity &identity, ConnectionTarget &) {
            prepared << identity.controller;
            return QString();
        });
        const ConnectionTarget target
            = pty ? portTarget(peer.pty()) : hostTarget(u"127.0.0.1:%1"_s.arg(peer.port()));
        QCOMPARE(target.knownController(), ControllerKind::Auto);
        const Outcome outcome = connectTo(connection, target);
        QVERIFY2(outcome.connected, qPrintable(outcome.message));
        QCOMPARE(connection.controllerKind(), ControllerKind::GrblHal);
        QCOMPARE(prepared, QList { ControllerKind::GrblHal });
        QVERIFY(connection.firmware().isGrblHal());
        QCOMPARE(connection.firmware().toolTableSize, 16);
        // Nothing was switched by the questions: the coolant is off (M9), as grblHAL starts.
        const QList<QByteArray> modes = ask(connection, "$G");
        QVERIFY(!modes.isEmpty());
        QVERIFY2(
            modes.front().contains(" M9 ") && !modes.front().contains(" M7 "), modes.front().constData());
    }

    void findsTheCarveraPlainAndFramed_data()
    {
        QTest::addColumn<QString>("protocol");
        QTest::addColumn<bool>("wifi");
        QTest::newRow("plain, UART") << u"smoothie"_s << false;
        QTest::newRow("plain, Wi-Fi") << u"smoothie"_s << true;
        QTest::newRow("framed, UART") << u"makera"_s << false;
        QTest::newRow("framed, Wi-Fi") << u"makera"_s << true;
    }
    void findsTheCarveraPlainAndFramed()
    {
        if (CarveraPeer::script().isEmpty())
            QSKIP(qPrintable(CarveraPeer::skipReason()));
        QFETCH(QString, protocol);
        QFETCH(bool, wifi);
        CarveraPeer peer({}, protocol);
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        MachineConnection connection;
        const Outcome outcome
            = connectTo(connection, wifi ? hostTarget(peer.wifi()) : portTarget(peer.uart()));
        QVERIFY2(outcome.connected, qPrintable(outcome.message));
        QCOMPARE(connection.controllerKind(), ControllerKind::Carvera);
        QCOMPARE(connection.firmware().kind, FirmwareInfo::Kind::Community);
        QCOMPARE(connection.firmware().version, u"2.1.0c-simulator"_s);
        const auto *stream = qobject_cast<const StreamTransport *>(connection.link()->transport());
        QVERIFY(stream);
        QCOMPARE(
            stream->mode(), protocol == u"makera" ? ConsoleStream::Mode::Framed : ConsoleStream::Mode::Text);
        QVERIFY(connection.connectResult().tlo.has_value()); // M493.4 read: the Carvera's own connect ran
    }

    // Plain text chosen for the framed firmware over Wi-Fi: refused by the first question, and the firmware
    // still answers the next connection (plain bytes would have left it deaf until restarted).
    void plainTextChosenForTheFramedFirmwareLeavesItAnswering()
    {
        if (CarveraPeer::script().isEmpty())
            QSKIP(qPrintable(CarveraPeer::skipReason()));
        CarveraPeer peer({}, u"makera"_s);
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        MachineConnection connection;
        ConnectionTarget chosen = hostTarget(peer.wifi());
        chosen.protocol = StreamTransport::Protocol::Text;
        const Outcome refused = connectTo(connection, chosen);
        QVERIFY(!refused.connected);
        QVERIFY2(refused.message.contains(u"speaks Makera's frames"_s), qPrintable(refused.message));
        connection.disconnectFromMachine();
        const Outcome found = connectTo(connection, hostTarget(peer.wifi()));
        QVERIFY2(found.connected, qPrintable(found.message));
        QCOMPARE(connection.controllerKind(), ControllerKind::Carvera);
    }

    // The Carvera chosen for a grblHAL machine: refused naming grblHAL, and grblHAL as it was.
    void aCarveraChosenForGrblHalIsRefusedByName()
    {
        if (GrblHalPeer::script().isEmpty())
            QSKIP(qPrintable(GrblHalPeer::skipReason()));
        GrblHalPeer peer;
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        MachineConnection connection;
        ConnectionTarget chosen = hostTarget(u"127.0.0.1:%1"_s.arg(peer.port()));
        chosen.controller = ControllerKind::Carvera;
        const Outcome refused = connectTo(connection, chosen);
        QVERIFY(!refused.connected);
        QVERIFY2(refused.message.contains(u"answered as grblHAL, not as Carvera as chosen"_s)
                && refused.message.contains(u"--controller grblhal"_s),
            qPrintable(refused.message));
        connection.disconnectFromMachine();
        QTest::qWait(200);
        const QList<QByteArray> modes = peer.ask("$G");
        QVERIFY(!modes.isEmpty());
        QVERIFY2(modes.front().contains(" M9 "), modes.front().constData());
    }

    // The first question's answers in another order (grblHAL's "error:20" to the frame's 0xA2 after its
    // status report, seen under load): read as the question's, not taken for the answer to `version`, so $I
    // gets its own answer and grblHAL is found.
    void answersToTheFirstQuestionInAnyOrder()
    {
        OtherController machine;
        machine.lateRealTimeError = true;
        machine.answer = [](const QByteArray &line) -> QByteArray {
            if (line == "$I")
                return "[VER:1.1f.20260817:]\r\n[OPT:VNML+,100,1024,3,16]\r\n[FIRMWARE:grblHAL]\r\nok\r\n";
            return "error:2\r\n";
        };
        MachineConnection connection;
        QList<ControllerKind> prepared;
        connection.setPreparer([&prepared](const MachineIdentity &identity, ConnectionTarget &) {
            prepared << identity.controller;
            return QString(u"stop here"_s);
        });
        const Outcome outcome = connectTo(connection, hostTarget(machine.address()));
        QCOMPARE(prepared, QList<ControllerKind> { ControllerKind::GrblHal });
        QVERIFY2(outcome.message.contains(u"stop here"_s), qPrintable(outcome.message));
        QCOMPARE(machine.lines.size(), 3);
        QCOMPARE(machine.lines.at(1), QByteArray("version"));
        QCOMPARE(machine.lines.at(2), QByteArray("$I"));
    }

    // A network machine that answers nothing to the first question is asked LinuxCNC's hello, and nothing
    // else: linuxcncrsh answers it, and is LinuxCNC. One that answers nothing at all is said to, within the
    // limits; with the Carvera chosen, the first question's silence fails as before, unasked.
    void aSilentConsoleIsAskedLinuxCncsHelloAlone()
    {
        SilentConsole console;
        MachineConnection connection;
        QList<ControllerKind> prepared;
        connection.setPreparer([&prepared](const MachineIdentity &identity, ConnectionTarget &) {
            prepared << identity.controller;
            return u"stop here"_s;
        });
        Outcome outcome = connectTo(connection, hostTarget(u"127.0.0.1:%1"_s.arg(console.port())));
        QCOMPARE(prepared, QList<ControllerKind> { ControllerKind::LinuxCnc });
        QCOMPARE(console.lines.size(), 2);
        QVERIFY(console.lines.at(0).startsWith("\x86h")); // the first question's frame, ended by Toffee
        QCOMPARE(console.lines.at(1), QByteArray("hello EMC toffee 1.0"));

        console.answersHello = false;
        console.lines.clear();
        MachineConnection nothing;
        QElapsedTimer clock;
        clock.start();
        outcome = connectTo(nothing, hostTarget(u"127.0.0.1:%1"_s.arg(console.port())));
        QVERIFY(!outcome.connected);
        QVERIFY2(outcome.message.contains(u"answered nothing"_s), qPrintable(outcome.message));
        QVERIFY(clock.elapsed() < 15000);

        console.lines.clear();
        MachineConnection chosen;
        ConnectionTarget carvera = hostTarget(u"127.0.0.1:%1"_s.arg(console.port()));
        carvera.controller = ControllerKind::Carvera;
        outcome = connectTo(chosen, carvera);
        QVERIFY(!outcome.connected);
        QVERIFY2(outcome.message.contains(u"did not answer within 3 s"_s), qPrintable(outcome.message));
        QVERIFY(!console.lines.contains("hello EMC toffee 1.0"));
    }

    // Classic Grbl (it answers $I without [FIRMWARE:grblHAL]) and a controller that is neither: refused by
    // what they said, and nothing was sent them but the questions (the first, its line end, `version`, $I).
    void anotherControllerIsRefusedByWhatItSaid_data()
    {
        QTest::addColumn<bool>("classicGrbl");
        QTest::newRow("classic Grbl") << true;
        QTest::newRow("neither") << false;
    }
    void anotherControllerIsRefusedByWhatItSaid()
    {
        QFETCH(bool, classicGrbl);
        OtherController machine;
        machine.answer = [classicGrbl](const QByteArray &line) -> QByteArray {
            if (!classicGrbl)
                return "WELCOME TO ACME CNC\r\n";
            if (line == "$I")
                return "[VER:1.1h.20190825:]\r\n[OPT:V,15,128]\r\nok\r\n";
            return "error:2\r\n";
        };
        MachineConnection connection;
        QList<ControllerKind> prepared;
        connection.setPreparer([&prepared](const MachineIdentity &identity, ConnectionTarget &) {
            prepared << identity.controller;
            return QString();
        });
        const Outcome refused = connectTo(connection, hostTarget(machine.address()));
        QVERIFY(!refused.connected);
        QVERIFY(prepared.isEmpty());
        QCOMPARE(connection.controllerKind(), ControllerKind::Auto);
        if (classicGrbl) {
            QVERIFY2(refused.message.contains(u"classic Grbl"_s), qPrintable(refused.message));
        } else {
            QVERIFY2(refused.message.contains(u"not a Carvera, grblHAL or LinuxCNC"_s)
                    && refused.message.contains(u"WELCOME TO ACME CNC"_s),
                qPrintable(refused.message));
        }
        QTest::qWait(300);
        QCOMPARE(machine.lines.size(), 3);
        QVERIFY(machine.lines.at(0).startsWith("\x86h")); // the first question's frame, ended by Toffee
        QCOMPARE(machine.lines.at(1), QByteArray("version"));
        QCOMPARE(machine.lines.at(2), QByteArray("$I"));
    }
};

QTEST_GUILESS_MAIN(TestControllerDetection)
#include "tst_controllerdetection.moc"
