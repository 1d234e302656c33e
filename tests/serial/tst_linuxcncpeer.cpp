// SPDX-License-Identifier: GPL-3.0-or-later
// LinuxCNC itself (TOFFEE_LINUXCNC_PEER: Debian's LinuxCNC run headless with a simulated tool setter) driven
// by Toffee's controller over linuxcncrsh, as an operator's session would, step after step on one LinuxCNC:
// found by asking, refused while in estop, off, not homed or not in MDI; two tools probed (the second with a
// G54 Z offset and G92 in force), LinuxCNC's tool.tbl on disk and its tool in force checked after each; a
// break test that passes and one that finds a tool shorter with nothing adopted; a TLO set and restored;
// select and change; push (a tool LinuxCNC lacks refused by name, nothing written) and pull from the file;
// another client taking control; an abort and a link lost mid-probe. Skipped, and says so, without the peer.
#include <cmath>

#include <QSignalSpy>
#include <QTcpServer>
#include <QTest>

#include "serial/machine/machinecontroller.h"
#include "serial/machine/machinelink.h"
#include "serial/machineconnection.h"
#include "serial/transport/linetransport.h"
#include "tests/support/linuxcncpeer.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

constexpr double kSetterZ = -100.0;
// Tool lengths below the spindle nose: T1 20 mm (the reference), T2 25 mm, T3 18 mm.
const std::map<int, double> kLengths { { 1, 20.0 }, { 2, 25.0 }, { 3, 18.0 } };

ToolSetter setter()
{
    ToolSetter s;
    s.x = 10;
    s.y = 10;
    s.zMin = -140;
    s.seekFeed = 3000;
    s.latchFeed = 200;
    s.safeZ = 0;
    return s;
}

// The same setter searching at 600 mm/min: 6 s from −20 to T3's contact, time enough to act mid-search.
ToolSetter slowSearch()
{
    ToolSetter s = setter();
    s.seekFeed = 600;
    return s;
}

SessionResult await(const std::function<bool(MachineConnection::Done)> &start, int limitMs = 120000)
{
    std::optional<SessionResult> result;
    if (!start([&result](const SessionResult &r) { result = r; }))
        return SessionResult::failed(SessionResult::Outcome::Refused, u"not started: busy or halted"_s);
    (void)QTest::qWaitFor([&] { return result.has_value(); }, limitMs);
    return result.value_or(
        SessionResult::failed(SessionResult::Outcome::LinkFailure, u"no result in time"_s));
}

} // namespace

class TestLinuxCncPeer : public QObject
{
    Q_OBJECT

    std::unique_ptr<LinuxCncPeer> m_peer;
    MachineConnection m_connection;
    std::optional<double> m_reference; // the reference Toffee keeps for this machine (T1's contact)

    ConnectionTarget target(ControllerKind kind = ControllerKind::Auto) const
    {
        ConnectionTarget t;
        t.emulator = false;
        t.host = u"127.0.0.1"_s;
        t.tcpPort = m_peer->port();
        t.controller = kind;
        t.setter = setter();
        t.reference = m_reference;
        return t;
    }
    bool connectTo(MachineConnection &connection, const ConnectionTarget &t, QString *why = nullptr)
    {
        QSignalSpy failed(&connection, &MachineConnection::connectFailed);
        connection.connectTo(t);
        (void)QTest::qWaitFor(
            [&] { return connection.state() == MachineConnection::State::Connected || !failed.isEmpty(); },
            30000);
        if (why && !failed.isEmpty())
            *why = failed.front().front().toString();
        return connection.state() == MachineConnection::State::Connected;
    }
    // The offset in force and the spindle's tool, as LinuxCNC says them through its own client.
    QByteArray programCodes() const { return m_peer->get("program_codes"); }
    double machineZ() const
    {
        const QList<QByteArray> xyz = m_peer->get("abs_act_pos").simplified().split(' ');
        return xyz.value(2).toDouble();
    }

private Q_SLOTS:
    void initTestCase()
    {
        if (const QString why = LinuxCncPeer::skipReason(); !why.isEmpty())
            QSKIP(qPrintable(why));
        m_peer = std::make_unique<LinuxCncPeer>(kLengths, kSetterZ);
        QVERIFY2(m_peer->started(), qPrintable(m_peer->errors()));
        qInfo("LinuxCNC started in %lld ms", m_peer->startupMs());
    }

    // Automatic detection finds LinuxCNC by its hello (nothing answers the first question), and connecting
    // moves nothing and works in estop; what it can do it says; an operation is refused saying what to do.
    void foundByItsHelloAndRefusedInEstop()
    {
        QString why;
        QVERIFY2(connectTo(m_connection, target(), &why), qPrintable(why));
        QCOMPARE(m_connection.controllerKind(), ControllerKind::LinuxCnc);
        QVERIFY(m_connection.firmware().isLinuxCnc());
        QVERIFY(m_connection.firmware().hasToolTable());
        QCOMPARE(m_connection.connectResult().status->state, u"Estop"_s);
        // Its table came from the file the INI it runs names (LinuxCNC runs on this computer).
        QVERIFY(m_connection.connectResult().controllerTools.has_value());
        QCOMPARE(m_connection.connectResult().controllerTools->size(), 4);
        const SessionResult refused = await([this](auto d) { return m_connection.selectTool(1, d); });
        QCOMPARE(refused.outcome, SessionResult::Outcome::Refused);
        QVERIFY2(refused.message.contains(u"estop"_s) && refused.message.contains(u"never releases"_s),
            qPrintable(refused.message));
        QCOMPARE(m_peer->get("estop"), QByteArray("ON"));
    }

    void refusedWhileOffNotHomedOrNotInMdi()
    {
        m_peer->ask({ "set estop off" });
        SessionResult r = await([this](auto d) { return m_connection.selectTool(1, d); });
        QVERIFY2(r.message.contains(u"is off"_s), qPrintable(r.message));
        m_peer->ask({ "set machine on" });
        r = await([this](auto d) { return m_connection.selectTool(1, d); });
        QVERIFY2(r.message.contains(u"not homed"_s), qPrintable(r.message));
        m_peer->ask({ "set mode manual", "set home -1" });
        QVERIFY(
            QTest::qWaitFor([this] { return m_peer->get("joint_homed").startsWith("YES YES YES"); }, 20000));
        r = await([this](auto d) { return m_connection.selectTool(1, d); });
        QVERIFY2(r.message.contains(u"manual mode"_s) && r.message.contains(u"MDI"_s), qPrintable(r.message));
        QCOMPARE(m_peer->get("mode"), QByteArray("MANUAL")); // Toffee switched nothing
        m_peer->ask({ "set mode mdi" });
        // The peer's client took the enable: Toffee says another program has control, and sends nothing.
        r = await([this](auto d) { return m_connection.selectTool(1, d); });
        QCOMPARE(r.outcome, SessionResult::Outcome::Refused);
        QVERIFY2(r.message.contains(u"Another program took control"_s), qPrintable(r.message));
        QCOMPARE(m_peer->get("tool"), QByteArray("0"));
        // Connected again, it holds the enable.
        m_connection.disconnectFromMachine();
        QString why;
        QVERIFY2(connectTo(m_connection, target(ControllerKind::LinuxCnc), &why), qPrintable(why));
        QVERIFY2(m_connection.firmware().description().startsWith(u"LinuxCNC 2."_s),
            qPrintable(m_connection.firmware().description()));
    }

    // T1 is the reference; T2 measured with a G54 Z offset and G92 in force is 5 mm longer: tool.tbl holds it
    // at once, G43 H2 is in force, and the spindle ends lifted.
    void probesTwoToolsWhateverWorkOffsetIsInForce()
    {
        SessionResult r = await([this](auto d) { return m_connection.selectTool(1, d); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(m_peer->get("tool"), QByteArray("1"));
        r = await([this](auto d) { return m_connection.probe(d); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(r.tlo->tlo(), 0.0);
        QVERIFY(std::fabs(*r.tlo->currentMz - (kSetterZ + 20.0)) < 0.01);
        QVERIFY2(r.message.contains(u"reference"_s), qPrintable(r.message));
        m_reference = r.tlo->referenceMz;
        QCOMPARE(m_peer->tableZ(1), 0.0);
        QVERIFY(std::fabs(machineZ()) < 0.01); // lifted to the safe Z

        // Someone's work offsets: G54 Z −33 and a G92 shift.
        const QList<QByteArray> offsets
            = m_peer->ask({ "set mdi G10 L2 P1 Z-33", "set mdi G54", "set mdi G92 Z7" });
        QCOMPARE(offsets, (QList<QByteArray> { "SET MDI ACK", "SET MDI ACK", "SET MDI ACK" }));
        QString why;
        m_connection.disconnectFromMachine();
        QVERIFY2(connectTo(m_connection, target(ControllerKind::LinuxCnc), &why), qPrintable(why));
        r = await([this](auto d) { return m_connection.selectTool(2, d); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        r = await([this](auto d) { return m_connection.probe(d); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QVERIFY2(std::fabs(r.tlo->tlo() - 5.0) < 0.01, qPrintable(QString::number(r.tlo->tlo())));
        QVERIFY2(
            m_peer->tableZ(2) && std::fabs(*m_peer->tableZ(2) - 5.0) < 0.01, m_peer->tableFile().constData());
        QVERIFY2(programCodes().contains("G43"), programCodes().constData());
        QCOMPARE(r.recording->tool, 2);
        m_peer->ask({ "set mdi G92.1", "set mdi G10 L2 P1 Z0" });
        m_connection.disconnectFromMachine();
        QVERIFY2(connectTo(m_connection, target(ControllerKind::LinuxCnc), &why), qPrintable(why));
        QCOMPARE(m_connection.activeTool(), 2);
    }

    // A probe that meets nothing (the search ends above T2's contact at −75) and one that starts touching
    // (the safe height below it): each said in words, nothing written, G90 back in force and the spindle
    // lifted.
    void aProbeThatMeetsNothingOrStartsTouchingIsSaid()
    {
        const QByteArray before = m_peer->tableFile();
        ToolSetter shallow = setter();
        shallow.zMin = -60;
        m_connection.session()->setToolSetter(shallow);
        SessionResult r = await([this](auto d) { return m_connection.probe(d); });
        m_connection.session()->setToolSetter(setter());
        QCOMPARE(r.outcome, SessionResult::Outcome::MachineError);
        QVERIFY2(r.message.contains(u"met nothing down to machine Z -60.000"_s), qPrintable(r.message));
        QVERIFY(!r.recording);
        QVERIFY(!programCodes().simplified().split(' ').contains("G91"));
        QVERIFY(std::fabs(machineZ()) < 0.01);
        ToolSetter low = setter();
        low.safeZ = -80; // T2 touches at −75: the setter triggers on the way down to the safe height
        m_connection.session()->setToolSetter(low);
        r = await([this](auto d) { return m_connection.probe(d); });
        m_connection.session()->setToolSetter(setter());
        QCOMPARE(r.outcome, SessionResult::Outcome::MachineError);
        QVERIFY2(r.message.contains(u"already touching"_s), qPrintable(r.message));
        QVERIFY(!programCodes().simplified().split(' ').contains("G91"));
        QCOMPARE(m_peer->tableFile(), before);
        // Lifted out of the setter by hand, as an operator would, for the next step.
        QCOMPARE(m_peer->ask({ "set mdi G90 G53 G0 Z0" }), QList<QByteArray> { "SET MDI ACK" });
        QString why;
        m_connection.disconnectFromMachine();
        QVERIFY2(connectTo(m_connection, target(ControllerKind::LinuxCnc), &why), qPrintable(why));
    }

    // T2 again, intact: passes. Worn 0.3 mm shorter: ToolBroken, nothing adopted in tool.tbl or in force, the
    // spindle stopped and lifted.
    void breakTestsCompareAndAdoptNothing()
    {
        SessionResult r = await([this](auto d) { return m_connection.breakTest(0.1, d, 5.0); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QVERIFY(std::fabs(r.breakTest->newTlo - 5.0) < 0.01);
        QVERIFY(m_peer->setLength(2, 24.7));
        r = await([this](auto d) { return m_connection.breakTest(0.1, d, 5.0); });
        QCOMPARE(r.outcome, SessionResult::Outcome::ToolBroken);
        QVERIFY2(r.message.contains(u"T2"_s) && r.message.contains(u"4.700"_s), qPrintable(r.message));
        QCOMPARE(r.recording->breakTestFailed, true);
        QVERIFY(std::fabs(*m_peer->tableZ(2) - 5.0) < 0.001);
        QVERIFY(std::fabs(machineZ()) < 0.01);
        // Below the firmware's smallest tolerance: refused before anything moves.
        r = await([this](auto d) { return m_connection.breakTest(0.01, d, 5.0); });
        QCOMPARE(r.outcome, SessionResult::Outcome::Refused);
        QVERIFY(m_peer->setLength(2, 25.0));
    }

    // A TLO set by hand and one restored reach tool.tbl and the offset in force; M6 changes tools (the peer's
    // change ends at once) and measures the new one.
    void setRestoreSelectAndChange()
    {
        SessionResult r = await([this](auto d) { return m_connection.setTlo(5.5, d); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QVERIFY(std::fabs(*m_peer->tableZ(2) - 5.5) < 0.001);
        r = await([this](auto d) { return m_connection.restoreTlo(2, 5.0, d); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QVERIFY(std::fabs(*m_peer->tableZ(2) - 5.0) < 0.001);
        QCOMPARE(m_connection.session()->setTloCommand(1.25), u"G10 L1 P2 Z1.25, G43 H2"_s);
        // An offset beyond any machine's: refused before anything is sent.
        r = await([this](auto d) { return m_connection.setTlo(1e6, d); });
        QCOMPARE(r.outcome, SessionResult::Outcome::Refused);
        QVERIFY(std::fabs(*m_peer->tableZ(2) - 5.0) < 0.001);
        r = await([this](auto d) { return m_connection.changeTool(3, d); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(m_peer->get("tool"), QByteArray("3"));
        QVERIFY2(std::fabs(r.tlo->tlo() - (-2.0)) < 0.01, qPrintable(QString::number(r.tlo->tlo())));
        QVERIFY(std::fabs(*m_peer->tableZ(3) + 2.0) < 0.001);
        // A tool LinuxCNC's table lacks is refused by LinuxCNC, in its words.
        r = await([this](auto d) { return m_connection.selectTool(9, d); });
        QCOMPARE(r.outcome, SessionResult::Outcome::MachineError);
        QVERIFY2(r.message.contains(u"M61 Q9"_s), qPrintable(r.message));
        QCOMPARE(m_peer->get("tool"), QByteArray("3"));
    }

    // T3 as a face mill: three touches 5 mm off the setter's centre, each said, the TLO from the highest; the
    // same length every time here (LinuxCNC's setter has one per tool), so the spread is the latch's own.
    // LinuxCNC cannot turn the spindle to an angle: said. A break test touches as often.
    void aToolTouchedOnEachEdgeOffCentre()
    {
        ProbePlan plan;
        plan.touches = 3;
        plan.offsetX = 5.0;
        plan.spreadLimit = 0.05;
        m_connection.setProbePlans([plan](int tool) { return tool == 3 ? plan : ProbePlan {}; });
        SessionResult r = await([this](auto d) { return m_connection.probe(d); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(r.tlo->touches.size(), 3);
        QVERIFY2(spreadOf(r.tlo->touches) <= 0.004, qPrintable(QString::number(spreadOf(r.tlo->touches))));
        QCOMPARE(*r.tlo->currentMz, highestTouch(r.tlo->touches));
        QVERIFY(std::fabs(r.tlo->tlo() + 2.0) < 0.01);
        QCOMPARE(r.recording->touches, r.tlo->touches);
        QVERIFY2(r.message.contains(u"LinuxCNC cannot turn its spindle"_s), qPrintable(r.message));
        QVERIFY2(!r.message.contains(u"edges differ"_s), qPrintable(r.message));
        const QList<QByteArray> xyz = m_peer->get("abs_act_pos").simplified().split(' ');
        QVERIFY2(std::fabs(xyz.value(0).toDouble() - 15.0) < 0.01, m_peer->get("abs_act_pos").constData());
        QVERIFY(std::fabs(machineZ()) < 0.01);
        r = await([this](auto d) { return m_connection.breakTest(0.1, d, -2.0); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(r.breakTest->touches.size(), 3);
        // A touch-off point beyond the machine: refused before anything moves.
        plan.offsetX = 150.0;
        m_connection.setProbePlans([plan](int) { return plan; });
        r = await([this](auto d) { return m_connection.probe(d); });
        QCOMPARE(r.outcome, SessionResult::Outcome::Refused);
        m_connection.setProbePlans(nullptr);
        // T3's TLO back to the change's −2.000 (the latch's last micrometres aside), for the steps after.
        r = await([this](auto d) { return m_connection.restoreTlo(3, -2.0, d); });
        QVERIFY2(r.ok(), qPrintable(r.message));
    }

    // Push: a tool not in LinuxCNC's table refuses the whole push by name; the others written and read back
    // from the file. Pull reads the file as LinuxCNC rewrote it.
    void pushIsAllOrNothingAndPullReadsTheFile()
    {
        const QByteArray before = m_peer->tableFile();
        SessionResult r = await([this](auto d) {
            return m_connection.writeToolTable({ { 1, 0.0, 1.5 }, { 4, 3.25, 1.0 }, { 12, 1.0, 1.0 } }, d);
        });
        QCOMPARE(r.outcome, SessionResult::Outcome::Refused);
        QVERIFY2(r.message.contains(u"T12"_s) && !r.message.contains(u"T4,"_s), qPrintable(r.message));
        QCOMPARE(m_peer->tableFile(), before);
        r = await([this](auto d) {
            return m_connection.writeToolTable({ { 1, 0.0, 1.5 }, { 4, 3.25, 1.0 } }, d);
        });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QVERIFY(std::fabs(*m_peer->tableZ(4) - 3.25) < 0.001);
        QVERIFY2(m_peer->tableFile().contains("2 mm ball end mill"), "LinuxCNC's remarks are kept");
        r = await([this](auto d) { return m_connection.readToolTable(d); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QList<ControllerTool> expected { { 1, 0.0, 1.5 }, { 2, 5.0, 3.0 }, { 3, -2.0, 5.0 },
            { 4, 3.25, 1.0 } };
        QCOMPARE(*r.controllerTools, expected);
    }

    // Stop during a probe: LinuxCNC aborts it (from a second connection, the first waiting for its line), the
    // probe ends as a failure with nothing written, and the next operation takes the enable back.
    void stopMidProbeAbortsIt()
    {
        const QByteArray before = m_peer->tableFile();
        // A slow search (T3 touches at −82): the stop lands while it goes down, however loaded the computer.
        m_connection.session()->setToolSetter(slowSearch());
        std::optional<SessionResult> result;
        QVERIFY(m_connection.probe([&result](const SessionResult &r) { result = r; }));
        QVERIFY(QTest::qWaitFor([&] { return result.has_value() || machineZ() < -20.0; }, 30000));
        QVERIFY2(!result, qPrintable(result->message));
        m_connection.stop();
        QVERIFY(QTest::qWaitFor([&result] { return result.has_value(); }, 20000));
        QVERIFY2(result->message.startsWith(u"Stopped: LinuxCNC aborted"_s), qPrintable(result->message));
        QVERIFY(!result->recording);
        QCOMPARE(m_peer->tableFile(), before);
        const double stoppedAt = machineZ();
        QTest::qWait(500);
        QCOMPARE(machineZ(), stoppedAt); // it stays where it stopped
        const SessionResult again = await([this](auto d) { return m_connection.selectTool(3, d); });
        QVERIFY2(again.ok(), qPrintable(again.message));
    }

    // The link lost mid-probe: the probe fails as a link failure within its limit, nothing recorded; LinuxCNC
    // goes on to the end of its move.
    void aLinkLostMidProbeRecordsNothing()
    {
        const QByteArray before = m_peer->tableFile();
        m_connection.session()->setToolSetter(slowSearch());
        std::optional<SessionResult> result;
        QVERIFY(m_connection.probe([&result](const SessionResult &r) { result = r; }));
        // Lifted first (the last test stopped it low), then on its way down to the setter.
        QVERIFY(QTest::qWaitFor([&] { return result.has_value() || machineZ() > -1.0; }, 30000));
        QVERIFY(QTest::qWaitFor([&] { return result.has_value() || machineZ() < -20.0; }, 30000));
        QVERIFY2(!result, qPrintable(result->message));
        m_connection.link()->transport()->close();
        QVERIFY(QTest::qWaitFor([&result] { return result.has_value(); }, 10000));
        QCOMPARE(result->outcome, SessionResult::Outcome::LinkFailure);
        QVERIFY2(result->message.contains(u"G38.2"_s), qPrintable(result->message));
        QVERIFY(!result->recording);
        QCOMPARE(m_peer->tableFile(), before);
        QVERIFY(QTest::qWaitFor([this] { return m_peer->get("program_status") == "IDLE"; }, 30000));
    }
};

QTEST_GUILESS_MAIN(TestLinuxCncPeer)
#include "tst_linuxcncpeer.moc"
