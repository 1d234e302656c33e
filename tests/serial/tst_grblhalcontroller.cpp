// SPDX-License-Identifier: GPL-3.0-or-later
// GrblHalController on a grblHAL build the test peer is not: one built without a tool table ([OPT:…,0]),
// which only G43.1 can give a TLO. The peer (tst_grblhalcli) is the reference for everything it can show;
// this controller answers on TCP as grblHAL 1.1f does (the replies are the peer's, taken from its README and
// tst_grblhalpeer), with a table size of 0, and keeps the offset a G43.1 sets.
#include <QEventLoop>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>

#include "serial/grblhal/grblhalcontroller.h"
#include "serial/machine/machinelink.h"
#include "serial/transport/tcptransport.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

// grblHAL without a tool table, on a port of 127.0.0.1: what it answers to each line Toffee sends.
class TablelessGrblHal : public QObject
{
public:
    QTcpServer server;
    QList<QByteArray> received;
    double tlo = 0.0;
    int tool = 2;
    double contactZ = -54.7; // where G38.2 says it touched (machine Z)
    int tableSize = 0; // a build with a tool table of this many tools lists each in $#
    bool jogsUntilCancelled = false; // a jog runs (state Jog) until a jog cancel (0x85) stops it
    bool jogging = false;
    QByteArray realtime; // the real-time bytes received other than '?' (0x85 jog cancel, 0x18 reset)

    TablelessGrblHal()
    {
        server.listen(QHostAddress::LocalHost, 0);
        connect(&server, &QTcpServer::newConnection, this, [this] {
            QTcpSocket *socket = server.nextPendingConnection();
            connect(socket, &QTcpSocket::readyRead, this, [this, socket] {
                m_buffer += socket->readAll();
                // Real-time commands wherever they come (in the first question's frame too).
                for (const char byte : { '\x85', '\x18' }) {
                    for (qsizetype q; (q = m_buffer.indexOf(byte)) >= 0;) {
                        m_buffer.remove(q, 1);
                        realtime += byte;
                        if (byte == '\x85')
                            jogging = false;
                    }
                }
                for (qsizetype q; (q = m_buffer.indexOf('?')) >= 0;) {
                    m_buffer.remove(q, 1);
                    socket->write(QByteArray(jogging ? "<Jog" : "<Idle")
                        + "|MPos:0.000,0.000,0.000|Bf:100,1023|FS:0,0|T:" + QByteArray::number(tool)
                        + ">\r\n");
                }
                for (;;) {
                    const qsizetype end = m_buffer.indexOf('\n');
                    if (end < 0)
                        break;
                    const QByteArray line = m_buffer.left(end).trimmed();
                    m_buffer.remove(0, end + 1);
                    received << line;
                    socket->write(answer(line));
                }
            });
        });
    }
    [[nodiscard]] quint16 port() const { return server.serverPort(); }

private:
    QByteArray answer(const QByteArray &line)
    {
        if (line == "$I")
            return "[VER:1.1f.20260817:]\r\n[OPT:VNML+,100,1024,3," + QByteArray::number(tableSize)
                + "]\r\n[AXS:3:XYZ]\r\n[NEWOPT:ENUMS,RT+,TC,SED]\r\n[FIRMWARE:grblHAL]\r\nok\r\n";
        if (line == "$G")
            return "[GC:G0 G54 G17 G21 G90 G94 G40 G49 G98 G50 M5 M9 T" + QByteArray::number(tool)
                + " F0 S0.]\r\nok\r\n";
        if (line == "$#") {
            QByteArray tools;
            for (int t = 1; t <= tableSize; ++t)
                tools += "[T:" + QByteArray::number(t) + "|0.000,0.000," + QByteArray::number(t * 0.5, 'f', 3)
                    + "|0.000|6,0,0||" + QByteArray::number(t) + "]\r\n";
            return "[G54:0.000,0.000,0.000]\r\n[G92:0.000,0.000,0.000]\r\n" + tools + "[TLO:0.000,0.000,"
                + QByteArray::number(tlo, 'f', 3) + "]\r\n[PRB:0.000,0.000,0.000:0]\r\nok\r\n";
        }
        if (line.startsWith("G43.1 Z")) {
            tlo = line.mid(7).toDouble();
            return "ok\r\n";
        }
        if (line.startsWith("G38.2"))
            return "[PRB:0.000,0.000," + QByteArray::number(contactZ, 'f', 3) + ":1]\r\nok\r\n";
        if (line.startsWith("$J="))
            jogging = jogsUntilCancelled;
        if (line.startsWith("G10 L1") || line.startsWith("G43 H"))
            return "error:38\r\n"; // no such tool: the build has no table
        return "ok\r\n";
    }
    QByteArray m_buffer;
};

SessionResult await(const std::function<void(MachineController::Done)> &start)
{
    QEventLoop loop;
    SessionResult result;
    bool done = false;
    QTimer::singleShot(10000, &loop, &QEventLoop::quit);
    start([&](const SessionResult &r) {
        result = r;
        done = true;
        loop.quit();
    });
    if (!done)
        loop.exec();
    return result;
}

// The controller on its own link to `machine`, over a real socket on 127.0.0.1, speaking plain text.
struct Rig
{
    explicit Rig(const TablelessGrblHal &machine)
        : transport(TcpTransport::Address { QStringLiteral("127.0.0.1"), machine.port() })
    {
        transport.setProtocol(StreamTransport::Protocol::Text);
    }
    TcpTransport transport;
    MachineLink link { &transport };
    GrblHalController controller { &link };
};

} // namespace

class TestGrblHalController : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void aBuildWithoutAToolTableGetsItsTloWithG431()
    {
        TablelessGrblHal machine;
        Rig rig(machine);
        GrblHalController &controller = rig.controller;
        controller.adoptReference(-70.0);
        const SessionResult connected = await([&](auto done) { controller.connectToMachine(done); });
        QVERIFY2(connected.ok(), qPrintable(connected.message));
        QCOMPARE(controller.firmware().kind, FirmwareInfo::Kind::GrblHal);
        QCOMPARE(controller.firmware().toolTableSize, 0);
        QVERIFY(!controller.firmware().hasToolTable());
        QCOMPARE(controller.activeTool(), std::optional(2));
        QCOMPARE(controller.setTloCommand(12.5), u"G43.1 Z12.5"_s);

        // Set by hand: G43.1, read back, said; never G10 L1 (which this build refuses).
        const SessionResult set = await([&](auto done) { controller.setTlo(12.5, done); });
        QVERIFY2(set.ok(), qPrintable(set.message));
        QVERIFY2(set.message.contains(u"keeps no tool table"_s), qPrintable(set.message));
        QCOMPARE(set.tlo->tlo(), 12.5);
        QVERIFY(set.recording.has_value());
        QCOMPARE(*set.recording->tlo, 12.5);
        QVERIFY(machine.received.contains("G43.1 Z12.5"));
        QVERIFY(!std::any_of(machine.received.cbegin(), machine.received.cend(),
            [](const QByteArray &l) { return l.startsWith("G10"); }));

        // Its table cannot be read or written: refused by name, nothing sent.
        const qsizetype before = machine.received.size();
        const SessionResult pushed = await([&](auto done) {
            controller.writeToolTable({ { 2, 12.5, 0.0 } }, done);
        });
        QCOMPARE(pushed.outcome, SessionResult::Outcome::Refused);
        QVERIFY2(pushed.message.contains(u"keeps no tool table"_s), qPrintable(pushed.message));
        QCOMPARE(machine.received.size(), before);
        QVERIFY(!controller.controllerTable().has_value());

        // A break test of a tool with no stored TLO (no table here, none given) is refused before anything
        // moves: the offset in force could be another tool's.
        const qsizetype sent = machine.received.size();
        const SessionResult test = await([&](auto done) { controller.breakTest(0.1, done); });
        QCOMPARE(test.outcome, SessionResult::Outcome::Refused);
        QVERIFY2(test.message.contains(u"no stored TLO"_s), qPrintable(test.message));
        QCOMPARE(machine.received.size(), sent);

        // A restore after a reset: M61 and G43.1, read back.
        machine.tlo = 0.0;
        const SessionResult restored = await([&](auto done) { controller.restoreTlo(2, 12.5, done); });
        QVERIFY2(restored.ok(), qPrintable(restored.message));
        QCOMPARE(machine.tlo, 12.5);
        QCOMPARE(controller.restoreCommand(2, 12.5), u"M61 Q2, G43.1 Z12.5"_s);
    }

    // One range before anything is written: a probe whose contact lies outside the search (a garbled or
    // hostile reply: Z -99999 once made a TLO of -99929 mm that reached grblHAL and the history) writes
    // nothing and records nothing; nor does a TLO beyond any tool, however it comes.
    void aReadingBeyondAnyToolIsWrittenNowhere()
    {
        TablelessGrblHal machine;
        machine.contactZ = -99999.0;
        Rig rig(machine);
        GrblHalController &controller = rig.controller;
        controller.adoptReference(-70.0);
        controller.setToolSetter(ToolSetter { 0.0, 0.0, -120.0, 3000.0, 300.0, 2.0, 0.0 });
        QVERIFY(await([&](auto done) { controller.connectToMachine(done); }).ok());
        const auto writes = [&machine] {
            return std::count_if(machine.received.cbegin(), machine.received.cend(),
                [](const QByteArray &l) { return l.startsWith("G10") || l.startsWith("G43"); });
        };
        const SessionResult probed = await([&](auto done) { controller.probe(done); });
        QCOMPARE(probed.outcome, SessionResult::Outcome::MachineError);
        QVERIFY2(probed.message.contains(u"outside the search"_s), qPrintable(probed.message));
        QVERIFY(!probed.recording);
        QCOMPARE(writes(), 0);

        // A setter set that deep (beyond any machine's coordinates) is refused before anything moves.
        machine.contactZ = -99000.0;
        controller.setToolSetter(ToolSetter { 0.0, 0.0, -99999.0, 3000.0, 300.0, 2.0, 0.0 });
        const qsizetype sentBefore = machine.received.size();
        const SessionResult deep = await([&](auto done) { controller.probe(done); });
        QCOMPARE(deep.outcome, SessionResult::Outcome::Refused);
        QCOMPARE(machine.received.size(), sentBefore);
        QVERIFY2(deep.message.contains(u"from -999.999 to 999.999 mm"_s), qPrintable(deep.message));
        QVERIFY(!deep.recording);
        QCOMPARE(writes(), 0);
        QCOMPARE(machine.tlo, 0.0);
    }

    // A jog is relative and in millimetres whatever is in force ($J=G91 G21), each axis moved only when
    // asked; a step beyond the limit, a feed outside the setter's, or no step at all is refused with nothing
    // sent.
    void aJogIsBoundedAndSaysWhatItSent()
    {
        TablelessGrblHal machine;
        Rig rig(machine);
        GrblHalController &controller = rig.controller;
        QVERIFY(await([&](auto done) { controller.connectToMachine(done); }).ok());
        const qsizetype before = machine.received.size();
        const SessionResult moved = await([&](auto done) {
            controller.jog({ 10.0, -0.1, 0.0 }, 1000.0, done);
        });
        QVERIFY2(moved.ok(), qPrintable(moved.message));
        QVERIFY(moved.status.has_value());
        QVERIFY2(machine.received.contains("$J=G91 G21 X10 Y-0.1 F1000"),
            machine.received.join(" | ").constData());
        for (const auto &[step, feed] : { std::pair { std::array { 50.5, 0.0, 0.0 }, 1000.0 },
                 std::pair { std::array { 0.0, 0.0, 1.0 }, 0.0 },
                 std::pair { std::array { 0.0, 0.0, qQNaN() }, 1000.0 },
                 std::pair { std::array { 0.0, 0.0, 0.0 }, 1000.0 } }) {
            const qsizetype sent = machine.received.size();
            const SessionResult refused = await([&](auto done) { controller.jog(step, feed, done); });
            QCOMPARE(refused.outcome, SessionResult::Outcome::Refused);
            QVERIFY(!refused.message.isEmpty());
            QCOMPARE(machine.received.size(), sent);
        }
        QCOMPARE(std::count_if(machine.received.cbegin() + before, machine.received.cend(),
                     [](const QByteArray &l) { return l.startsWith("$J="); }),
            1);
    }

    // Stop during a jog is grblHAL's jog cancel (0x85), not a reset: the jog ends where the machine stands,
    // said so, and the machine stays ready (no alarm, no Unlock). With no jog under way, Stop is a reset as
    // before.
    void stoppingAJogCancelsItWithoutAHalt()
    {
        TablelessGrblHal machine;
        machine.jogsUntilCancelled = true;
        Rig rig(machine);
        GrblHalController &controller = rig.controller;
        QVERIFY(await([&](auto done) { controller.connectToMachine(done); }).ok());
        std::optional<SessionResult> jogged;
        controller.jog({ 40.0, 0.0, 0.0 }, 100.0, [&jogged](const SessionResult &r) { jogged = r; });
        QTRY_VERIFY(machine.jogging);
        QTest::qWait(300); // still jogging: its state is read and it goes on
        QVERIFY(!jogged);
        controller.stopJog();
        QTRY_VERIFY(jogged.has_value());
        QVERIFY2(jogged->ok(), qPrintable(jogged->message));
        QVERIFY2(
            jogged->message.contains(u"stopped where the machine stands"_s), qPrintable(jogged->message));
        QCOMPARE(machine.realtime, QByteArray("\x85"));
        controller.stopJog(); // nothing jogs now: a reset, as Stop
        QTRY_COMPARE(machine.realtime, QByteArray("\x85\x18"));
    }

    // A table of 300 tools is 300 lines of $#, more than a reply usually keeps: read whole, not "malformed".
    void aLargeToolTableIsReadWhole()
    {
        TablelessGrblHal machine;
        machine.tableSize = 300;
        Rig rig(machine);
        GrblHalController &controller = rig.controller;
        const SessionResult connected = await([&](auto done) { controller.connectToMachine(done); });
        QVERIFY2(connected.ok(), qPrintable(connected.message));
        QCOMPARE(controller.firmware().toolTableSize, 300);
        QVERIFY(connected.controllerTools);
        QCOMPARE(connected.controllerTools->size(), 300);
        QCOMPARE(connected.controllerTools->last().tlo, 150.0);
    }
};

QTEST_GUILESS_MAIN(TestGrblHalController)
#include "tst_grblhalcontroller.moc"
