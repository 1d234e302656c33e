// SPDX-License-Identifier: GPL-3.0-or-later
// Whole stories through the real window (offscreen) against the built-in emulator, step after step, as an
// operator lives them: at each step, what the window shows, what the machine holds and what the file holds.
#include <cmath>

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include "model/document/tooldocument.h"
#include "model/document/tooltablemodel.h"
#include "model/gcode/dialect.h"
#include "model/library/historyrecorder.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/machineconnection.h"
#include "tests/support/messageboxes.h"
#include "tests/support/station.h"
#include "ui/common/appsettings.h"
#include "ui/machine/consoledock.h"
#include "ui/machine/machinedock.h"
#include "ui/machine/tlopanel.h"
#include "ui/shell/mainwindow.h"
#include "ui/table/exportdialog.h"
#include "ui/table/tooltablepanel.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::answerNextBox;
using Toffee::Test::Station;

namespace {

// The window as an operator has it, with every line it sent to the machine.
// The chapters of the first story, in order; each leaves the station where the next begins.

// First start, connect, and the first tool probed.
void firstStartAndTheReference(Station &s)
{
    // First start: an empty table, no machine; nothing claims to be measured.
    QCOMPARE(s.table().size(), 0);
    QCOMPARE(s.text(u"machineStateLabel"_s), u"Not connected"_s);
    QVERIFY(!s.find<QAction>(u"actionProbe"_s)->isEnabled());

    // Connect: a fresh machine has no TLO in force (0, the firmware's "none"), and the strip says so rather
    // than "0.000 mm"; its reference is its calibration.
    s.connect();
    QCOMPARE(s.text(u"activeToolLabel"_s), u"T1"_s);
    QCOMPARE(s.text(u"tloLabel"_s), u"not measured"_s);
    QVERIFY(s.text(u"tloNoteLabel"_s).contains(u"probe the tool first"_s));
    QCOMPARE(s.text(u"referenceMzLabel"_s), u"-115.340 mm"_s);
    QCOMPARE(s.text(u"currentMzLabel"_s), u"not measured"_s);

    // Probe T1: it enters the table, measured against the machine's reference.
    const QString first = s.probe();
    QVERIFY(first.contains(u"recorded as T1's TLO"_s));
    QCOMPARE(*s.table().find(1)->measuredTlo, 43.04);
    QCOMPARE(s.table().find(1)->tloSource, TloSource::Probe);
    QCOMPARE(s.text(u"tloLabel"_s), u"43.040 mm"_s);
    QVERIFY(s.text(u"tloNoteLabel"_s).startsWith(u"measured "_s));
    QCOMPARE(s.text(u"referenceMzLabel"_s), u"-115.340 mm"_s);
    QCOMPARE(s.text(u"currentMzLabel"_s), u"-72.300 mm"_s);
}

// T2 loaded from the console, then probed.
void changeToT2FromTheConsole(Station &s)
{
    // Change to T2 from the console: it moves the machine, so it asks first; No sends nothing.
    auto *console = s.find<QLineEdit>(u"consoleCommand"_s);
    QString question;
    answerNextBox(QMessageBox::Cancel, &question);
    QTest::keyClicks(console, u"M6 T2"_s);
    QTest::keyClick(console, Qt::Key_Return);
    QVERIFY(question.contains(u"changes the tool"_s));
    QVERIFY(!s.sent.contains("M6 T2"));
    QCOMPARE(s.machine()->tool(), 1);
    answerNextBox(QMessageBox::Yes);
    QTest::keyClick(console, Qt::Key_Up);
    QTest::keyClick(console, Qt::Key_Return);
    QVERIFY(QTest::qWaitFor([&s] { return s.idle() && s.sent.contains("M6 T2"); }, 10000));
    QCOMPARE(s.machine()->tool(), 2);
    // The console's tool change measured T2 on the machine, and it is recorded like a probe from the panel;
    // the strip shows the machine as it is after the command, not as it was before.
    QTRY_VERIFY(s.table().find(2) && s.table().find(2)->measuredTlo);
    QCOMPARE(*s.table().find(2)->measuredTlo, 9.652);
    QCOMPARE(s.table().find(2)->tloSource, TloSource::Probe);
    QTRY_COMPARE(s.text(u"currentMzLabel"_s), u"-105.688 mm"_s);
    QCOMPARE(s.text(u"tloLabel"_s), u"9.652 mm"_s);

    // Probe T2 again from the panel: 9.652 mm, at the machine's resolution.
    s.probe();
    QCOMPARE(*s.table().find(2)->measuredTlo, 9.652);
    QCOMPARE(s.cell(2, ToolTableModel::MeasuredTloColumn), u"9.652"_s);
}

// T2's offset adjusted by hand: the machine and the table agree, marked so.
void adjustT2ByHand(Station &s)
{
    QString question;
    // Adjust by hand (+2.9, the seed's example): the machine and the table agree, marked set by hand.
    auto *mode = s.find<QComboBox>(u"offsetModeCombo"_s);
    mode->setCurrentIndex(mode->findText(u"Change TLO by"_s));
    auto *value = s.find<QDoubleSpinBox>(u"offsetValueSpin"_s);
    value->setValue(2.9);
    answerNextBox(QMessageBox::Yes, &question);
    QTest::mouseClick(s.find<QPushButton>(u"sendOffsetButton"_s), Qt::LeftButton);
    QVERIFY(question.contains(u"T2"_s));
    QVERIFY(question.contains(u"M493.3 Z12.552"_s));
    QVERIFY(QTest::qWaitFor([&s] { return s.idle(); }, 5000));
    QVERIFY(std::fabs(s.machine()->tlo() - 12.552) < 1e-9);
    QCOMPARE(*s.table().find(2)->measuredTlo, 12.552);
    QCOMPARE(s.table().find(2)->tloSource, TloSource::Manual);
    QCOMPARE(s.cell(2, ToolTableModel::MeasuredTloColumn), u"12.552 (by hand)"_s);
    // The firmware prints the TLO as its "current tool offset" now: the strip claims no MCS Z of the tool.
    QCOMPARE(s.text(u"currentMzLabel"_s), u"not measured"_s);
    QVERIFY(s.text(u"tloNoteLabel"_s).startsWith(u"set by hand"_s));
    QCOMPARE(value->value(), 0.0); // a second Send would not add 2.9 again
    QVERIFY(!s.find<QPushButton>(u"sendOffsetButton"_s)->isEnabled()); // and adding 0 is no change
    // The probe panel no longer claims the probe's TLO is the one in use.
    QVERIFY(!s.text(u"probeResultLabel"_s).contains(u"9.652"_s));
    QCOMPARE(s.window.document()->undoStack()->undoText(), u"Set T2 TLO by hand"_s);
}

// A break test against the hand-set TLO finds T2 "broken"; the machine halts.
void breakTestFindsT2Broken(Station &s)
{
    QString question;
    // Break test: told first that the TLO it compares against was set by hand.
    answerNextBox(QMessageBox::Yes, &question);
    s.trigger(u"actionBreakTest"_s);
    QVERIFY(question.contains(u"Break-test T2?"_s) || question.contains(u"measure T2 again"_s));
    QVERIFY(question.contains(u"was set by hand"_s));
    // The real T2 is 2.9 mm from the hand-set TLO: broken. A reflex Enter leaves the machine halted.
    QString alarm;
    QTimer::singleShot(100, [&] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box)
            return;
        alarm = box->text() + u'\n' + box->informativeText();
        QTest::keyClick(box, Qt::Key_Return);
    });
    QVERIFY(QTest::qWaitFor([&alarm] { return !alarm.isEmpty(); }, 10000));
    QVERIFY(alarm.contains(u"T2 may be broken"_s));
    // It says that the value it compared with was set by hand: the tool may be whole.
    QVERIFY(alarm.contains(u"the tool may be whole"_s));
    QVERIFY(QTest::qWaitFor([&s] { return s.idle() && !QApplication::activeModalWidget(); }, 5000));
    QVERIFY(s.machine()->isHalted());
    QVERIFY(!s.sent.contains("$X"));
}

// Halted: the window says so and offers nothing that moves; the console is no back door.
void haltedOffersNothingThatMoves(Station &s)
{
    auto *console = s.find<QLineEdit>(u"consoleCommand"_s);
    // Halted: the strip says so in words, nothing that moves is offered, and the tool is marked.
    QCOMPARE(s.text(u"machineStateLabel"_s), u"HALTED"_s);
    QVERIFY(s.find<QLabel>(u"haltLabel"_s)->isVisible());
    QVERIFY(s.text(u"haltLabel"_s).contains(u"Unlock"_s));
    QVERIFY(s.find<QPushButton>(u"unlockButton"_s)->isVisible());
    QVERIFY(!s.find<QAction>(u"actionProbe"_s)->isEnabled());
    QVERIFY(!s.find<QAction>(u"actionBreakTest"_s)->isEnabled());
    QVERIFY(!s.find<QPushButton>(u"probeButton"_s)->isEnabled());
    QVERIFY(!s.find<QPushButton>(u"sendOffsetButton"_s)->isEnabled());
    QVERIFY(s.find<QAction>(u"actionUnlock"_s)->isEnabled());
    QVERIFY(s.table().find(2)->breakTestFailed);
    QVERIFY(s.cell(2, ToolTableModel::MeasuredTloColumn).contains(u"BROKEN?"_s));
    QVERIFY(s.text(u"tloNoteLabel"_s).contains(u"T2 FAILED ITS BREAK TEST"_s));
    // The console is no back door.
    const int before = int(s.sent.size());
    QTest::keyClicks(console, u"M491"_s);
    QTest::keyClick(console, Qt::Key_Return);
    QCOMPARE(int(s.sent.size()), before);
    QVERIFY(s.window.consoleDock()->lines().last().contains(u"  · not sent: The machine is halted"_s));
}

// Saved with the mark; unlocked and probed again, the mark is gone; reopened, the window shows the file.
void unlockAndProbeAgain(Station &s, const QTemporaryDir &dir)
{
    // Saved now, the file keeps the mark.
    const QString path = dir.filePath(u"shop.json"_s);
    s.saveAs(path);
    QVERIFY(!s.window.document()->isModified());
    auto saved = loadTableFile(path);
    QVERIFY(saved.ok());
    QVERIFY(saved.value().find(2)->breakTestFailed);
    QCOMPARE(saved.value().find(2)->tloSource, TloSource::Manual);

    // Unlock (Ctrl+Shift+U): the failed break test left the length it measured in force, and the stored TLO
    // goes back before anything else; then probe T2 again: measured, and the mark is gone.
    QCOMPARE(s.machine()->tlo(), 9.652);
    s.window.activateWindow();
    // Unlock asks first, naming the mark; Cancel leaves the machine halted.
    QString question;
    answerNextBox(QMessageBox::Cancel, &question);
    s.trigger(u"actionUnlock"_s);
    QVERIFY2(question.contains(u"T2 failed its break test"_s) && question.contains(u"12.552 mm"_s),
        qPrintable(question));
    QVERIFY(s.machine()->isHalted());
    answerNextBox(QMessageBox::NoButton, &question, u"unlockBrokenButton"_s);
    s.trigger(u"actionUnlock"_s);
    QVERIFY(QTest::qWaitFor([&s] { return s.idle() && !s.machine()->isHalted(); }, 5000));
    QCOMPARE(s.machine()->tlo(), 12.552);
    QVERIFY(s.sent.contains("M493.3 Z12.552"));
    QTRY_VERIFY(s.find<QAction>(u"actionProbe"_s)->isEnabled());
    QTRY_VERIFY(!s.find<QLabel>(u"haltLabel"_s)->isVisible());
    // Probing the tool still marked says so before it moves.
    QVERIFY2(s.probe().contains(u"T2 is marked broken"_s), "the probe question says nothing of the mark");
    QCOMPARE(*s.table().find(2)->measuredTlo, 9.652);
    QVERIFY(!s.table().find(2)->breakTestFailed);
    QCOMPARE(s.table().find(2)->tloSource, TloSource::Probe);
    QCOMPARE(s.cell(2, ToolTableModel::MeasuredTloColumn), u"9.652"_s);
    // The break test's "BROKEN TOOL" was about the tool before it was measured again.
    QVERIFY(s.text(u"breakVerdictLabel"_s).isEmpty());

    // Save (Ctrl+S) and reopen: the window shows what the file holds.
    s.trigger(u"actionSave"_s);
    QVERIFY(!s.window.document()->isModified());
    Station reopened;
    QVERIFY(reopened.window.openFile(path));
    QCOMPARE(reopened.table(), s.table());
    QCOMPARE(reopened.cell(2, ToolTableModel::MeasuredTloColumn), u"9.652"_s);
    QCOMPARE(reopened.cell(1, ToolTableModel::MeasuredTloColumn), u"43.040"_s);
}

} // namespace

class TestWorkflows : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { Test::isolateWindowTest(u"tst_workflows"_s); }
    void init() { Test::startFresh(); }

    void firstStartThroughAManualOffsetAndABrokenToolToReopen()
    {
        QTemporaryDir dir;
        Station s;
        for (auto chapter : { firstStartAndTheReference, changeToT2FromTheConsole, adjustT2ByHand,
                 breakTestFindsT2Broken, haltedOffersNothingThatMoves }) {
            chapter(s);
            if (QTest::currentTestFailed())
                return;
        }
        unlockAndProbeAgain(s, dir);
    }

    void aBrokenToolStaysMarkedAcrossAReopenUntilItIsProbed()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"tools.json"_s);
        {
            Station s;
            QVERIFY(s.window.openFile(Test::kExampleTable));
            s.connect();
            s.probe(); // T1, the reference
            s.machine()->breakTool(1, 0.4);
            QString question;
            answerNextBox(QMessageBox::Yes, &question);
            QTimer::singleShot(
                100, [] { answerNextBox(QMessageBox::NoButton, nullptr, u"alarmLeaveHaltedButton"_s); });
            s.trigger(u"actionBreakTest"_s);
            QVERIFY(question.isEmpty() || !question.contains(u"set by hand"_s)); // T1 was measured
            QVERIFY(QTest::qWaitFor([&s] { return s.table().find(1)->breakTestFailed; }, 10000));
            QVERIFY(QTest::qWaitFor([] { return !QApplication::activeModalWidget(); }, 5000));
            s.saveAs(path);
            QVERIFY(!s.window.document()->isModified());
        }
        Station s;
        QVERIFY(s.window.openFile(path));
        QVERIFY(s.table().find(1)->breakTestFailed);
        QVERIFY(s.cell(1, ToolTableModel::MeasuredTloColumn).contains(u"BROKEN?"_s));
        s.connect(); // a new session: the machine is no longer halted
        // The strip names the failure for the tool in the spindle.
        QTRY_VERIFY(s.text(u"tloNoteLabel"_s).contains(u"T1 FAILED ITS BREAK TEST"_s)
            || s.text(u"tloLabel"_s) == u"not measured"_s);
        s.probe();
        QVERIFY(!s.table().find(1)->breakTestFailed);
        QVERIFY(!s.cell(1, ToolTableModel::MeasuredTloColumn).contains(u"BROKEN?"_s));
        QVERIFY(s.window.document()->isModified());
    }

    void theStripFitsA1280By720ScreenAndScrollingChangesNoValue()
    {
        Station s;
        QVERIFY(s.window.openFile(Test::kExampleTable));
        s.connect();
        s.window.resize(1280, 720);
        QTRY_COMPARE(s.window.width(), 1280);
        // The strip is always there, above the table, whatever the docks do.
        auto *strip = s.find<TloPanel>(u"machineStrip"_s);
        s.window.machineDock()->hide();
        QVERIFY(strip->isVisible());
        QVERIFY(strip->mapTo(&s.window, QPoint(strip->width(), 0)).x() <= s.window.width());
        s.window.machineDock()->show();
        // The machine panel needs no horizontal scrolling at 1280 wide.
        auto *send = s.find<QPushButton>(u"sendOffsetButton"_s);
        const QPoint right = send->mapTo(&s.window, QPoint(send->width(), 0));
        QVERIFY2(right.x() <= s.window.width(), qPrintable(QString::number(right.x())));
        // A halt's long explanation wraps; it never widens the window past Disconnect.
        s.machine()->halt(4);
        QTRY_VERIFY(s.find<QLabel>(u"haltLabel"_s)->isVisible());
        QVERIFY(s.text(u"haltLabel"_s).contains(u"break test found the tool broken"_s));
        QCOMPARE(s.window.width(), 1280);
        auto *disconnect = s.find<QPushButton>(u"connectButton"_s);
        QVERIFY(disconnect->mapTo(&s.window, QPoint(disconnect->width(), 0)).x() <= s.window.width());
        QVERIFY(strip->mapTo(&s.window, QPoint(strip->width(), 0)).x() <= s.window.width());
        // A wheel over a spin box the operator did not click scrolls the panel, not the value.
        auto *tolerance = s.find<QDoubleSpinBox>(u"toleranceSpin"_s);
        const double was = tolerance->value();
        QWheelEvent wheel(QPointF(5, 5), tolerance->mapToGlobal(QPointF(5, 5)), QPoint(), QPoint(0, 120),
            Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(tolerance, &wheel);
        QCOMPARE(tolerance->value(), was);
        tolerance->setFocus();
        QApplication::sendEvent(tolerance, &wheel);
        QVERIFY(tolerance->value() != was); // once focused, the wheel is the operator's choice
    }

    void restoreRefusesATloMeasuredAgainstAnotherReference()
    {
        Station s;
        QVERIFY(s.window.openFile(Test::kExampleTable));
        s.connect();
        s.probe(); // T1, against the machine's reference, MCS Z -115.340
        QCOMPARE(*s.table().find(1)->referenceMz, -115.34);
        // T2's TLO was measured against a reference elsewhere (another machine, or before a calibration).
        Tool t2 = *s.table().find(2);
        t2.referenceMz = -123.04;
        QVERIFY(s.window.document()->editTool(2, t2).ok());
        s.window.toolTablePanel()->selectTool(2);
        QString refusal;
        answerNextBox(QMessageBox::Ok, &refusal);
        QTest::mouseClick(s.find<QPushButton>(u"restoreButton"_s), Qt::LeftButton);
        QVERIFY(refusal.contains(u"Probe T2 instead"_s));
        QVERIFY(refusal.contains(u"7.700 mm"_s)); // how far off it would be
        QVERIFY(!s.sent.contains("M493.2 T2"));
        QCOMPARE(s.machine()->tool(), 1);
    }

    void anOffsetTypedInTheConsoleIsRecordedAsSetByHand()
    {
        Station s;
        s.connect();
        s.probe(); // T1
        s.window.consoleDock()->sendCommand(u"M493.3 Z-1.5"_s, false);
        QVERIFY(QTest::qWaitFor([&s] { return s.idle() && s.sent.contains("M493.3 Z-1.5"); }, 5000));
        QCOMPARE(*s.table().find(1)->measuredTlo, -1.5);
        QCOMPARE(s.table().find(1)->tloSource, TloSource::Manual);
        QCOMPARE(*s.table().find(1)->referenceMz, -115.34);
        QVERIFY(s.window.consoleDock()->lines().last().contains(u"recorded in the table: T1"_s));
    }

    void theStatusBarNeverSaysDisconnectedWhileConnected()
    {
        Station s;
        s.connect();
        // The cable comes out: the window says so and offers to reconnect; the operator does.
        QString offer;
        answerNextBox(QMessageBox::NoButton, &offer, u"reconnectButton"_s);
        s.window.connection()->link()->close();
        QTRY_VERIFY(s.window.statusBar()->currentMessage().startsWith(u"Disconnected"_s));
        QTRY_VERIFY(!offer.isEmpty());
        QVERIFY2(offer.contains(u"Nothing was running"_s), qPrintable(offer));
        QTRY_COMPARE(s.window.connection()->state(), MachineConnection::State::Connected);
        QVERIFY(!s.window.statusBar()->currentMessage().contains(u"Disconnected"_s));
    }
};

QTEST_MAIN(TestWorkflows)
#include "tst_workflows.moc"
