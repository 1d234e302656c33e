// SPDX-License-Identifier: GPL-3.0-or-later
// Whole stories through the real window (offscreen) against the built-in emulator about what the history
// library keeps: a locked, a wrong and a damaged library with the window working on, the library and the
// machine's name chosen in a dialog, a probe off the trend, a program's cutting time for each tool. At each
// step, what the window shows and what the library holds.
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

class TestHistoryWorkflows : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { Test::isolateWindowTest(u"tst_historyworkflows"_s); }
    void init() { Test::startFresh(); }

    // The history library is locked by another program (toffee-cli writing a long batch): the probe is in the
    // table at once, the status bar says once that the library waits, and the measurement is written after.
    void aLockedHistoryLibraryKeepsTheMeasurementAndWritesItLater()
    {
        Station s;
        s.connect();
        s.probe();
        QCOMPARE(s.window.history()->library()->history({}).value().size(), 1);
        QSqlDatabase other = QSqlDatabase::addDatabase(u"QSQLITE"_s, u"other-program"_s);
        other.setDatabaseName(s.libraryPath());
        QVERIFY(other.open());
        QSqlQuery lock(other);
        QVERIFY(lock.exec(u"BEGIN IMMEDIATE"_s));

        s.machine()->setToolLength(1, 77.69); // worn by 0.01: a new TLO the table must show now
        s.probe();
        QCOMPARE(*s.table().find(1)->measuredTlo, 43.03);
        QCOMPARE(s.window.history()->pendingCount(), 1);
        QVERIFY(s.window.statusBar()->currentMessage().contains(u"cannot be written"_s));
        QVERIFY(s.window.statusBar()->currentMessage().contains(s.libraryPath()));

        QVERIFY(lock.exec(u"ROLLBACK"_s));
        QTRY_COMPARE_WITH_TIMEOUT(s.window.history()->pendingCount(), 0, 3 * HistoryRecorder::kRetryMs);
        QVERIFY(s.window.statusBar()->currentMessage().contains(u"written again"_s));
        const auto events = s.window.history()->library()->history({}).value();
        QCOMPARE(events.size(), 2);
        QCOMPARE(events.last().tlo, 43.03);
        lock.finish();
        other.close();
        other = QSqlDatabase();
        QSqlDatabase::removeDatabase(u"other-program"_s);
    }

    // A library that is not one (a folder here) is named in the status bar; the table and the machine work
    // on, and the measurement waits for a library.
    void aLibraryThatIsNotOneLeavesTheTableUsable()
    {
        Station s;
        QTemporaryDir dir;
        s.window.setLibrary({ dir.path() });
        QVERIFY(s.window.statusBar()->currentMessage().contains(dir.path() + u" is a folder"_s));
        s.connect();
        s.probe();
        QCOMPARE(*s.table().find(1)->measuredTlo, 43.04);
        QCOMPARE(s.window.history()->pendingCount(), 1);
        s.window.setLibrary({ s.libraryPath() }); // a library again: what waited is written
        QCOMPARE(s.window.history()->pendingCount(), 0);
        QCOMPARE(s.window.history()->library()->history({}).value().size(), 1);
    }

    // A library whose schema version another program made -1 (it crashed the window at every start): the
    // window starts, says what is wrong and what to do, and the measurement waits for a library.
    void aDamagedLibraryIsSaidAndTheWindowWorksOn()
    {
        Station s;
        QTemporaryDir dir;
        const QString path = dir.filePath(u"damaged.sqlite"_s);
        QVERIFY(Library::open({ path }));
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(u"QSQLITE"_s, u"damage"_s);
            db.setDatabaseName(path);
            QVERIFY(db.open());
            QSqlQuery query(db);
            QVERIFY(query.exec(u"UPDATE toffee_schema SET version = -1"_s));
        }
        QSqlDatabase::removeDatabase(u"damage"_s);
        s.window.setLibrary({ path });
        const QString said = s.window.statusBar()->currentMessage();
        QVERIFY2(said.contains(u"is damaged: its schema version is \"-1\""_s), qPrintable(said));
        QVERIFY(said.contains(u"restore it from a backup"_s));
        s.connect();
        s.probe();
        QCOMPARE(*s.table().find(1)->measuredTlo, 43.04);
        QCOMPARE(s.window.history()->pendingCount(), 1);
    }

    // Machine ▸ History Library…: another library and another machine name; a folder is refused with the
    // dialog still open.
    void theHistoryLibraryAndTheMachinesNameAreChosenInADialog()
    {
        Station s;
        QTemporaryDir dir;
        const QString other = dir.filePath(u"shop.sqlite"_s);
        QString refusal;
        QTimer::singleShot(0, [&] {
            auto *dialog = qobject_cast<QDialog *>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            dialog->findChild<QLineEdit *>(u"libraryPathEdit"_s)->setText(dir.path()); // a folder
            answerNextBox(QMessageBox::Ok, &refusal);
            dialog->accept();
            QVERIFY(dialog->isVisible()); // refused: still open
            dialog->findChild<QLineEdit *>(u"libraryPathEdit"_s)->setText(other);
            dialog->findChild<QLineEdit *>(u"machineNameEdit"_s)->setText(u"Mill 2"_s);
            dialog->findChild<QSpinBox *>(u"staleDaysSpin"_s)->setValue(3);
            dialog->accept();
        });
        s.trigger(u"actionHistorySettings"_s);
        QVERIFY2(refusal.contains(u"is a folder"_s), qPrintable(refusal));
        QCOMPARE(AppSettings().machineName(), u"Mill 2"_s);
        QCOMPARE(AppSettings().staleAfterDays(), 3);
        QCOMPARE(s.window.document()->model()->staleAfterDays(), 3);
        QCOMPARE(s.window.history()->location().path, other);
        s.connect();
        s.probe();
        const auto events = s.window.history()->library()->history({}).value();
        QCOMPARE(events.size(), 1);
        QCOMPARE(events.front().machine, u"Mill 2"_s);
        const auto machines = s.window.history()->library()->machines().value();
        QCOMPARE(machines.size(), 1);
        QCOMPARE(machines.front().dialect, u"carvera"_s);
        QCOMPARE(machines.front().connection, s.window.connection()->description());
    }

    // A tool that measures far off its trend is pointed out with numbers as soon as it is probed.
    void aProbeOffTheTrendIsPointedOut()
    {
        Station s;
        s.connect();
        s.probe(); // T1
        s.machine()->setToolLength(1, 77.6); // 0.1 shorter: within the 0.1 tolerance of the trend
        s.probe();
        QVERIFY(!s.window.statusBar()->currentMessage().contains(u"trend"_s));
        s.machine()->setToolLength(1, 77.3); // 0.4 short of where it started, well below its trend: the tip
        s.probe();
        QVERIFY2(s.window.statusBar()->currentMessage().startsWith(u"T1 measured "_s)
                && s.window.statusBar()->currentMessage().contains(
                    u"shorter than its trend predicts (±0.1): check the tip"_s),
            qPrintable(s.window.statusBar()->currentMessage()));
    }

    // The operator records that a program ran: each tool's cutting time goes into the library and the table.
    void aProgramRunGivesEachToolItsCuttingTime()
    {
        Station s;
        QVERIFY(s.window.openFile(Test::kExampleTable));
        QTemporaryDir dir;
        const QString program = dir.filePath(u"pocket.nc"_s);
        QFile file(program);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("M6 T2\nG0 X0 Y0\nG1 X600 F600\nM6 T3\nG1 X0 F1200\nG2 X0 Y0 I5\nM30\n");
        file.close();
        const auto recorded = s.window.recordProgramRun(program);
        QVERIFY2(recorded, qPrintable(recorded.error().message));
        QCOMPARE(recorded.value(), 2);
        QCOMPARE(s.cell(2, ToolTableModel::ToolLifeColumn), u"1 min"_s); // 600 mm at 600 mm/min
        QCOMPARE(s.cell(3, ToolTableModel::ToolLifeColumn), u"32 s"_s); // 600 mm and a 10π mm circle at 1200
        QVERIFY(s.cell(1, ToolTableModel::ToolLifeColumn).isEmpty());
        QCOMPARE(
            s.window.history()->library()->uses(u"Carvera"_s, 2).value().front().program, u"pocket.nc"_s);
        // A program the interpreter refuses records nothing.
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("M6 T2\nG1 X10 F100\nG2 X50 Y0 R10\n");
        file.close();
        const auto refused = s.window.recordProgramRun(program);
        QVERIFY(!refused);
        QVERIFY(refused.error().message.contains(u"Nothing was recorded"_s));
        QCOMPARE(s.cell(2, ToolTableModel::ToolLifeColumn), u"1 min"_s);
    }
};

QTEST_MAIN(TestHistoryWorkflows)
#include "tst_historyworkflows.moc"
