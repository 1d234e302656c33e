// SPDX-License-Identifier: GPL-3.0-or-later
// The window over Wi-Fi when the link goes: lost while idle, and the verdict after it; lost in the middle of
// a probe, which records nothing, offers to reconnect, and on reconnecting says whether the probe happened.
// The emulator serves TCP in this process (tests/ui/networkmachine.h).
#include <QAbstractButton>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>
#include <QUdpSocket>

#include "tests/ui/networkmachine.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;
using namespace Toffee::Test;

class TestWifiLostLink : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { Test::isolateWindowTest(u"tst_wifilostlink"_s); }
    void init() { Test::startFresh(); }

    // The link goes while nothing runs: the window says so and offers to reconnect all the same.
    void aLinkLostWhileIdle()
    {
        NetworkMachine machine(u"Carvera_Idle"_s, freeUdpPort(), false);
        Station s;
        ConnectionTarget target;
        target.emulator = false;
        target.host = u"127.0.0.1"_s;
        target.tcpPort = machine.server.port();
        s.window.connection()->connectTo(target);
        QVERIFY(waitConnected(s));
        QString lost;
        answerBoxTitled(u"The link to the machine was lost"_s, u"reconnectButton"_s, &lost);
        machine.server.dropAll();
        QTRY_VERIFY_WITH_TIMEOUT(!lost.isEmpty(), 10000);
        QVERIFY2(lost.contains(u"closed the connection"_s) && lost.contains(u"Nothing was running"_s),
            qPrintable(lost));
        QVERIFY(waitConnected(s));
        QVERIFY(!s.window.connection()->interruption());
    }

    // What the machine holds after a lost link, against what it held before, in words.
    void theVerdictAfterALostLink_data()
    {
        QTest::addColumn<double>("tloBefore");
        QTest::addColumn<double>("tloNow");
        QTest::addColumn<bool>("currentMzNow");
        QTest::addColumn<QString>("says");
        QTest::newRow("changed") << -30.2 << -30.488 << true << u"It ran on the machine"_s;
        QTest::newRow("the same") << -30.2 << -30.2 << true << u"Nothing changed on the machine"_s;
        QTest::newRow("restarted") << -30.2 << 0.0 << false << u"as after a restart"_s;
        QTest::newRow("nothing before") << 0.0 << 0.0 << false << u"Nothing changed on the machine"_s;
    }
    void theVerdictAfterALostLink()
    {
        QFETCH(double, tloBefore);
        QFETCH(double, tloNow);
        QFETCH(bool, currentMzNow);
        QFETCH(QString, says);
        const MachineConnection::Interruption before { u"Probing T2…"_s, u"127.0.0.1:2222"_s, 2, tloBefore,
            std::nullopt };
        SessionResult now;
        now.tool = 2;
        now.tlo
            = TloReading { tloNow, -115.34, currentMzNow ? std::optional(-115.34 + tloNow) : std::nullopt };
        const QString verdict = MachineConnection::interruptionVerdict(before, now);
        QVERIFY2(verdict.contains(says), qPrintable(verdict));
        QVERIFY2(verdict.contains(u"Before \"Probing T2…\" the machine had T2"_s), qPrintable(verdict));
    }

    // The machine leaves the network in the middle of a probe: nothing recorded, a reconnect offered, and
    // on reconnecting the window says whether the probe happened, from the offsets the machine reads back.
    void aLinkLostMidProbe_data()
    {
        QTest::addColumn<bool>("probeRuns");
        QTest::newRow("the machine went on and probed") << true;
        QTest::newRow("the probe never reached the machine") << false;
    }
    void aLinkLostMidProbe()
    {
        QFETCH(bool, probeRuns);
        NetworkMachine machine(u"Carvera_Lost"_s, freeUdpPort(), true);
        Station s;
        QVERIFY(s.window.openFile(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json")));
        ConnectionTarget target;
        target.emulator = false;
        target.host = u"127.0.0.1"_s;
        target.tcpPort = machine.server.port();
        QString refused;
        QObject::connect(s.window.connection(), &MachineConnection::connectFailed, &s.window,
            [&refused](const QString &m) { refused = m; });
        answerBoxTitled(u"Cannot connect to the machine"_s, {}, &refused);
        s.window.connection()->connectTo(target);
        QVERIFY2(waitConnected(s) || refused.isEmpty(), qPrintable(refused));
        QVERIFY(waitConnected(s));
        QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"Idle"_s);

        // T1 measured first (the reference), then T2 goes in.
        QVERIFY(s.window.connection()->selectTool(1, {}));
        QVERIFY(waitIdle(s));
        s.probe();
        QVERIFY(waitIdle(s));
        QVERIFY(s.window.connection()->selectTool(2, {}));
        QVERIFY(waitIdle(s));
        QTRY_COMPARE(s.text(u"activeToolLabel"_s), u"T2"_s);
        const ToolTable before = s.table();
        const double tloBefore = machine.emulator.tlo();

        if (probeRuns) // a probe that takes a while, and the link drops in the middle of it
            machine.emulator.setTiming({ 1500, 0, 0 });
        else // the link drops as the probe's first command arrives
            machine.emulator.injectFault(CarveraEmulator::Fault::CloseLink, "M491");

        QString lost;
        QString verdict;
        answerNextBox(QMessageBox::Yes); // Probe T2?
        // One box: the link was lost, nothing written, Reconnect? Then what the machine holds now.
        answerBoxTitled(u"The link to the machine was lost"_s, u"reconnectButton"_s, &lost);
        s.trigger(u"actionProbe"_s);
        if (probeRuns) {
            QTRY_VERIFY(machine.emulator.isBusy());
            machine.server.dropAll();
        }
        QTRY_VERIFY_WITH_TIMEOUT(!lost.isEmpty(), 10000);
        QVERIFY2(lost.contains(u"during \"Probing T2…\""_s) && lost.contains(u"Nothing of it was written"_s)
                && lost.contains(u"Reconnect"_s),
            qPrintable(lost));
        QCOMPARE(s.table(), before); // nothing the machine did not confirm

        answerBoxTitled(u"Connected again"_s, {}, &verdict);
        refused.clear();
        answerBoxTitled(u"Cannot connect to the machine"_s, {}, &refused);
        QTRY_VERIFY_WITH_TIMEOUT(!verdict.isEmpty() || !refused.isEmpty(), 15000);
        QVERIFY2(refused.isEmpty(), qPrintable(refused));
        QVERIFY(waitConnected(s));
        if (probeRuns) {
            QTRY_VERIFY(!machine.emulator.isBusy());
            QVERIFY(machine.emulator.tlo() != tloBefore);
            QVERIFY2(verdict.contains(u"It ran on the machine"_s), qPrintable(verdict));
        } else {
            QCOMPARE(machine.emulator.tlo(), tloBefore);
            QVERIFY2(verdict.contains(u"Nothing changed on the machine"_s), qPrintable(verdict));
        }
        QVERIFY2(verdict.contains(u"Before \"Probing T2…\" the machine had T2"_s), qPrintable(verdict));
        QVERIFY(!s.window.connection()->interruption());
        QCOMPARE(s.table(), before); // still nothing recorded: probing again records it
        s.probe();
        QVERIFY(waitIdle(s));
        QCOMPARE(*s.table().find(2)->measuredTlo, machine.emulator.tlo());
    }
};

QTEST_MAIN(TestWifiLostLink)
#include "tst_wifilostlink.moc"
