// SPDX-License-Identifier: GPL-3.0-or-later
// The window on grblHAL itself (TOFFEE_GRBLHAL_PEER), as a LongMill owner runs it: the connection panel's
// Wi-Fi choice with an address typed and grblHAL chosen, Machine ▸ Tool Setter… kept for the machine, the
// first tool probed as the reference and a second against it (in the table and in grblHAL's own table), a
// break test that finds a tool 0.5 mm shorter with nothing overwritten, Pull Offsets and Push Offsets each
// through their preview, the rack refused by name, and Check Job warning of a table that differs from the
// controller's. With TOFFEE_SCREENSHOTS set, the window and the previews are saved there.
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>

#include "model/document/tooltablemodel.h"
#include "model/library/library.h"
#include "tests/support/grblhalpeer.h"
#include "tests/support/messageboxes.h"
#include "tests/support/processes.h"
#include "tests/support/station.h"
#include "tests/support/windowsteps.h"
#include "ui/common/appsettings.h"
#include "ui/connection/connectionpanel.h"
#include "ui/job/jobcheckdialog.h"
#include "ui/machine/offsetsyncdialog.h"
#include "ui/machine/toolsetterdialog.h"
#include "ui/rack/rackpanel.h"
#include "ui/table/tooltablepanel.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

void connectTo(Station &s, const GrblHalPeer &peer)
{
    auto *panel = s.window.findChild<ConnectionPanel *>();
    panel->setKind(ConnectionPanel::Kind::WiFi);
    auto *machine = s.find<QComboBox>(u"wifiMachineCombo"_s);
    machine->setEditText(u"127.0.0.1:%1"_s.arg(peer.port()));
    // Automatic, as a new user finds it: grblHAL is found by asking.
    auto *controller = s.find<QComboBox>(u"controllerCombo"_s);
    QVERIFY(controller->isVisible() && controller->isEnabled());
    QCOMPARE(controller->currentData().toString(), u"auto"_s);
    QCOMPARE(controller->currentText(), u"Automatic"_s);
    QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
    QVERIFY(waitConnected(s));
    QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"Idle"_s);
    QCOMPARE(s.window.connection()->controllerKind(), ControllerKind::GrblHal);
    // What was found is shown where it was asked for: the controller and the machine's own name (or link).
    QTRY_VERIFY2(
        controller->currentText().startsWith(u"Automatic: grblHAL"_s), qPrintable(controller->currentText()));
}

} // namespace

class TestGrblHalWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        if (GrblHalPeer::script().isEmpty())
            QSKIP(qPrintable(GrblHalPeer::skipReason()));
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    // Two machines, one library: grblHAL measured in the window, then the built-in emulator by toffee-cli
    // with the same library. Each is its own machine, named after its kind and said to be new the first time;
    // connected again, grblHAL keeps its own reference (−70), not the emulator's (−115.340, which once made
    // T2's TLO 45.340 in grblHAL's table). A name bound to the emulator refuses grblHAL in the window, unless
    // the operator says it is the same machine; cancelled, nothing is sent but the questions.
    void twoMachinesKeepTheirOwnReference()
    {
        GrblHalPeer peer;
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        QVERIFY(peer.writeSetter(-100.0, { { 1, 30.0 }, { 2, 45.3 } }));
        QSettings().clear();
        Station s;
        s.window.resize(1280, 720);
        QStringList said;
        connect(s.window.statusBar(), &QStatusBar::messageChanged, this,
            [&said](const QString &message) { said << message; });
        connectTo(s, peer);
        QVERIFY2(said.contains(
                     u"“grblHAL” is grblHAL at 127.0.0.1:%1, new to the history library."_s.arg(peer.port())),
            qPrintable(said.join(u" | "_s)));
        inNextDialog<ToolSetterDialog>([](ToolSetterDialog *d) {
            d->findChild<QDoubleSpinBox *>(u"setterZMin"_s)->setValue(-120.0);
            d->findChild<QDoubleSpinBox *>(u"setterSeekFeed"_s)->setValue(3000.0);
            d->findChild<QDoubleSpinBox *>(u"setterLatchFeed"_s)->setValue(300.0);
            d->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok)->click();
        });
        s.trigger(u"actionToolSetter"_s);
        QTRY_VERIFY(s.window.statusBar()->currentMessage().startsWith(u"grblHAL's tool setter"_s));
        QVERIFY(s.window.connection()->selectTool(1, {}));
        QVERIFY(waitIdle(s, 60000));
        s.probe();
        QVERIFY(waitIdle(s, 60000));
        QCOMPARE(*s.table().find(1)->referenceMz, -70.0);
        s.window.connection()->disconnectFromMachine();

        const Run emulator
            = cli({ u"--json"_s, u"--library"_s, s.libraryPath(), u"--emulator"_s, u"probe"_s });
        QVERIFY2(emulator.exitCode == 0, emulator.err.constData());
        QVERIFY2(emulator.err.contains("\"Emulator\" is the built-in emulator, new to the library"),
            emulator.err.constData());

        said.clear();
        connectTo(s, peer);
        QVERIFY2(!said.join(u'|').contains(u"new to the history library"_s), qPrintable(said.join(u'|')));
        QVERIFY(s.window.connection()->selectTool(2, {}));
        QVERIFY(waitIdle(s, 60000));
        s.probe();
        QVERIFY(waitIdle(s, 60000));
        QCOMPARE(*s.table().find(2)->measuredTlo, 15.3);
        QCOMPARE(*s.table().find(2)->referenceMz, -70.0);
        QCOMPARE(peer.tableZ(2), std::optional(15.3));
        {
            auto library = Library::open({ s.libraryPath() });
            HistoryQuery grbl;
            grbl.machine = u"grblHAL"_s;
            QCOMPARE(library.value()->history(grbl).value().size(), 2);
            HistoryQuery emulated;
            emulated.machine = u"Emulator"_s;
            QCOMPARE(library.value()->history(emulated).value().size(), 1);
        }
        s.window.connection()->disconnectFromMachine();

        // Named "Emulator" in the settings: that name is the emulator's; grblHAL is asked about, and
        // cancelled.
        AppSettings().setMachineName(u"Emulator"_s);
        // The question (Cancel is its default), then the window's word that it did not connect.
        QString asked;
        QString refusal;
        answerAnyBox(&asked);
        std::function<void()> thenTheRefusal = [&] {
            if (asked.isEmpty())
                return QTimer::singleShot(10, thenTheRefusal);
            answerAnyBox(&refusal);
        };
        QTimer::singleShot(10, thenTheRefusal);
        QSignalSpy failed(s.window.connection(), &MachineConnection::connectFailed);
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(failed.size(), 1, 15000);
        QTRY_VERIFY2(refusal.contains(u"Give this machine a name of its own"_s), qPrintable(refusal));
        QVERIFY2(
            asked.contains(u"“Emulator” in the history library is the built-in emulator; this is grblHAL "
                           "at 127.0.0.1:%1"_s.arg(peer.port())),
            qPrintable(asked));
        QVERIFY2(failed.front().front().toString().contains(u"Give this machine a name of its own"_s),
            qPrintable(failed.front().front().toString()));
        QCOMPARE(s.window.connection()->state(), MachineConnection::State::Disconnected);
        QCOMPARE(peer.tableZ(2), std::optional(15.3));
        AppSettings().setMachineName({});
    }

    void aLongMillOwnersDay()
    {
        QSettings().clear(); // no setter kept on this computer from another story
        GrblHalPeer peer;
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        QVERIFY(peer.writeSetter(-100.0, { { 1, 30.0 }, { 2, 45.3 } }));
        // Set on the controller by someone else before Toffee: T5's entry.
        QVERIFY(peer.ask("G10 L1 P5 Z2.5").contains("ok"));
        Station s;
        s.window.resize(1280, 720);
        connectTo(s, peer);
        QCOMPARE(s.window.connection()->firmware().kind, FirmwareInfo::Kind::GrblHal);
        QCOMPARE(s.window.connection()->firmware().toolTableSize, 16);
        // A probe before the setter is known is refused with where to set it.
        QVERIFY(s.window.connection()->selectTool(1, {}));
        QVERIFY(waitIdle(s, 60000));
        QTRY_COMPARE(s.text(u"activeToolLabel"_s), u"T1"_s);
        QString refusal;
        QString question;
        answerNextBox(QMessageBox::Yes, &question);
        QTimer::singleShot(300, [&refusal] { answerAnyBox(&refusal); });
        s.trigger(u"actionProbe"_s);
        QVERIFY(waitIdle(s, 60000));
        QTRY_VERIFY2(refusal.contains(u"Tool Setter"_s), qPrintable(question + u" / "_s + refusal));
        QVERIFY(!s.table().find(1) || !s.table().find(1)->measuredTlo);

        // Machine ▸ Tool Setter…: kept for the machine in the library, given to the controller at once.
        inNextDialog<ToolSetterDialog>([&s](ToolSetterDialog *d) {
            d->findChild<QDoubleSpinBox *>(u"setterZMin"_s)->setValue(-120.0);
            d->findChild<QDoubleSpinBox *>(u"setterSeekFeed"_s)->setValue(3000.0);
            // A latch faster than the search is refused in the dialog, OK disabled, with why.
            d->findChild<QDoubleSpinBox *>(u"setterLatchFeed"_s)->setValue(5000.0);
            auto *ok = d->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
            QVERIFY(!ok->isEnabled());
            QVERIFY(d->findChild<QLabel *>(u"setterProblem"_s)->text().contains(u"latch feed"_s));
            d->findChild<QDoubleSpinBox *>(u"setterLatchFeed"_s)->setValue(300.0);
            QVERIFY(ok->isEnabled());
            // Where the setter is, from where the machine stands: jogged there (asked once), then taken.
            auto *position = d->findChild<QLabel *>(u"setterMachinePosition"_s);
            QVERIFY(position);
            QTRY_VERIFY2(position->text().contains(u"X 0.000, Y 0.000"_s), qPrintable(position->text()));
            d->findChild<QComboBox *>(u"setterJogStep"_s)->setCurrentIndex(2); // 10 mm
            QString asked;
            answerNextBox(QMessageBox::NoButton, &asked, u"setterJogYesButton"_s);
            d->findChild<QPushButton *>(u"setterJogXPlus"_s)->click();
            QVERIFY2(
                asked.contains(u"The machine moves each time you press a jog button"_s), qPrintable(asked));
            QTRY_VERIFY_WITH_TIMEOUT(position->text().contains(u"X 10.000, Y 0.000"_s), 10000);
            d->findChild<QComboBox *>(u"setterJogStep"_s)->setCurrentIndex(1); // 1 mm, not asked again
            QTRY_VERIFY(d->findChild<QPushButton *>(u"setterJogYMinus"_s)->isEnabled());
            d->findChild<QPushButton *>(u"setterJogYMinus"_s)->click();
            QTRY_VERIFY_WITH_TIMEOUT(position->text().contains(u"X 10.000, Y -1.000"_s), 10000);
            QTRY_VERIFY(d->findChild<QPushButton *>(u"setterUseHere"_s)->isEnabled());
            screenshot(*d, u"grblhal-tool-setter.png"_s);
            d->findChild<QPushButton *>(u"setterUseHere"_s)->click();
            QCOMPARE(d->findChild<QDoubleSpinBox *>(u"setterX"_s)->value(), 10.0);
            QCOMPARE(d->findChild<QDoubleSpinBox *>(u"setterY"_s)->value(), -1.0);
            // Stop during a jog: grblHAL's jog cancel, where the machine stands, and it stays ready (no alarm
            // to unlock, as the reset it was).
            d->findChild<QComboBox *>(u"setterJogStep"_s)->setCurrentIndex(2); // 10 mm, 0.6 s at 1000 mm/min
            QTRY_VERIFY(d->findChild<QPushButton *>(u"setterJogXPlus"_s)->isEnabled());
            d->findChild<QPushButton *>(u"setterJogXPlus"_s)->click();
            QTRY_VERIFY_WITH_TIMEOUT(s.window.connection()->link()->lastStatus()
                    && s.window.connection()->link()->lastStatus()->state == u"Jog"_s,
                5000);
            d->findChild<QPushButton *>(u"setterJogStop"_s)->click();
            auto *said = d->findChild<QLabel *>(u"setterJogResult"_s);
            QTRY_VERIFY_WITH_TIMEOUT(said->text().contains(u"stopped where the machine stands"_s), 10000);
            QVERIFY(!s.window.connection()->isHalted());
            const double x = s.window.connection()->link()->lastStatus()->mpos[0];
            QVERIFY2(x > 10.0 && x < 20.0, qPrintable(QString::number(x)));
            ok->click();
        });
        s.trigger(u"actionToolSetter"_s);
        QTRY_VERIFY(s.window.connection()->session()->toolSetter().has_value());
        QCOMPARE(s.window.connection()->session()->toolSetter()->zMin, -120.0);
        QCOMPARE(s.window.connection()->session()->toolSetter()->x, 10.0);
        QCOMPARE(s.window.connection()->session()->toolSetter()->y, -1.0);
        {
            auto library = Library::open({ s.libraryPath() });
            // Kept under the machine's name: nobody named it, so it is called after its kind.
            const auto kept = library.value()->toolSetter(u"grblHAL"_s);
            QVERIFY(kept && kept.value());
            QCOMPARE(kept.value()->seekFeed, 3000.0);
        }

        // The first tool measured is the reference, said before and after; the second against it.
        QVERIFY(s.window.connection()->probeMakesReference());
        const QString first = s.probe();
        QVERIFY2(
            first.contains(u"This machine has no reference tool yet: T1 becomes it"_s), qPrintable(first));
        QVERIFY(waitIdle(s, 60000));
        QCOMPARE(*s.table().find(1)->measuredTlo, 0.0);
        QCOMPARE(*s.table().find(1)->referenceMz, -70.0);
        QVERIFY2(
            s.text(u"probeResultLabel"_s).contains(u"T1 is this machine's reference tool (its TLO is 0)"_s),
            qPrintable(s.text(u"probeResultLabel"_s)));
        QVERIFY(!s.window.connection()->probeMakesReference());
        QVERIFY(s.window.connection()->selectTool(2, {}));
        QVERIFY(waitIdle(s, 60000));
        const QString second = s.probe();
        QVERIFY2(!second.isEmpty() && !second.contains(u"reference"_s), qPrintable(second));
        QVERIFY(waitIdle(s, 60000));
        QCOMPARE(*s.table().find(2)->measuredTlo, 15.3);
        QCOMPARE(s.text(u"tloLabel"_s), u"15.300 mm"_s);
        // The strip shows the TLO whole at 1280 px (it was cut to "15.300 mr").
        auto *tloLabel = s.find<QLabel>(u"tloLabel"_s);
        QTRY_VERIFY2(tloLabel->width() >= tloLabel->fontMetrics().horizontalAdvance(tloLabel->text()),
            qPrintable(u"%1 px for %2 px of text"_s.arg(tloLabel->width())
                           .arg(tloLabel->fontMetrics().horizontalAdvance(tloLabel->text()))));
        // The offset panel shows what grblHAL is sent, in its words.
        s.find<QDoubleSpinBox>(u"offsetValueSpin"_s)->setValue(15.5);
        // One command a line, each whole (it was cut to "G10 L1 P2 Z15.5, G43" at 1280 px).
        auto *preview = s.find<QLabel>(u"offsetCommandPreview"_s);
        QTRY_COMPARE(preview->text(), u"G10 L1 P2 Z15.5\nG43 H2"_s);
        QTRY_VERIFY(preview->width() >= preview->fontMetrics().horizontalAdvance(u"G10 L1 P2 Z15.5"_s)
            && preview->height() >= 2 * preview->fontMetrics().height());
        screenshot(s.window, u"grblhal-probed.png"_s);

        // 0.5 mm shorter: broken; the stored TLO kept.
        QVERIFY(peer.writeSetter(-100.0, { { 1, 30.0 }, { 2, 44.8 } }));
        answerNextBox(QMessageBox::Yes);
        QString box;
        QTimer::singleShot(300, [&box] { answerAnyBox(&box); });
        s.trigger(u"actionBreakTest"_s);
        QVERIFY(waitIdle(s, 60000));
        QTRY_VERIFY2(box.contains(u"kept in the table and in grblHAL"_s), qPrintable(box));
        // grblHAL is not halted by Toffee's break test, and the box does not say it is.
        QVERIFY2(box.contains(u"not halted"_s), qPrintable(box));
        QVERIFY(!s.window.connection()->isHalted());
        QTRY_VERIFY(s.text(u"breakVerdictLabel"_s).contains(u"BROKEN"_s, Qt::CaseInsensitive));
        QVERIFY(s.table().find(2)->breakTestFailed);
        QCOMPARE(*s.table().find(2)->measuredTlo, 15.3);

        // The rack is the Carvera's: not offered, and said why.
        QVERIFY(!s.find<QAction>(u"actionMeasureRack"_s)->isEnabled());

        // Pull: T5, set on the controller, comes in as set there (not measured), after its preview.
        QVERIFY(s.find<QAction>(u"actionPullOffsets"_s)->isEnabled());
        QStringList pullRows;
        inNextDialog<OffsetSyncDialog>([&](OffsetSyncDialog *d) {
            pullRows = rowsOf(d->table());
            screenshot(*d, u"grblhal-pull-preview.png"_s);
            d->findChild<QPushButton *>(u"offsetsGoButton"_s)->click();
        });
        s.trigger(u"actionPullOffsets"_s);
        QVERIFY(waitIdle(s, 60000));
        QVERIFY2(pullRows.contains(u"T5|—|2.500|new tool"_s), qPrintable(pullRows.join(u'\n')));
        QVERIFY2(pullRows.contains(u"T2|15.300|15.300|unchanged"_s), qPrintable(pullRows.join(u'\n')));
        QVERIFY2(pullRows.contains(u"T1|0.000|0.000|unchanged"_s), qPrintable(pullRows.join(u'\n')));
        QCOMPARE(*s.table().find(5)->measuredTlo, 2.5);
        QCOMPARE(s.table().find(5)->tloSource, TloSource::Pulled);
        // Said as read from the controller, not as set by hand: in the table and in its tooltip.
        ToolTableModel *model = s.window.document()->model();
        QModelIndex t5;
        for (int row = 0; row < model->rowCount(); ++row) {
            if (model->index(row, ToolTableModel::NumberColumn).data().toInt() == 5)
                t5 = model->index(row, ToolTableModel::MeasuredTloColumn);
        }
        QCOMPARE(t5.data().toString(), u"2.500 (pulled)"_s);
        QVERIFY2(t5.data(Qt::ToolTipRole).toString().contains(u"read from the controller's own table"_s),
            qPrintable(t5.data(Qt::ToolTipRole).toString()));
        QVERIFY(!s.table().find(5)->referenceMz);
        // One undo takes the pull back.
        s.window.document()->undoStack()->undo();
        QVERIFY(!s.table().find(5));
        s.window.document()->undoStack()->redo();
        QCOMPARE(*s.table().find(5)->measuredTlo, 2.5);

        // Push: T1's entry changed on the controller behind Toffee's back is written back from the file.
        s.window.connection()->disconnectFromMachine();
        QVERIFY(peer.ask("G10 L1 P1 Z7").contains("ok"));
        connectTo(s, peer);
        // Check Job reads grblHAL's table as connected: T1's entry is not the file's.
        QTemporaryDir dir;
        const QString program = dir.filePath(u"job.nc"_s);
        {
            QFile f(program);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("G21 G90\nM6 T1\nG43 H1\nG1 Z-1 F100\nM30\n");
        }
        JobCheckDialog *check = s.window.openJobCheck(program);
        QTRY_VERIFY(check->report().has_value() && !check->isRunning());
        QCOMPARE(check->report()->dialect, Dialect::GrblHal);
        const auto differs = [&] {
            const QList<Finding> findings = check->report()->findings;
            return std::any_of(findings.cbegin(), findings.cend(), [](const Finding &f) {
                return f.kind == FindingKind::ControllerTableDiffers && f.tool == 1;
            });
        };
        QVERIFY(differs());
        check->close();
        QStringList pushRows;
        inNextDialog<OffsetSyncDialog>([&](OffsetSyncDialog *d) {
            pushRows = rowsOf(d->table());
            screenshot(*d, u"grblhal-push-preview.png"_s);
            d->findChild<QPushButton *>(u"offsetsGoButton"_s)->click();
        });
        s.trigger(u"actionPushOffsets"_s);
        QVERIFY(waitIdle(s, 60000));
        QVERIFY2(pushRows.contains(u"T1|0.000|7.000|written"_s), qPrintable(pushRows.join(u'\n')));
        QVERIFY2(pushRows.contains(u"T5|2.500|2.500|unchanged"_s), qPrintable(pushRows.join(u'\n')));

        // Checked again: in step now.
        check = s.window.openJobCheck(program);
        QTRY_VERIFY(check->report().has_value() && !check->isRunning());
        QVERIFY(!differs());
        check->close();

        // grblHAL's tool change from the table (Ctrl+Shift+M): asked first, then the wait for the person,
        // Continue (cycle start), and T2 measured (now 0.5 mm shorter) and recorded.
        QVERIFY(s.window.connection()->selectTool(1, {}));
        QVERIFY(waitIdle(s, 60000));
        s.window.findChild<ToolTablePanel *>()->selectTool(2);
        QTRY_VERIFY(s.find<QAction>(u"actionChangeTo"_s)->isEnabled());
        QString changeQuestion;
        answerNextBox(QMessageBox::NoButton, &changeQuestion, u"changeToYesButton"_s);
        s.trigger(u"actionChangeTo"_s);
        QTRY_VERIFY_WITH_TIMEOUT(QApplication::activeModalWidget()
                && QApplication::activeModalWidget()->objectName() == u"toolChangeWaitBox"_s,
            15000);
        QVERIFY2(changeQuestion.contains(u"waits for you to put T2 in the spindle"_s)
                && changeQuestion.contains(u"Sends: M6 T2"_s),
            qPrintable(changeQuestion));
        QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"Waiting for the operator"_s);
        screenshot(s.window, u"grblhal-tool-change.png"_s);
        QTest::mouseClick(
            QApplication::activeModalWidget()->findChild<QPushButton *>(u"toolChangeContinueButton"_s),
            Qt::LeftButton);
        QVERIFY(waitIdle(s, 60000));
        QCOMPARE(s.window.connection()->activeTool(), std::optional(2));
        QCOMPARE(*s.table().find(2)->measuredTlo, 14.8);
        QCOMPARE(s.table().find(2)->tloSource, TloSource::Probe);
        QVERIFY2(
            s.window.statusBar()->currentMessage().contains(u"T2 is in the spindle, measured: TLO 14.800"_s),
            qPrintable(s.window.statusBar()->currentMessage()));
        s.window.connection()->disconnectFromMachine();
        QCOMPARE(peer.tableZ(1), std::optional(0.0));
        QCOMPARE(peer.tableZ(2), std::optional(14.8));
    }
};

QTEST_MAIN(TestGrblHalWindow)
#include "tst_grblhalwindow.moc"
