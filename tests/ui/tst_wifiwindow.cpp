// SPDX-License-Identifier: GPL-3.0-or-later
// The window over Wi-Fi, as an owner reaches a Carvera: the connection panel's Wi-Fi choice lists the
// machines heard announcing themselves (name, address, busy), connects to one chosen or typed, remembers it,
// names a busy machine before connecting, and keeps reading the strip while a box is open (a lost link:
// tst_wifilostlink). The emulator serves TCP in this process
// (its beacons to a port of the test's own); the Carvera's real firmware (TOFFEE_CARVERA_PEER), framed as
// Makera's firmware, is found by its own beacon on UDP 3333, connected to, and probes and break-tests a tool.
// With TOFFEE_SCREENSHOTS set, the window is saved there.
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

class TestWifiWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { Test::isolateWindowTest(u"tst_wifiwindow"_s); }
    void init() { Test::startFresh(); }

    // Heard, chosen, connected, probed; the next start remembers the machine.
    void aMachineHeardIsConnectedByWifiAndRemembered()
    {
        const quint16 discovery = freeUdpPort();
        NetworkMachine machine(u"Carvera_Shop"_s, discovery, true);
        {
            Station s;
            panelOf(s)->setDiscoveryPort(discovery);
            auto *link = s.find<QComboBox>(u"linkCombo"_s);
            QCOMPARE(link->currentText(), u"Built-in emulator"_s); // a first start: nothing remembered
            link->setCurrentIndex(link->findText(u"Wi-Fi"_s));
            QVERIFY(s.find<QComboBox>(u"wifiMachineCombo"_s)->isVisible());
            QVERIFY(!s.find<QComboBox>(u"baudCombo"_s)->isVisible()); // a network has no baud rate
            QVERIFY(!s.find<QPushButton>(u"runBreakTestButton"_s)->isEnabled()); // nothing to test yet

            // The list fills as the beacon arrives: name, address, not busy; the one machine heard is chosen.
            QTRY_COMPARE_WITH_TIMEOUT(
                heard(s), QStringList { u"Carvera_Shop — "_s + machine.address() }, 5000);
            QCOMPARE(s.find<QComboBox>(u"wifiMachineCombo"_s)->currentText(), heard(s).front());
            QTRY_COMPARE(s.text(u"connectionHint"_s), u"One machine heard on the network."_s);

            QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
            QVERIFY(waitConnected(s));
            QCOMPARE(s.window.connection()->target().name(), machine.address());
            QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"Idle"_s);
            QVERIFY2(s.window.connection()->description().contains(u"(framed)"_s),
                qPrintable(s.window.connection()->description()));
            QVERIFY(!s.find<QComboBox>(u"linkCombo"_s)->isEnabled());
            QVERIFY(!panelOf(s)->listener()->isListening()); // nothing heard while connected: it is us

            // T1 in the spindle, probed over Wi-Fi: the table has its TLO, as on a cable.
            QVERIFY(s.window.openFile(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json")));
            QVERIFY(s.window.connection()->selectTool(1, {}));
            QVERIFY(waitIdle(s));
            s.probe();
            QVERIFY(waitIdle(s));
            QVERIFY(s.table().find(1)->measuredTlo.has_value());
            QCOMPARE(*s.table().find(1)->measuredTlo, machine.emulator.tlo());
            screenshot(s.window, u"wifi-connected.png"_s);
            s.window.connection()->disconnectFromMachine();
        }
        QCOMPARE(AppSettings().connectionHostName(), u"Carvera_Shop"_s);
        {
            // The next start shows the same machine, by its address, ready to connect.
            Station again;
            panelOf(again)->setDiscoveryPort(discovery);
            QCOMPARE(again.find<QComboBox>(u"linkCombo"_s)->currentText(), u"Wi-Fi"_s);
            QVERIFY2(again.find<QComboBox>(u"wifiMachineCombo"_s)->currentText().contains(machine.address()),
                qPrintable(again.find<QComboBox>(u"wifiMachineCombo"_s)->currentText()));
            QCOMPARE(panelOf(again)->target().name(), machine.address());
            // Enter in the address connects, as the button does.
            QTest::keyClick(again.find<QComboBox>(u"wifiMachineCombo"_s)->lineEdit(), Qt::Key_Return);
            QVERIFY(waitConnected(again));
        }
        // The machine got another address (its router's DHCP): found again by its name.
        NetworkMachine moved(u"Carvera_Shop"_s, discovery, true);
        QVERIFY(moved.address() != machine.address());
        machine.beacon.reset(); // the old address is heard no more
        Station third;
        panelOf(third)->setDiscoveryPort(discovery);
        QTRY_COMPARE_WITH_TIMEOUT(panelOf(third)->target().name(), moved.address(), 5000);
        QCOMPARE(third.find<QComboBox>(u"wifiMachineCombo"_s)->currentText(),
            u"Carvera_Shop — "_s + moved.address());
    }

    // While the broken-tool alarm is open (a modal box, opened from the break test's answer), the strip keeps
    // reading the machine: the halt is shown as the machine says it, never "no status report for 17 s".
    void theStripKeepsReadingWhileABoxIsOpen()
    {
        NetworkMachine machine(u"Carvera_Box"_s, freeUdpPort(), false);
        Station s;
        panelOf(s)->setKind(ConnectionPanel::Kind::WiFi);
        s.find<QComboBox>(u"wifiMachineCombo"_s)->setEditText(machine.address());
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QVERIFY(waitConnected(s));
        QVERIFY(s.window.openFile(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json")));
        QVERIFY(s.window.connection()->selectTool(1, {}));
        QVERIFY(waitIdle(s));
        s.probe();
        QVERIFY(waitIdle(s));
        machine.emulator.setToolLength(1, 20.0); // shorter now: broken

        bool sawBox = false;
        qint64 oldestStatusMs = 0;
        QString state;
        std::function<void(int)> answer = [&](int attempts) {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            if (box && box->objectName() != u"brokenToolAlarm"_s) {
                box->button(QMessageBox::Yes)->click(); // the break test's own question
            } else if (box) {
                sawBox = true;
                // Three seconds with the box open, twice the strip's stale limit: the reports keep coming.
                auto *sample = new QTimer(box);
                auto open = std::make_shared<QElapsedTimer>();
                open->start();
                connect(sample, &QTimer::timeout, box, [&, sample, open, box] {
                    oldestStatusMs = std::max(oldestStatusMs, s.window.connection()->link()->statusAgeMs());
                    if (open->elapsed() > 3000) {
                        sample->stop();
                        state = s.text(u"machineStateLabel"_s);
                        box->findChild<QAbstractButton *>(u"alarmLeaveHaltedButton"_s)->click();
                    }
                });
                sample->start(100);
                return;
            }
            if (attempts > 0)
                QTimer::singleShot(20, [&answer, attempts] { answer(attempts - 1); });
        };
        QTimer::singleShot(0, [&answer] { answer(1500); });
        s.trigger(u"actionBreakTest"_s);
        QVERIFY(QTest::qWaitFor([&] { return !state.isEmpty(); }, 30000));
        QVERIFY(sawBox);
        QVERIFY2(oldestStatusMs < int(MachineConnection::kStaleAfterMs),
            qPrintable(QString::number(oldestStatusMs)));
        QCOMPARE(state, u"HALTED"_s);
    }

    // A typed address works without a beacon; a wrong one is said in words, and nothing hangs.
    void aTypedAddress()
    {
        NetworkMachine machine(u"Quiet"_s, freeUdpPort(), false); // its beacon goes where nobody listens
        Station s;
        panelOf(s)->setDiscoveryPort(freeUdpPort());
        panelOf(s)->setKind(ConnectionPanel::Kind::WiFi);
        QTRY_VERIFY(s.text(u"connectionHint"_s).contains(u"None heard yet"_s));
        auto *combo = s.find<QComboBox>(u"wifiMachineCombo"_s);

        QString said;
        combo->setEditText(u"127.0.0.1:99999"_s);
        answerBoxTitled(u"Cannot connect to the machine"_s, {}, &said);
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QTRY_VERIFY(!said.isEmpty());
        QVERIFY2(said.contains(u"127.0.0.1:99999"_s) && said.contains(u"HOST:PORT"_s), qPrintable(said));
        QCOMPARE(s.window.connection()->state(), MachineConnection::State::Disconnected);

        // Nothing listens there: refused, in words, at once.
        QTcpServer closed;
        QVERIFY(closed.listen(QHostAddress::LocalHost, 0));
        const quint16 nobody = closed.serverPort();
        closed.close();
        said.clear();
        combo->setEditText(u"127.0.0.1:"_s + QString::number(nobody));
        answerBoxTitled(u"Cannot connect to the machine"_s, {}, &said);
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!said.isEmpty(), 10000);
        QVERIFY2(said.contains(u"connection was refused"_s), qPrintable(said));

        combo->setEditText(machine.address());
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QVERIFY(waitConnected(s));
        QVERIFY2(!s.window.connection()->description().contains(u"(framed)"_s),
            qPrintable(s.window.connection()->description()));
        QCOMPARE(AppSettings().connectionHost(), machine.address());
    }

    // Another program holds the machine: the list and the hint say so, and connecting asks first.
    void aBusyMachineIsNamedBeforeConnecting()
    {
        const quint16 discovery = freeUdpPort();
        NetworkMachine machine(u"Carvera_Busy"_s, discovery, true);
        QTcpSocket other; // Makera's controller on another computer
        other.connectToHost(QHostAddress::LocalHost, machine.server.port());
        QVERIFY(other.waitForConnected(5000));
        QTRY_VERIFY(machine.server.isBusy());

        Station s;
        panelOf(s)->setDiscoveryPort(discovery);
        panelOf(s)->setKind(ConnectionPanel::Kind::WiFi);
        QTRY_VERIFY_WITH_TIMEOUT(heard(s).value(0).endsWith(u"(busy)"_s), 5000);
        chooseHeard(s, u"Carvera_Busy"_s);
        QTRY_COMPARE(
            s.text(u"connectionHint"_s), u"Carvera_Busy is busy: another program is connected to it."_s);

        QString said;
        answerBoxTitled(u"The machine is busy"_s, {}, &said); // Cancel, the first button
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QTRY_VERIFY(!said.isEmpty());
        QVERIFY2(said.contains(u"Carvera_Busy says it is busy"_s), qPrintable(said));
        QTest::qWait(100);
        QCOMPARE(s.window.connection()->state(), MachineConnection::State::Disconnected);

        said.clear();
        answerBoxTitled(u"The machine is busy"_s, u"connectAnywayButton"_s, &said);
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QTRY_VERIFY(!said.isEmpty());
        QVERIFY(waitConnected(s));
        // Busy with us now: not shown as another program's.
        QCOMPARE(s.find<QComboBox>(u"wifiMachineCombo"_s)->currentText(),
            u"Carvera_Busy — "_s + machine.address());
    }

    // The Carvera's real firmware, framed as Makera's current firmware: found by its beacon on UDP 3333 (the
    // machines' own port: this test holds a lock on it), connected over Wi-Fi, a probe and a break test.
    void theRealFirmwareFoundByItsBeacon()
    {
        if (CarveraPeer::script().isEmpty())
            QSKIP(qPrintable(CarveraPeer::skipReason()));
        CarveraPeer peer({}, u"makera"_s);
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        Station s;
        s.window.resize(1280, 720);
        QVERIFY(s.window.openFile(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json")));
        panelOf(s)->setKind(ConnectionPanel::Kind::WiFi);
        QVERIFY2(panelOf(s)->listener()->isListening(), qPrintable(s.text(u"connectionHint"_s)));
        chooseHeard(s, u"CARVERA_C1_SIM"_s);
        QVERIFY2(heard(s).contains(u"CARVERA_C1_SIM — "_s + peer.wifi()), qPrintable(heard(s).join(u", "_s)));
        screenshot(s.window, u"wifi-machines-heard.png"_s);
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QVERIFY(waitConnected(s));
        QCOMPARE(s.window.connection()->target().name(), peer.wifi());
        QVERIFY2(s.window.connection()->description().contains(u"(framed)"_s),
            qPrintable(s.window.connection()->description()));
        QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"Idle"_s);

        // T1 by hand, probed against the machine's reference, then break-tested: it passes.
        QVERIFY(s.window.connection()->selectTool(1, {}));
        QVERIFY(waitIdle(s));
        QTRY_COMPARE(s.text(u"activeToolLabel"_s), u"T1"_s);
        s.probe();
        QVERIFY(waitIdle(s, 60000));
        QVERIFY(s.table().find(1)->measuredTlo.has_value());
        QCOMPARE(*s.table().find(1)->referenceMz, -115.34);
        QCOMPARE(s.text(u"tloLabel"_s), QString::number(*s.table().find(1)->measuredTlo, 'f', 3) + u" mm"_s);
        answerNextBox(QMessageBox::Yes);
        s.trigger(u"actionBreakTest"_s);
        QVERIFY(waitIdle(s, 60000));
        QTRY_VERIFY(s.text(u"breakVerdictLabel"_s).contains(u"OK"_s));
        QVERIFY(!s.table().find(1)->breakTestFailed);
        screenshot(s.window, u"wifi-real-firmware-after-a-break-test.png"_s);
    }
};

QTEST_MAIN(TestWifiWindow)
#include "tst_wifiwindow.moc"
