// SPDX-License-Identifier: GPL-3.0-or-later
// The window on LinuxCNC itself (TOFFEE_LINUXCNC_PEER), as a mill's owner runs it: the connection panel's
// network choice with LinuxCNC's address typed (found by asking), a probe refused in estop with what to do,
// the machine made ready at LinuxCNC's own screen, Machine ▸ Tool Setter… kept for the machine, two tools
// probed (the first the reference) into the table and into LinuxCNC's tool.tbl, a break test that finds a
// tool 0.4 mm shorter with nothing overwritten, Push Offsets and Pull Offsets through their previews. With
// TOFFEE_SCREENSHOTS set, the window and the previews are saved there.
#include <algorithm>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>

#include "tests/support/linuxcncpeer.h"
#include "tests/support/messageboxes.h"
#include "tests/support/station.h"
#include "tests/support/windowsteps.h"
#include "ui/connection/connectionpanel.h"
#include "ui/connection/linuxcncaccessdialog.h"
#include "ui/job/jobcheckdialog.h"
#include "ui/machine/consoledock.h"
#include "ui/machine/offsetsyncdialog.h"
#include "ui/machine/toolsetterdialog.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

class TestLinuxCncWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        if (const QString why = LinuxCncPeer::skipReason(); !why.isEmpty())
            QSKIP(qPrintable(why));
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void aMillOwnersDay()
    {
        LinuxCncPeer peer({ { 1, 30.0 }, { 2, 45.3 } });
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        Station s;
        s.window.resize(1280, 720);
        auto *panel = s.window.findChild<ConnectionPanel *>();
        panel->setKind(ConnectionPanel::Kind::WiFi);
        s.find<QComboBox>(u"wifiMachineCombo"_s)->setEditText(peer.address());
        auto *controller = s.find<QComboBox>(u"controllerCombo"_s);
        QVERIFY(controller->findData(u"linuxcnc"_s) >= 0); // offered by name, found by asking here
        // Machine ▸ LinuxCNC Access…: a wrong enable password, typed hidden, is refused by LinuxCNC by name.
        inNextDialog<LinuxCncAccessDialog>([](LinuxCncAccessDialog *d) {
            auto *password = d->findChild<QLineEdit *>(u"linuxCncPassword"_s);
            QCOMPARE(password->echoMode(), QLineEdit::Password);
            // Every label reaches its field by its mnemonic (no "&" shown as text).
            for (QLabel *label : d->findChildren<QLabel *>()) {
                if (label->text().contains(u'&'))
                    QVERIFY2(label->buddy(), qPrintable(label->text()));
            }
            password->setText(u"not-it"_s);
            screenshot(*d, u"linuxcnc-access.png"_s);
            d->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok)->click();
        });
        s.trigger(u"actionLinuxCncAccess"_s);
        QSignalSpy failed(s.window.connection(), &MachineConnection::connectFailed);
        QString refused;
        QTimer::singleShot(300, [&refused] { answerAnyBox(&refused); });
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(failed.size(), 1, 20000);
        QVERIFY2(failed.front().front().toString().contains(u"refused the enable password"_s),
            qPrintable(failed.front().front().toString()));
        QVERIFY(!failed.front().front().toString().contains(u"not-it"_s));
        // Nor in the console: the enable line is never shown.
        QVERIFY(!s.window.findChild<ConsoleDock *>()->lines().join(u'\n').contains(u"not-it"_s));
        QTRY_VERIFY(!refused.isEmpty());
        inNextDialog<LinuxCncAccessDialog>([](LinuxCncAccessDialog *d) {
            d->findChild<QLineEdit *>(u"linuxCncPassword"_s)->clear();
            d->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok)->click();
        });
        s.trigger(u"actionLinuxCncAccess"_s);

        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QVERIFY(waitConnected(s));
        QCOMPARE(s.window.connection()->controllerKind(), ControllerKind::LinuxCnc);
        QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"Estop"_s);
        QTRY_VERIFY2(controller->currentText().startsWith(u"Automatic: LinuxCNC"_s),
            qPrintable(controller->currentText()));

        // The setter, kept for the machine; then a probe in estop: refused, saying what to do.
        inNextDialog<ToolSetterDialog>([](ToolSetterDialog *d) {
            d->findChild<QDoubleSpinBox *>(u"setterX"_s)->setValue(10.0);
            d->findChild<QDoubleSpinBox *>(u"setterY"_s)->setValue(10.0);
            d->findChild<QDoubleSpinBox *>(u"setterZMin"_s)->setValue(-140.0);
            d->findChild<QDoubleSpinBox *>(u"setterSeekFeed"_s)->setValue(3000.0);
            d->findChild<QDoubleSpinBox *>(u"setterLatchFeed"_s)->setValue(30.0);
            d->findChild<QDoubleSpinBox *>(u"setterBackoff"_s)->setValue(0.5);
            d->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok)->click();
        });
        s.trigger(u"actionToolSetter"_s);
        QTRY_VERIFY(s.window.connection()->session()->toolSetter().has_value());
        // In estop with nothing in the spindle: Probe says there is nothing to probe; selecting a tool is
        // refused by LinuxCNC's state, saying what to do, and nothing is sent.
        QString box;
        QTimer::singleShot(300, [&box] { answerAnyBox(&box); });
        s.trigger(u"actionProbe"_s);
        QTRY_VERIFY2(box.contains(u"nothing to probe"_s), qPrintable(box));
        std::optional<SessionResult> selected;
        QVERIFY(s.window.connection()->selectTool(1, [&selected](const SessionResult &r) { selected = r; }));
        QTRY_VERIFY(selected.has_value());
        QVERIFY2(selected->message.contains(u"estop"_s) && selected->message.contains(u"never releases"_s),
            qPrintable(selected->message));
        QCOMPARE(peer.get("tool"), QByteArray("0"));

        // Ready at LinuxCNC's own screen (another client), then connected again to hold control.
        QVERIFY(peer.makeReady());
        s.window.connection()->disconnectFromMachine();
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QVERIFY(waitConnected(s));
        QTRY_COMPARE(s.text(u"machineStateLabel"_s), u"Idle"_s);

        QVERIFY(s.window.connection()->selectTool(1, {}));
        QVERIFY(waitIdle(s, 60000));
        QTRY_COMPARE(s.text(u"activeToolLabel"_s), u"T1"_s);
        const QString first = s.probe();
        QVERIFY2(first.contains(u"T1 becomes it"_s), qPrintable(first));
        QVERIFY(waitIdle(s, 60000));
        QCOMPARE(*s.table().find(1)->measuredTlo, 0.0);
        QCOMPARE(*s.table().find(1)->referenceMz, -70.0);
        QVERIFY(s.window.connection()->selectTool(2, {}));
        QVERIFY(waitIdle(s, 60000));
        s.probe();
        QVERIFY(waitIdle(s, 60000));
        QCOMPARE(*s.table().find(2)->measuredTlo, 15.3);
        QCOMPARE(s.text(u"tloLabel"_s), u"15.300 mm"_s);
        QCOMPARE(peer.tableZ(2), std::optional(15.3));
        // The strip shows the TLO whole at 1280 px.
        auto *tloLabel = s.find<QLabel>(u"tloLabel"_s);
        QTRY_VERIFY2(tloLabel->width() >= tloLabel->fontMetrics().horizontalAdvance(tloLabel->text()),
            qPrintable(u"%1 px for %2 px of text"_s.arg(tloLabel->width())
                           .arg(tloLabel->fontMetrics().horizontalAdvance(tloLabel->text()))));
        // Idle, the state is asked for every half second: never stale, and never in the console.
        QTest::qWait(2000);
        QVERIFY(!s.window.connection()->isStatusStale());
        QCOMPARE(s.text(u"machineStateLabel"_s), u"Idle"_s);
        const QStringList shown = s.window.findChild<ConsoleDock *>()->lines();
        const QString polled = shown.filter(u"get estop"_s).join(u'\n');
        QTest::qWait(2000);
        QCOMPARE(s.window.findChild<ConsoleDock *>()->lines().filter(u"get estop"_s).join(u'\n'), polled);
        screenshot(s.window, u"linuxcnc-probed.png"_s);

        // 0.4 mm shorter: broken; the stored TLO kept in the table and in LinuxCNC's.
        QVERIFY(peer.setLength(2, 44.9));
        answerNextBox(QMessageBox::Yes);
        box.clear();
        QTimer::singleShot(300, [&box] { answerAnyBox(&box); });
        s.trigger(u"actionBreakTest"_s);
        QVERIFY(waitIdle(s, 60000));
        QTRY_VERIFY2(box.contains(u"kept in the table and in LinuxCNC"_s), qPrintable(box));
        QVERIFY(s.table().find(2)->breakTestFailed);
        QCOMPARE(*s.table().find(2)->measuredTlo, 15.3);
        QCOMPARE(peer.tableZ(2), std::optional(15.3));
        QVERIFY(!s.find<QAction>(u"actionMeasureRack"_s)->isEnabled());

        // Someone sets T1 at LinuxCNC's screen: Check Job, in LinuxCNC's dialect, warns that its table
        // differs from the file; Push writes the file's back, after its preview, and the job checks clean of
        // it.
        QCOMPARE(peer.ask({ "set mdi G10 L1 P1 Z7" }), QList<QByteArray> { "SET MDI ACK" });
        s.window.connection()->disconnectFromMachine();
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QVERIFY(waitConnected(s));
        QTemporaryDir dir;
        const QString program = dir.filePath(u"job.ngc"_s);
        {
            QFile f(program);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("G21 G90\nM6 T1\nG43 H1\nG1 Z-1 F100\nM30\n");
        }
        const auto differs = [&s, &program] {
            JobCheckDialog *check = s.window.openJobCheck(program);
            if (!QTest::qWaitFor([check] { return check->report().has_value() && !check->isRunning(); }))
                return -1;
            const JobReport report = *check->report();
            check->close();
            if (report.dialect != Dialect::LinuxCnc)
                return -2;
            return int(std::count_if(report.findings.cbegin(), report.findings.cend(), [](const Finding &f) {
                return f.kind == FindingKind::ControllerTableDiffers && f.tool == 1;
            }));
        };
        QCOMPARE(differs(), 1);
        QVERIFY(s.find<QAction>(u"actionPushOffsets"_s)->isEnabled());
        QStringList pushRows;
        inNextDialog<OffsetSyncDialog>([&](OffsetSyncDialog *d) {
            pushRows = rowsOf(d->table());
            screenshot(*d, u"linuxcnc-push-preview.png"_s);
            d->findChild<QPushButton *>(u"offsetsGoButton"_s)->click();
        });
        s.trigger(u"actionPushOffsets"_s);
        QVERIFY(waitIdle(s, 60000));
        QVERIFY2(pushRows.contains(u"T1|0.000|7.000|written"_s), qPrintable(pushRows.join(u'\n')));
        QCOMPARE(peer.tableZ(1), std::optional(0.0));
        QCOMPARE(differs(), 0);

        // Pull: T2 set at LinuxCNC's screen comes in as set there, after its preview.
        QCOMPARE(peer.ask({ "set mdi G10 L1 P2 Z14.9" }), QList<QByteArray> { "SET MDI ACK" });
        s.window.connection()->disconnectFromMachine();
        QTest::mouseClick(s.find<QPushButton>(u"connectButton"_s), Qt::LeftButton);
        QVERIFY(waitConnected(s));
        QStringList pullRows;
        inNextDialog<OffsetSyncDialog>([&](OffsetSyncDialog *d) {
            pullRows = rowsOf(d->table());
            d->findChild<QPushButton *>(u"offsetsGoButton"_s)->click();
        });
        s.trigger(u"actionPullOffsets"_s);
        QVERIFY(waitIdle(s, 60000));
        QVERIFY2(pullRows.contains(u"T2|15.300|14.900|taken, as set on the controller"_s),
            qPrintable(pullRows.join(u'\n')));
        QCOMPARE(*s.table().find(2)->measuredTlo, 14.9);
        QCOMPARE(s.table().find(2)->tloSource, TloSource::Pulled);

        // The console takes G-code for LinuxCNC's MDI, and names a line it takes.
        auto *console = s.window.findChild<ConsoleDock *>();
        auto *command = s.find<QLineEdit>(u"consoleCommand"_s);
        QVERIFY2(command->placeholderText().contains(u"G43 H2"_s), qPrintable(command->placeholderText()));
        QTRY_VERIFY(s.window.connection()->canOperate());
        console->sendCommand(u"G4 P0.1"_s, false);
        QTRY_VERIFY2(console->lines().join(u'\n').contains(u"> set mdi G4 P0.1"_s),
            qPrintable(console->lines().join(u'\n')));
        QTRY_VERIFY(s.window.connection()->canOperate());
        const QStringList lines = console->lines();
        const qsizetype sent = lines.indexOf(QRegularExpression(u".*> set mdi G4 P0\\.1$"_s));
        QVERIFY(sent >= 0 && sent + 1 < lines.size());
        QVERIFY2(lines.at(sent + 1).endsWith(u"< SET MDI ACK"_s), qPrintable(lines.at(sent + 1)));
        s.window.connection()->disconnectFromMachine();
    }
};

QTEST_MAIN(TestLinuxCncWindow)
#include "tst_linuxcncwindow.moc"
