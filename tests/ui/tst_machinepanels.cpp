// SPDX-License-Identifier: GPL-3.0-or-later
// The machine panels driven as an operator drives them, against the built-in emulator.
#include <functional>

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include "model/clock.h"
#include "model/document/tooldocument.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/machineconnection.h"
#include "tests/support/messageboxes.h"
#include "ui/common/appsettings.h"
#include "ui/machine/consoledock.h"
#include "ui/shell/mainwindow.h"
#include "ui/table/tooltablepanel.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::answerNextBox;

namespace {

const QString kExample = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

struct Fixture
{
    QList<QByteArray> sent; // before the window: its teardown still reports lines
    MainWindow window;

    Fixture()
    {
        window.show();
        if (!window.openFile(kExample))
            qFatal("the example did not open");
        window.connection()->connectTo(ConnectionTarget {});
        if (!QTest::qWaitFor(
                [this] { return window.connection()->state() == MachineConnection::State::Connected; }))
            qFatal("the emulator did not connect");
        QObject::connect(window.connection(), &MachineConnection::consoleLine, &window,
            [this](const QByteArray &line, bool outgoing) {
                if (outgoing)
                    sent.append(line);
            });
    }
    template<typename T> T *find(const QString &name) const { return window.findChild<T *>(name); }
    bool idle() const { return !window.connection()->isBusy(); }
    void probe()
    {
        answerNextBox(QMessageBox::Yes);
        QTest::mouseClick(find<QPushButton>(u"probeButton"_s), Qt::LeftButton);
        QVERIFY(QTest::qWaitFor([this] { return idle(); }, 10000));
    }
};

} // namespace

class TestMachinePanels : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_machinepanels"_s);
    }

    void init()
    {
        QSettings().clear(); // each test starts from the defaults, whatever the last one remembered
    }

    void aProbeAsksFirstAndUpdatesTheTable()
    {
        Fixture f;
        QString question;
        answerNextBox(QMessageBox::Cancel, &question);
        QTest::mouseClick(f.find<QPushButton>(u"probeButton"_s), Qt::LeftButton);
        QVERIFY2(question.contains(u"will move"_s), qPrintable(question));
        QVERIFY(!f.sent.contains("M491")); // cancelled: nothing moved

        f.window.document()->undoStack()->setClean();
        f.probe();
        QVERIFY(f.sent.contains("M491"));
        const Tool *t1 = f.window.document()->table().find(1);
        QCOMPARE(t1->measuredTlo.value_or(99), 43.04);
        QVERIFY(t1->measuredAt.secsTo(QDateTime::currentDateTimeUtc()) < 10);
        QVERIFY(f.window.document()->isModified());
        QCOMPARE(f.find<QLabel>(u"referenceMzLabel"_s)->text(), u"-115.340 mm"_s);
        f.window.document()->undoStack()->undo(); // the measurement is one undo step
        QCOMPARE(f.window.document()->table().find(1)->measuredAt,
            QDateTime::fromString(u"2026-11-20T08:12:40.000Z"_s, Qt::ISODateWithMs));
    }

    void aToleranceUnderTheMinimumIsRefusedWithItsReason()
    {
        // 0.01 once became 0.02 without a word, was sent, and was remembered.
        Fixture f;
        f.probe();
        auto *spin = f.find<QDoubleSpinBox>(u"toleranceSpin"_s);
        QCOMPARE(spin->value(), 0.1); // the seed's default
        spin->selectAll();
        QTest::keyClicks(spin, u"0.01"_s);
        QTest::keyClick(spin, Qt::Key_Tab);
        QCOMPARE(spin->value(), 0.01); // what the operator typed, not a value of the field's choosing
        QString refusal;
        answerNextBox(QMessageBox::Ok, &refusal);
        QTest::mouseClick(f.find<QPushButton>(u"runBreakTestButton"_s), Qt::LeftButton);
        QVERIFY2(refusal.contains(u"too small"_s) && refusal.contains(u"0.02"_s), qPrintable(refusal));
        QVERIFY(std::none_of(
            f.sent.cbegin(), f.sent.cend(), [](const QByteArray &l) { return l.startsWith("M491.1"); }));
        QVERIFY(!f.window.connection()->emulator()->isHalted());
        QCOMPARE(AppSettings().breakTestTolerance(), 0.1); // not remembered

        // 0.02 is taken, sent as typed, and remembered.
        spin->selectAll();
        QTest::keyClicks(spin, u"0.02"_s);
        QTest::keyClick(spin, Qt::Key_Tab);
        answerNextBox(QMessageBox::Yes);
        QTest::mouseClick(f.find<QPushButton>(u"runBreakTestButton"_s), Qt::LeftButton);
        QVERIFY(QTest::qWaitFor([&f] { return f.idle(); }, 10000));
        QVERIFY(f.sent.contains("M491.1 H0.02"));
        QCOMPARE(AppSettings().breakTestTolerance(), 0.02);
        AppSettings().setBreakTestTolerance(0.1);
    }

    void enterAfterABrokenToolLeavesTheMachineHalted()
    {
        // The alarm once had no default button, so Unlock was the default: a reflex Enter released the
        // machine with the suspect tool still in the spindle.
        Fixture f;
        f.probe();
        f.window.connection()->emulator()->breakTool(1, 0.4);
        bool sawAlarm = false;
        answerNextBox(QMessageBox::Yes); // the confirmation
        std::function<void()> pressEnter = [&] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            if (!box || box->objectName() != u"brokenToolAlarm"_s) {
                QTimer::singleShot(20, pressEnter);
                return;
            }
            sawAlarm = true;
            QVERIFY(box->defaultButton());
            QCOMPARE(box->defaultButton()->objectName(), u"alarmLeaveHaltedButton"_s);
            QTest::keyClick(box, Qt::Key_Return);
        };
        QTimer::singleShot(50, pressEnter);
        QTest::mouseClick(f.find<QPushButton>(u"runBreakTestButton"_s), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(sawAlarm, 10000);
        QVERIFY(QTest::qWaitFor([&f] { return f.idle(); }, 10000));
        QTest::qWait(200);
        QVERIFY(f.window.connection()->emulator()->isHalted());
        QVERIFY(!f.sent.contains("$X"));
    }

    void aBrokenToolRaisesTheAlarmAndUnlockClearsIt()
    {
        Fixture f;
        f.probe();
        f.window.connection()->emulator()->breakTool(1, 0.4);
        QString alarm;
        answerNextBox(QMessageBox::Yes); // the confirmation
        QTimer::singleShot(
            50, [&alarm] { answerNextBox(QMessageBox::NoButton, &alarm, u"alarmUnlockButton"_s); });
        QTest::mouseClick(f.find<QPushButton>(u"runBreakTestButton"_s), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(alarm.contains(u"may be broken"_s), 10000);
        QCOMPARE(f.find<QLabel>(u"breakVerdictLabel"_s)->text(), u"T1: BROKEN TOOL"_s);
        QCOMPARE(f.find<QLabel>(u"breakDifferenceLabel"_s)->text(), u"0.400 mm"_s);
        QTRY_VERIFY_WITH_TIMEOUT(!f.window.connection()->emulator()->isHalted(), 5000);
        QVERIFY(f.sent.contains("$X"));
    }

    void theSeedsAddTwoPointNineExample()
    {
        Fixture f;
        f.probe(); // T1
        QVERIFY(QTest::qWaitFor([&f] { return f.idle(); }));
        f.window.consoleDock()->sendCommand(u"M493.2 T2"_s, false);
        QVERIFY(QTest::qWaitFor([&f] { return f.idle() && f.sent.contains("M493.2 T2"); }));
        f.probe(); // T2: -105.688 against the reference -115.340, TLO 9.652
        QCOMPARE(f.find<QLabel>(u"tloLabel"_s)->text(), u"9.652 mm"_s);

        auto *mode = f.find<QComboBox>(u"offsetModeCombo"_s);
        mode->setCurrentIndex(mode->findText(u"Change TLO by"_s));
        auto *value = f.find<QDoubleSpinBox>(u"offsetValueSpin"_s);
        value->selectAll();
        QTest::keyClicks(value, u"2.9"_s);
        QCOMPARE(f.find<QLabel>(u"offsetCommandPreview"_s)->text(), u"M493.3 Z12.552"_s);
        QCOMPARE(f.find<QLabel>(u"offsetResultPreview"_s)->text(), u"9.652 → 12.552 mm"_s);
        QString question;
        answerNextBox(QMessageBox::Yes, &question);
        QTest::mouseClick(f.find<QPushButton>(u"sendOffsetButton"_s), Qt::LeftButton);
        QVERIFY(question.contains(u"M493.3 Z12.552"_s));
        QVERIFY(QTest::qWaitFor([&f] { return f.idle() && f.sent.contains("M493.3 Z12.552"); }));
        QTRY_COMPARE(f.find<QLabel>(u"tloLabel"_s)->text(), u"12.552 mm"_s);
        QVERIFY(std::fabs(f.window.connection()->emulator()->tlo() - 12.552) < 1e-9);
    }

    // The strip dates only what it saw measured: a TLO in force that equals a value the table had from before
    // this connection (the machine kept it, or set it some other way) is said to be the table's, with the
    // table's date, not to have been measured then.
    void theStripSaysWhoseTloItIs()
    {
        Fixture f;
        f.probe(); // T1
        QTRY_VERIFY2(f.find<QLabel>(u"tloNoteLabel"_s)->text().startsWith(u"measured "_s),
            qPrintable(f.find<QLabel>(u"tloNoteLabel"_s)->text()));
        Tool t1 = *f.window.document()->table().find(1);
        t1.measuredAt = Clock::now().addDays(-8); // the example's probe, from before this connection
        QVERIFY(f.window.document()->editTool(1, t1).ok());
        QTRY_VERIFY2(f.find<QLabel>(u"tloNoteLabel"_s)->text().startsWith(u"as the table's, measured "_s),
            qPrintable(f.find<QLabel>(u"tloNoteLabel"_s)->text()));
    }

    void restoresAKnownTloFromTheTable()
    {
        Fixture f;
        f.probe();
        f.window.connection()->emulator()->setToolLength(2, 10.0); // would measure very differently
        f.window.toolTablePanel()->selectTool(2); // measured 9.652 in the example
        answerNextBox(QMessageBox::NoButton, nullptr, u"restoreYesButton"_s);
        QTest::mouseClick(f.find<QPushButton>(u"restoreButton"_s), Qt::LeftButton);
        QVERIFY(QTest::qWaitFor([&f] { return f.idle() && f.sent.contains("M493.3 Z9.652"); }));
        QCOMPARE(f.window.connection()->emulator()->tool(), 2);
        QVERIFY(std::fabs(f.window.connection()->emulator()->tlo() - 9.652) < 1e-9);
        QVERIFY(!f.sent.contains("M491") || f.sent.count("M491") == 1); // no probe for the restore
    }

    // Set by hand, failed in its break test, older than the stale limit: each named in the question, which
    // warns; Cancel (the default) sends nothing.
    void restoreNamesWhatMakesAStoredTloDoubtful()
    {
        Fixture f;
        Tool t2 = *f.window.document()->table().find(2);
        t2.tloSource = TloSource::Manual;
        t2.breakTestFailed = true;
        t2.measuredAt = Clock::now().addDays(-10);
        QVERIFY(f.window.document()->editTool(2, t2).ok());
        f.window.toolTablePanel()->selectTool(2);
        QString question;
        answerNextBox(QMessageBox::Cancel, &question);
        QTest::mouseClick(f.find<QPushButton>(u"restoreButton"_s), Qt::LeftButton);
        QVERIFY2(question.contains(u"T2's TLO was set by hand, not measured on the tool setter."_s)
                && question.contains(u"T2 failed its last break test."_s)
                && question.contains(u"T2's TLO is 10 days old, older than the stale limit (7 d)"_s),
            qPrintable(question));
        QVERIFY(!f.sent.contains("M493.2 T2"));
    }

    void restoreAsksWhetherTheToolIsInTheSpindleAndWarnsWithoutAReference()
    {
        // A TLO in the table that does not say which reference it was measured against.
        Fixture f;
        Tool t2 = *f.window.document()->table().find(2);
        t2.referenceMz.reset();
        QVERIFY(f.window.document()->editTool(2, t2).ok());
        f.window.toolTablePanel()->selectTool(2);
        QString question;
        answerNextBox(QMessageBox::Cancel, &question);
        QTest::mouseClick(f.find<QPushButton>(u"restoreButton"_s), Qt::LeftButton);
        QVERIFY(question.contains(u"Is T2 in the spindle now?"_s));
        QVERIFY2(question.contains(u"does not say which reference tool T2's TLO was measured against"_s),
            qPrintable(question));
        QVERIFY(!f.sent.contains("M493.2 T2")); // Cancel, the default, sends nothing
        QCOMPARE(f.window.connection()->emulator()->tool(), 1);
    }

    void ctrlRRestoresAfterTheButtonsLabelChanged()
    {
        // Selecting a tool relabels the button ("Restore T2 TLO"), which once took its Ctrl+R away.
        Fixture f;
        f.probe();
        f.window.toolTablePanel()->selectTool(2);
        QCOMPARE(f.find<QPushButton>(u"restoreButton"_s)->text(), u"Restore T2 TLO"_s);
        f.window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&f.window));
        QString question;
        answerNextBox(QMessageBox::Cancel, &question);
        QTest::keyClick(QApplication::focusWidget() ? QApplication::focusWidget() : &f.window, Qt::Key_R,
            Qt::ControlModifier);
        QTRY_VERIFY_WITH_TIMEOUT(question.contains(u"T2"_s), 5000);
    }

    void theConsoleSendsTypedCommandsWithHistory()
    {
        Fixture f;
        auto *line = f.find<QLineEdit>(u"consoleCommand"_s);
        QTest::keyClicks(line, u"M493.4"_s);
        QTest::keyClick(line, Qt::Key_Return);
        QVERIFY(QTest::qWaitFor([&f] {
            return f.window.consoleDock()->lines().join(u'\n').contains(
                u"< using default Tool setter position"_s);
        }));
        QTest::keyClick(line, Qt::Key_Up);
        QCOMPARE(line->text(), u"M493.4"_s);
        auto *filter = f.find<QLineEdit>(u"consoleFilter"_s);
        QTest::keyClicks(filter, u"setter"_s);
        QVERIFY(f.window.consoleDock()->lines().size() > 1);
    }

    void closingWhileProbingAsksThenStopsTheMachine()
    {
        Fixture f;
        f.window.connection()->emulator()->setTiming({ 3000, 0 });
        answerNextBox(QMessageBox::Yes);
        QTest::mouseClick(f.find<QPushButton>(u"probeButton"_s), Qt::LeftButton);
        QVERIFY(f.window.connection()->isBusy());
        QString question;
        answerNextBox(QMessageBox::Cancel, &question);
        QVERIFY(!f.window.close());
        QVERIFY(question.contains(u"Stop it and quit?"_s));
        QVERIFY(f.window.connection()->isBusy());
        answerNextBox(QMessageBox::Yes);
        QVERIFY(f.window.close());
        QTRY_VERIFY(f.window.connection()->emulator()->isHalted()); // stopped by Ctrl-X
        // The fixture now destroys the window with the link still open: that must not crash.
    }

    void showsWhenTheStatusGoesStale()
    {
        Fixture f;
        auto *state = f.find<QLabel>(u"machineStateLabel"_s);
        QTRY_COMPARE(state->text(), u"Idle"_s);
        f.window.connection()->link()->setPollInterval(0); // the reports stop, as on a stalled link
        QTRY_VERIFY_WITH_TIMEOUT(state->text().contains(u"stale"_s), 5000);
        QVERIFY(!state->isEnabled());
        f.window.connection()->disconnectFromMachine();
        QCOMPARE(state->text(), u"Not connected"_s);
    }

    // A halted machine whose reports stop is still shown as halted, in red and not greyed as a dead link,
    // with how long it has been silent (issue 30, item 6).
    void aHaltedMachineThatGoesQuietIsStillShownHalted()
    {
        Fixture f;
        auto *state = f.find<QLabel>(u"machineStateLabel"_s);
        QTRY_COMPARE(state->text(), u"Idle"_s);
        f.window.connection()->emulator()->halt(1);
        f.window.connection()->link()->sendRealtime('?');
        QTRY_VERIFY(f.window.connection()->isHalted() || state->text().startsWith(u"Alarm"_s));
        // The firmware says it is halted as a reply to a command: send one, as the operator's console would.
        if (!f.window.connection()->isHalted()) {
            f.window.connection()->link()->send("G0 X1", 2000, [](const CommandReply &) {});
            QTRY_VERIFY(f.window.connection()->isHalted());
        }
        QTRY_VERIFY(state->text().startsWith(u"HALTED"_s));
        f.window.connection()->link()->setPollInterval(0);
        QTRY_VERIFY_WITH_TIMEOUT(state->text().contains(u"no status report for"_s), 5000);
        QVERIFY2(state->text().startsWith(u"HALTED (no status report for "_s)
                && state->text().endsWith(u"s; it stays halted until unlocked)"_s),
            qPrintable(state->text()));
        QVERIFY(!state->text().contains(u"stale"_s));
        QVERIFY(state->isEnabled());
        f.window.connection()->link()->setPollInterval(200);
        QTRY_COMPARE(state->text(), u"HALTED"_s);
    }
};

QTEST_MAIN(TestMachinePanels)
#include "tst_machinepanels.moc"
