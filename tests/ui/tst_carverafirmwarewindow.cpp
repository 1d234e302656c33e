// SPDX-License-Identifier: GPL-3.0-or-later
// The window's stories on the Carvera's real firmware (TOFFEE_CARVERA_PEER) and, the same stories, on
// toffee-emulator set up as the same machine, both over a pseudo-terminal: connect, select and probe a tool,
// set its TLO by hand, a break test that fails (what the operator sees then: which length is in force, the
// halt, the mark) and Unlock (the stored TLO back first), a break test that passes, a tool change on a rack
// that holds nothing. With TOFFEE_SCREENSHOTS set, the window after the failed break test is saved there.
#include <functional>

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>

#include "tests/support/carverapeer.h"
#include "tests/support/processes.h"
#include "tests/support/station.h"
#include "tests/support/windowsteps.h"
#include "ui/machine/consoledock.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

const QStringList kLikeThePeer { u"--reference"_s, u"-115.34"_s, u"--spindle"_s, u"-1"_s, u"--empty-rack"_s,
    u"--probe-ms"_s, u"500"_s, u"--change-ms"_s, u"0"_s, u"--tool"_s, u"1=41.575"_s, u"--tool"_s,
    u"2=41.575"_s };

void connectTo(Station &s, const QString &port)
{
    ConnectionTarget target;
    target.emulator = false;
    target.port = port;
    s.window.connection()->connectTo(target);
    QVERIFY(QTest::qWaitFor(
        [&s] { return s.window.connection()->state() == MachineConnection::State::Connected; }, 20000));
    QObject::connect(s.window.connection(), &MachineConnection::consoleLine, &s.window,
        [&s](const QByteArray &line, bool outgoing) {
            if (outgoing)
                s.sent.append(line);
        });
    QTRY_COMPARE_WITH_TIMEOUT(s.text(u"machineStateLabel"_s), u"Idle"_s, 5000);
}

} // namespace

class TestCarveraFirmwareWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_carverafirmwarewindow"_s);
    }
    void init() { QSettings().clear(); }

    void anOperatorsDayOnTheMachine_data()
    {
        QTest::addColumn<bool>("realFirmware");
        QTest::newRow("the real firmware") << true;
        QTest::newRow("the emulator, as the same machine") << false;
    }
    void anOperatorsDayOnTheMachine()
    {
        QFETCH(bool, realFirmware);
        if (realFirmware && CarveraPeer::script().isEmpty())
            QSKIP(qPrintable(CarveraPeer::skipReason()));
        QTemporaryDir dir;
        std::unique_ptr<CarveraPeer> peer;
        std::unique_ptr<Emulator> emulator;
        QString port;
        if (realFirmware) {
            peer = std::make_unique<CarveraPeer>();
            QVERIFY2(peer->started(), qPrintable(peer->errors()));
            port = peer->uart();
        } else {
            port = dir.filePath(u"tty"_s);
            emulator = std::make_unique<Emulator>(port, kLikeThePeer);
            QVERIFY(emulator->started());
        }
        Station s;
        s.window.resize(1280, 720);
        QVERIFY(s.window.openFile(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json")));
        connectTo(s, port);

        // Connected: a fresh C1 with an empty spindle, its reference its calibration, nothing in force.
        QCOMPARE(s.text(u"activeToolLabel"_s), u"none"_s);
        QCOMPARE(s.text(u"referenceMzLabel"_s), u"-115.340 mm"_s);
        QCOMPARE(s.text(u"tloLabel"_s), u"not measured"_s);
        QVERIFY(s.text(u"firmwareLimitsLabel"_s).isEmpty()
            || s.find<QLabel>(u"firmwareLimitsLabel"_s)->isHidden());

        // T1 goes in by hand; the console tells the machine.
        s.window.consoleDock()->sendCommand(u"M493.2 T1"_s, false);
        QVERIFY(QTest::qWaitFor([&s] { return s.idle() && s.sent.contains("M493.2 T1"); }, 5000));
        QTRY_COMPARE(s.text(u"activeToolLabel"_s), u"T1"_s);

        // Probe (F5): the firmware measures it against its reference; the table and the strip agree.
        s.probe();
        QVERIFY(waitIdle(s));
        QCOMPARE(*s.table().find(1)->measuredTlo, 6.915);
        QCOMPARE(*s.table().find(1)->referenceMz, -115.34);
        QCOMPARE(s.text(u"tloLabel"_s), u"6.915 mm"_s);
        QCOMPARE(s.text(u"currentMzLabel"_s), u"-108.425 mm"_s);

        // Set by hand to 6.5: the machine's TLO is 6.5 now; no MCS Z of the tool is claimed.
        auto *mode = s.find<QComboBox>(u"offsetModeCombo"_s);
        mode->setCurrentIndex(mode->findText(u"Set TLO to"_s));
        auto *value = s.find<QDoubleSpinBox>(u"offsetValueSpin"_s);
        value->setValue(6.5);
        answerNextBox(QMessageBox::Yes);
        QTest::mouseClick(s.find<QPushButton>(u"sendOffsetButton"_s), Qt::LeftButton);
        QVERIFY(waitIdle(s));
        QTRY_COMPARE(s.text(u"tloLabel"_s), u"6.500 mm"_s);
        QCOMPARE(s.text(u"currentMzLabel"_s), u"not measured"_s);
        QCOMPARE(*s.table().find(1)->measuredTlo, 6.5);

        // The break test against 6.5 finds 6.915: the alarm says which length is in force now, and the
        // operator leaves the machine halted to look at the tool.
        auto *tolerance = s.find<QDoubleSpinBox>(u"toleranceSpin"_s);
        tolerance->setValue(0.05);
        QString alarm;
        answerNextBox(QMessageBox::Yes);
        // The alarm, as the operator sees it when it comes up, saved; then Leave Halted.
        std::function<void(int)> answerAlarm = [&](int attempts) {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            if (!box || box->objectName() != u"brokenToolAlarm"_s) {
                if (attempts > 0)
                    QTimer::singleShot(20, [&answerAlarm, attempts] { answerAlarm(attempts - 1); });
                return;
            }
            if (realFirmware)
                screenshot(*box, u"carvera-firmware-broken-tool-alarm.png"_s);
            alarm = box->text() + u'\n' + box->informativeText();
            box->findChild<QAbstractButton *>(u"alarmLeaveHaltedButton"_s)->click();
        };
        QTimer::singleShot(200, [&answerAlarm] { answerAlarm(1500); });
        s.trigger(u"actionBreakTest"_s);
        QVERIFY(QTest::qWaitFor([&alarm] { return !alarm.isEmpty(); }, 30000));
        QVERIFY2(alarm.contains(u"T1 may be broken"_s), qPrintable(alarm));
        QVERIFY2(alarm.contains(u"halted with the new length, 6.915 mm, in force"_s), qPrintable(alarm));
        QVERIFY2(alarm.contains(u"sets the stored TLO, 6.500 mm, back first"_s), qPrintable(alarm));
        QVERIFY(waitIdle(s));
        QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"HALTED"_s);
        QTRY_COMPARE(s.text(u"tloLabel"_s), u"6.915 mm"_s); // what the firmware has in force: its T: field
        QVERIFY2(s.text(u"tloNoteLabel"_s).contains(u"T1 FAILED ITS BREAK TEST"_s)
                && s.text(u"tloNoteLabel"_s).contains(u"not T1's: the table holds 6.500"_s),
            qPrintable(s.text(u"tloNoteLabel"_s)));
        QVERIFY(s.table().find(1)->breakTestFailed);
        QVERIFY(!s.find<QAction>(u"actionProbe"_s)->isEnabled());
        // The banner says what the halt means here: which length is in force, and what Unlock does.
        QVERIFY2(s.text(u"haltLabel"_s).contains(u"The break test found T1 broken"_s)
                && s.text(u"haltLabel"_s).contains(u"sets its stored TLO, 6.500 mm, back first"_s),
            qPrintable(s.text(u"haltLabel"_s)));
        screenshot(s.window,
            realFirmware ? u"carvera-firmware-after-a-failed-break-test.png"_s
                         : u"carvera-emulator-after-a-failed-break-test.png"_s);

        // Unlock (after a look at the tool: it asks): the stored 6.5 goes back before anything can move.
        QString unlock;
        answerNextBox(QMessageBox::NoButton, &unlock, u"unlockBrokenButton"_s);
        s.trigger(u"actionUnlock"_s);
        QVERIFY2(unlock.contains(u"T1 failed its break test"_s), qPrintable(unlock));
        // The stored 6.500 was set by hand: said, with the length the test measured.
        QVERIFY2(unlock.contains(u"it was set by hand, not measured, and the break test measured 6.915 mm"_s),
            qPrintable(unlock));
        QVERIFY(waitIdle(s));
        QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"Idle"_s);
        QTRY_COMPARE(s.text(u"tloLabel"_s), u"6.500 mm"_s);
        QVERIFY(s.sent.contains("M493.3 Z6.5"));

        // Probed again (the mark goes), then a break test against that passes.
        s.probe();
        QVERIFY(waitIdle(s));
        QVERIFY(!s.table().find(1)->breakTestFailed);
        answerNextBox(QMessageBox::Yes);
        s.trigger(u"actionBreakTest"_s);
        QVERIFY(waitIdle(s));
        QTRY_VERIFY(s.text(u"breakVerdictLabel"_s).contains(u"OK"_s));

        // A change to T2 on a rack that holds nothing: the machine halts, and says why.
        answerNextBox(QMessageBox::Yes); // the console asks before a line that moves the machine
        s.window.consoleDock()->sendCommand(u"M6 T2"_s, true);
        QVERIFY(waitIdle(s, 60000));
        QTRY_COMPARE_WITH_TIMEOUT(s.text(u"machineStateLabel"_s), u"HALTED"_s, 5000);
        QVERIFY2(s.window.consoleDock()->lines().join(u'\n').contains(u"Unexpected tool absence"_s),
            qPrintable(s.window.consoleDock()->lines().join(u'\n')));
        // The banner gives the firmware's own words for the halt, not a guess from its number.
        QTRY_VERIFY2(s.text(u"haltLabel"_s).contains(u"Unexpected tool absence detected"_s),
            qPrintable(s.text(u"haltLabel"_s)));
        QVERIFY(!s.text(u"haltLabel"_s).contains(u"No tool was given"_s));
        s.trigger(u"actionUnlock"_s);
        QVERIFY(waitIdle(s));
        QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"Idle"_s);
        QCOMPARE(s.text(u"activeToolLabel"_s), u"none"_s);

        // Rack ▸ Measure: the first pick finds its slot empty, the machine halts, and the rack stops there,
        // recording nothing.
        const ToolTable before = s.table();
        QString stopped;
        answerNextBox(QMessageBox::Yes);
        QTimer::singleShot(300, [&stopped] { answerNextBox(QMessageBox::Ok, &stopped, {}, 1500); });
        QVERIFY2(s.find<QPushButton>(u"rackMeasureButton"_s)->isEnabled(),
            qPrintable(s.find<QPushButton>(u"rackMeasureButton"_s)->toolTip()));
        s.find<QPushButton>(u"rackMeasureButton"_s)->click();
        QVERIFY2(QTest::qWaitFor([&stopped] { return !stopped.isEmpty(); }, 60000),
            qPrintable(
                s.window.consoleDock()->lines().mid(s.window.consoleDock()->lines().size() - 8).join(u'\n')));
        QVERIFY2(stopped.contains(u"Unexpected tool absence"_s), qPrintable(stopped));
        QVERIFY(waitIdle(s));
        QCOMPARE(s.table(), before);
        QTRY_COMPARE_WITH_TIMEOUT(s.text(u"machineStateLabel"_s), u"HALTED"_s, 5000);
        s.trigger(u"actionUnlock"_s);
        QVERIFY(waitIdle(s));
        QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"Idle"_s);
    }

    // A tool outside the rack is changed by hand: the firmware goes to its change position and waits for its
    // button. The window says so, with the limit, and End the Change stops it there (a halt, as Ctrl-X is):
    // nothing measured, nothing recorded.
    void aChangeByHandWaitsForTheOperatorAndCanBeEnded()
    {
        if (CarveraPeer::script().isEmpty())
            QSKIP(qPrintable(CarveraPeer::skipReason()));
        CarveraPeer peer;
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        Station s;
        s.window.resize(1280, 720);
        QVERIFY(s.window.openFile(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json")));
        connectTo(s, peer.uart());
        const ToolTable before = s.table();
        s.find<QSpinBox>(u"rackToolSpin"_s)->setValue(8);
        answerNextBox(QMessageBox::Yes);
        s.find<QPushButton>(u"rackLoadButton"_s)->click();
        QMessageBox *box = nullptr;
        QVERIFY(QTest::qWaitFor(
            [&] {
                return (box = s.window.findChild<QMessageBox *>(u"toolChangeWaitBox"_s)) && box->isVisible();
            },
            30000));
        QCOMPARE(box->windowTitle(), u"Put T8 in the Spindle"_s);
        QVERIFY2(box->text().contains(u"press the machine's button"_s), qPrintable(box->text()));
        QVERIFY2(
            box->informativeText().contains(u"waits up to 10 min;"_s), qPrintable(box->informativeText()));
        QVERIFY(!box->findChild<QPushButton *>(u"toolChangeContinueButton"_s)); // only the machine's button
        QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"Waiting for the operator"_s);
        // Shown whole in the strip at 1280 px, once the layout has settled.
        auto *state = s.find<QLabel>(u"machineStateLabel"_s);
        QTRY_VERIFY2(state->width() >= state->fontMetrics().horizontalAdvance(state->text()),
            qPrintable(u"%1 px for %2 px of text"_s.arg(state->width())
                           .arg(state->fontMetrics().horizontalAdvance(state->text()))));
        screenshot(s.window, u"carvera-change-by-hand.png"_s);
        screenshot(*box, u"carvera-change-by-hand-box.png"_s);
        QString ended;
        QTimer::singleShot(0, [&ended] { answerNextBox(QMessageBox::Ok, &ended, {}, 1500); });
        box->findChild<QPushButton *>(u"toolChangeEndButton"_s)->click();
        QVERIFY(QTest::qWaitFor([&ended] { return !ended.isEmpty(); }, 30000));
        QVERIFY2(ended.contains(u"The operator ended the change in the window."_s)
                && ended.contains(u"nothing was measured or recorded"_s),
            qPrintable(ended));
        QVERIFY(waitIdle(s));
        QTRY_VERIFY(!s.window.findChild<QMessageBox *>(u"toolChangeWaitBox"_s));
        QCOMPARE(s.table(), before);
        QTRY_COMPARE_WITH_TIMEOUT(s.text(u"machineStateLabel"_s), u"HALTED"_s, 5000);
    }
};

QTEST_MAIN(TestCarveraFirmwareWindow)
#include "tst_carverafirmwarewindow.moc"
