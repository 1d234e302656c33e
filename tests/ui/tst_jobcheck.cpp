// SPDX-License-Identifier: GPL-3.0-or-later
// File ▸ Check Job… as an operator uses it: a program checked against the open table with progress and Cancel
// while the window keeps answering, the findings by line and the program around one, Prepare… with its side
// by side preview and the prepared file, a program dropped on the window.
#include <QAbstractItemModelTester>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QScopeGuard>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include "model/document/tooldocument.h"
#include "tests/support/programs.h"
#include "tests/support/testclock.h"
#include "ui/job/jobcheckdialog.h"
#include "ui/job/jobpreparedialog.h"
#include "ui/job/jobreportmodels.h"
#include "ui/shell/mainwindow.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

const QString kExample = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

// The operator's program: T2 (measured), T3 (not measured), T9 (not in the table, a manual change), a plunge
// to Z-22.
const QByteArray kProgram = "(pocket, posted for the Carvera)\n" // 1
                            "G21 G90 G17\n"
                            "M6 T2\n" // 3
                            "M3 S12000\n"
                            "G0 X0 Y0 Z5\n"
                            "G1 Z-1.5 F300\n"
                            "G1 X40 F800\n" // 7: T2's last cut
                            "G0 Z5\n"
                            "M6 T3\n" // 9
                            "G1 Z-0.5 F200\n"
                            "M6 T9\n" // 11
                            "G1 Z-22 F100\n" // 12
                            "M30\n";

QString write(const QTemporaryDir &dir, const QString &name, const QByteArray &content)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (file.open(QIODevice::WriteOnly))
        file.write(content);
    return path;
}

QString column(const QAbstractItemModel *model, int column)
{
    QStringList cells;
    for (int row = 0; row < model->rowCount(); ++row)
        cells << model->index(row, column).data().toString();
    return cells.join(u'|');
}

bool waitForCheck(JobCheckDialog *dialog)
{
    return QTest::qWaitFor([dialog] { return !dialog->isRunning() && dialog->report(); }, 60000);
}

} // namespace

class TestJobCheck : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear(); // what an earlier run chose (a controller, a floor) is not this run's
        Test::setClock(Test::exampleMorningAfter()); // the example's TLOs a day old, whatever day it is
    }

    void checksAProgramAndShowsItsToolsAndFindings()
    {
        MainWindow window;
        window.setLibrary({ m_dir.filePath(u"library.sqlite"_s) }); // this test's history only
        QVERIFY(window.openFile(kExample));
        window.show();
        QVERIFY(window.findChild<QAction *>(u"actionCheckJob"_s));
        QCOMPARE(window.findChild<QAction *>(u"actionCheckJob"_s)->shortcut(), QKeySequence(u"Ctrl+J"_s));
        JobCheckDialog *dialog = window.openJobCheck(write(m_dir, u"pocket.nc"_s, kProgram));
        QVERIFY(waitForCheck(dialog));
        // The floor is on from the first check, 20 mm below work Z0: T9's plunge to Z-22 is below it. Off, it
        // is checked again without it (and stays off: remembered).
        auto *floorCheck = dialog->findChild<QCheckBox *>(u"jobFloorCheck"_s);
        QVERIFY(floorCheck->isChecked());
        QCOMPARE(dialog->findChild<QDoubleSpinBox *>(u"jobFloorSpin"_s)->value(), -20.0);
        QCOMPARE(dialog->report()->errors(), 2);
        floorCheck->setChecked(false);
        QVERIFY(waitForCheck(dialog));
        auto *tools = dialog->findChild<QTableView *>(u"jobToolsView"_s)->model();
        QCOMPARE(column(tools, JobToolsModel::NumberColumn), u"T2|T3|T9"_s);
        QCOMPARE(column(tools, JobToolsModel::LoadedColumn), u"3|9|11"_s);
        QCOMPARE(column(tools, JobToolsModel::TloColumn), u"9.652|not measured|not in the table"_s);
        auto *findings = dialog->findChild<QTableView *>(u"jobFindingsView"_s);
        QCOMPARE(column(findings->model(), JobFindingsModel::LineColumn), u"9|11|11"_s);
        QCOMPARE(column(findings->model(), JobFindingsModel::SeverityColumn), u"Warning|Error|Warning"_s);
        QVERIFY(findings->model()
                    ->index(1, JobFindingsModel::MessageColumn)
                    .data()
                    .toString()
                    .contains(u"T9 is not in the tool table"_s));
        const QString summary = dialog->findChild<QLabel *>(u"jobSummaryLabel"_s)->text();
        QVERIFY2(summary.contains(u"13 lines as Carvera"_s) && summary.contains(u"1 error, 2 warnings"_s),
            qPrintable(summary));
        QVERIFY(!dialog->findChild<QProgressBar *>(u"jobProgress"_s)->isVisible());
        // A program with errors is not prepared; the button says why.
        auto *prepare = dialog->findChild<QPushButton *>(u"jobPrepareButton"_s);
        QVERIFY(!prepare->isEnabled());
        QVERIFY(prepare->toolTip().contains(u"fix them before preparing"_s));
        // Tab leaves a table for the next control.
        QVERIFY(!findings->tabKeyNavigation());

        // The floor: the plunge of T9 to Z-22 is below it. Setting it checks again by itself.
        dialog->findChild<QDoubleSpinBox *>(u"jobFloorSpin"_s)->setValue(-20.0);
        dialog->findChild<QCheckBox *>(u"jobFloorCheck"_s)->setChecked(true);
        QVERIFY(waitForCheck(dialog));
        QCOMPARE(column(findings->model(), JobFindingsModel::LineColumn), u"9|11|11|12"_s);
        QCOMPARE(dialog->report()->errors(), 2);

        // Enter on a finding shows the program around its line, the line marked.
        findings->setFocus();
        findings->setCurrentIndex(findings->model()->index(3, 0));
        QTest::keyClick(findings, Qt::Key_Return);
        const QString excerpt = dialog->findChild<QPlainTextEdit *>(u"jobExcerpt"_s)->toPlainText();
        QVERIFY2(excerpt.contains(u"▶ 12  G1 Z-22 F100"_s), qPrintable(excerpt));
        QVERIFY(excerpt.contains(u"   4  M3 S12000"_s));
        QVERIFY(!excerpt.contains(u"(pocket"_s)); // eight lines either side, no more
    }

    void aLongCheckShowsProgressKeepsTheWindowAnsweringAndCancels()
    {
        MainWindow window;
        window.setLibrary({ m_dir.filePath(u"library.sqlite"_s) }); // this test's history only
        QVERIFY(window.openFile(kExample));
        window.show();
        const QString big = m_dir.filePath(u"big.nc"_s);
        QVERIFY(Test::writeCamProgram(big, 3000000));
        // The window's event loop turns while the check runs: a timer fires again and again.
        int ticks = 0;
        QTimer ticker;
        connect(&ticker, &QTimer::timeout, this, [&ticks] { ++ticks; });
        ticker.start(10);
        JobCheckDialog *dialog = window.openJobCheck(big);
        auto *progress = dialog->findChild<QProgressBar *>(u"jobProgress"_s);
        QVERIFY(progress->isVisible());
        QVERIFY(QTest::qWaitFor([progress] { return progress->value() > 0; }, 30000));
        // The timer fires again and again while the check still runs (a blocked loop would let it fire only
        // once the check is over).
        QVERIFY(QTest::qWaitFor([&] { return ticks >= 2 || !dialog->isRunning(); }, 30000));
        QVERIFY(dialog->isRunning());
        QVERIFY2(ticks >= 2, qPrintable(QString::number(ticks)));
        QTest::mouseClick(dialog->findChild<QPushButton *>(u"jobCancelButton"_s), Qt::LeftButton);
        QVERIFY(waitForCheck(dialog));
        QVERIFY(dialog->report()->cancelled);
        QVERIFY(dialog->report()->lines < 3000000);
        QVERIFY(dialog->findChild<QLabel *>(u"jobSummaryLabel"_s)->text().startsWith(u"Cancelled after"_s));
        QVERIFY(!dialog->findChild<QPushButton *>(u"jobPrepareButton"_s)->isEnabled());
        // Run through, it covers every line.
        QTest::mouseClick(dialog->findChild<QPushButton *>(u"jobCheckAgainButton"_s), Qt::LeftButton);
        QVERIFY(waitForCheck(dialog));
        QVERIFY(!dialog->report()->cancelled);
        QCOMPARE(dialog->report()->lines, 3000000);
        // Escape while a check runs stops it, then closes the dialog.
        QPointer<JobCheckDialog> closing = dialog;
        QTest::mouseClick(dialog->findChild<QPushButton *>(u"jobCheckAgainButton"_s), Qt::LeftButton);
        QVERIFY(dialog->isRunning());
        QTest::keyClick(dialog, Qt::Key_Escape);
        QVERIFY(QTest::qWaitFor([&closing] { return closing.isNull(); }, 30000));
    }

    void preparesTheProgramWithASideBySidePreview()
    {
        MainWindow window;
        window.setLibrary({ m_dir.filePath(u"library.sqlite"_s) }); // this test's history only
        QVERIFY(window.openFile(kExample));
        window.show();
        const QString program = write(m_dir, u"two.nc"_s, kProgram.left(kProgram.indexOf("M6 T9")) + "M30\n");
        JobCheckDialog *dialog = window.openJobCheck(program);
        QVERIFY(waitForCheck(dialog));
        auto *prepare = dialog->findChild<QPushButton *>(u"jobPrepareButton"_s);
        QVERIFY(prepare->isEnabled());
        const QString output = m_dir.filePath(u"two.prepared.nc"_s);
        bool saw = false;
        QTimer::singleShot(0, this, [&saw, output, program] {
            auto *prep = qobject_cast<JobPrepareDialog *>(QApplication::activeModalWidget());
            QVERIFY(prep);
            // Closed however the checks below end, so that a failure fails the test instead of hanging it.
            const auto close = qScopeGuard([prep] { prep->close(); });
            QVERIFY(QTest::qWaitFor([prep] { return !prep->isRunning() && prep->summary(); }, 30000));
            auto *preview = prep->findChild<QTableWidget *>(u"preparePreview"_s);
            QStringList inserted;
            for (int row = 0; row < preview->rowCount(); ++row) {
                if (!preview->item(row, 0) && preview->item(row, 3))
                    inserted << preview->item(row, 3)->text();
            }
            QVERIFY2(inserted.size() == 3, qPrintable(inserted.join(u'\n')));
            QVERIFY(inserted.at(0).startsWith(u"M5 (Toffee: the spindle stops for T2's break test)"_s));
            QVERIFY(inserted.at(1).startsWith(
                u"M491.1 H0.1 (Toffee: break test of T2 after its cuts up to original line 7"_s));
            // Unticking the break test leaves nothing to do: T2 is a rack tool, measured at its change.
            prep->findChild<QCheckBox *>(u"prepareBreakTestCheck"_s)->setChecked(false);
            QVERIFY(QTest::qWaitFor([prep] { return !prep->isRunning() && prep->summary(); }, 30000));
            QCOMPARE(prep->summary()->inserted, 0);
            QVERIFY(!prep->findChild<QPushButton *>(u"prepareSaveButton"_s)->isEnabled());
            prep->findChild<QCheckBox *>(u"prepareBreakTestCheck"_s)->setChecked(true);
            QVERIFY(QTest::qWaitFor([prep] { return !prep->isRunning() && prep->summary(); }, 30000));
            // Saving over the program itself is refused; the preview stays.
            prep->saveTo(program);
            QVERIFY(QTest::qWaitFor([prep] { return !prep->isRunning(); }, 30000));
            QVERIFY(prep->findChild<QLabel *>(u"prepareStatusLabel"_s)->text().startsWith(u"Not saved"_s));
            QVERIFY(prep->findChild<QTableWidget *>(u"preparePreview"_s)->rowCount() > 0);
            QVERIFY(prep->findChild<QPushButton *>(u"prepareSaveButton"_s)->isEnabled());
            prep->saveTo(output);
            QVERIFY(QTest::qWaitFor([prep] { return !prep->savedTo().isEmpty(); }, 30000));
            saw = true;
        });
        QTest::mouseClick(prepare, Qt::LeftButton);
        QVERIFY(saw);
        QFile written(output);
        QVERIFY(written.open(QIODevice::ReadOnly));
        const QByteArray prepared = written.readAll();
        QCOMPARE(prepared.count("M491.1 H0.1"), 2);
        // And the prepared program checks as cleanly as the original.
        QVERIFY(waitForCheck(window.openJobCheck(output)));
        QCOMPARE(dialog->report()->errors(), 0);
        QCOMPARE(dialog->report()->program, u"two.prepared.nc"_s);
    }

    void aMachineWithoutARackMakesEveryChangeManual()
    {
        MainWindow window;
        window.setLibrary({ m_dir.filePath(u"library.sqlite"_s) }); // this test's history only
        QVERIFY(window.openFile(kExample));
        window.show();
        JobCheckDialog *dialog = window.openJobCheck(write(m_dir, u"rack.nc"_s, "M6 T2\nG1 Z-1 F100\nM30\n"));
        QVERIFY(waitForCheck(dialog));
        QCOMPARE(dialog->report()->findings.size(), 0);
        auto *rack = dialog->findChild<QLineEdit *>(u"jobRackEdit"_s);
        QCOMPARE(rack->text(), u"1-6"_s);
        rack->setText(u"none"_s);
        Q_EMIT rack->editingFinished();
        QVERIFY(waitForCheck(dialog));
        QCOMPARE(dialog->report()->findings.size(), 1);
        QCOMPARE(dialog->report()->findings.front().kind, FindingKind::ManualChange);
        QCOMPARE(QSettings().value(u"jobs/rack"_s).toString(), u"none"_s);
        rack->setText(u"1-6"_s);
        Q_EMIT rack->editingFinished();
        QVERIFY(waitForCheck(dialog));
    }

    void aProgramDroppedOnTheWindowIsChecked()
    {
        MainWindow window;
        window.setLibrary({ m_dir.filePath(u"library.sqlite"_s) }); // this test's history only
        QVERIFY(window.openFile(kExample));
        window.show();
        QVERIFY(window.acceptDrops());
        const QString program = write(m_dir, u"dropped.nc"_s, "M6 T2\nG1 Z-1 F100\nM30\n");
        QMimeData mime;
        mime.setUrls({ QUrl::fromLocalFile(program) });
        QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&window, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&window, &drop);
        auto *dialog = window.findChild<JobCheckDialog *>();
        QVERIFY(dialog);
        QVERIFY(waitForCheck(dialog));
        QCOMPARE(dialog->report()->program, u"dropped.nc"_s);
        // Something that is neither a program nor a table is not taken.
        QMimeData other;
        other.setUrls({ QUrl::fromLocalFile(m_dir.filePath(u"photo.jpg"_s)) });
        QDragEnterEvent refused(QPoint(10, 10), Qt::CopyAction, &other, Qt::LeftButton, Qt::NoModifier);
        refused.setAccepted(false);
        QApplication::sendEvent(&window, &refused);
        QVERIFY(!refused.isAccepted());
    }

    void anotherControllerIsCheckedByItsOwnRules()
    {
        MainWindow window;
        window.setLibrary({ m_dir.filePath(u"library.sqlite"_s) }); // this test's history only
        QVERIFY(window.openFile(kExample));
        window.show();
        JobCheckDialog *dialog = window.openJobCheck(
            write(m_dir, u"fanuc.nc"_s, "T1 M6\nG43 H1 Z50\nG1 Z-1 F100\nT2 M6\nG1 Z-2\nM30\n"));
        QVERIFY(waitForCheck(dialog));
        // Another controller in the list is another check, run at once.
        auto *combo = dialog->findChild<QComboBox *>(u"jobDialectCombo"_s);
        combo->setCurrentIndex(combo->findData(u"fanuc"_s));
        QVERIFY(waitForCheck(dialog));
        QCOMPARE(dialog->report()->dialect, Dialect::Fanuc);
        QCOMPARE(dialog->report()->findings.size(), 1);
        QCOMPARE(dialog->report()->findings.front().kind, FindingKind::LengthOffsetMismatch);
        QCOMPARE(dialog->report()->findings.front().line, 5);
        // A file that cannot be read says so in the dialog, and nothing is shown as found.
        dialog->check(m_dir.path());
        QVERIFY(QTest::qWaitFor([dialog] { return !dialog->isRunning(); }, 10000));
        QVERIFY(!dialog->report());
        QVERIFY(dialog->findChild<QLabel *>(u"jobSummaryLabel"_s)->text().contains(u"folder"_s));
        QCOMPARE(dialog->findChild<QTableView *>(u"jobFindingsView"_s)->model()->rowCount(), 0);
    }

    void aProgramOfThousandsOfToolsListsTheFirstAndSaysTheRestWereCounted()
    {
        MainWindow window;
        window.setLibrary({ m_dir.filePath(u"library.sqlite"_s) });
        QVERIFY(window.openFile(kExample));
        window.show();
        QByteArray program;
        for (int t = 1; t <= JobReport::kMaxListedTools + 50; ++t)
            program += "M6 T" + QByteArray::number(t) + "\nG1 Z-1 F100\n";
        JobCheckDialog *dialog = window.openJobCheck(write(m_dir, u"many.nc"_s, program));
        QVERIFY(waitForCheck(dialog));
        // What earlier tests chose is remembered: the Carvera, with no floor, here.
        if (auto *floor = dialog->findChild<QCheckBox *>(u"jobFloorCheck"_s); floor->isChecked()) {
            floor->setChecked(false);
            QVERIFY(waitForCheck(dialog));
        }
        if (auto *controller = dialog->findChild<QComboBox *>(u"jobDialectCombo"_s);
            controller->currentData() != u"carvera"_s) {
            controller->setCurrentIndex(controller->findData(u"carvera"_s));
            QVERIFY(waitForCheck(dialog));
        }
        auto *tools = dialog->findChild<QTableView *>(u"jobToolsView"_s)->model();
        QAbstractItemModelTester toolsTester(tools, QAbstractItemModelTester::FailureReportingMode::QtTest);
        // The listed tools, then one row for the rest.
        QCOMPARE(tools->rowCount(), JobReport::kMaxListedTools + 1);
        const int last = JobReport::kMaxListedTools;
        QCOMPARE(tools->index(last - 1, JobToolsModel::NumberColumn).data().toString(), u"T1000"_s);
        QCOMPARE(tools->index(last, JobToolsModel::NumberColumn).data().toString(), u"50 more"_s);
        QCOMPARE(tools->index(last, JobToolsModel::LoadedColumn).data().toString(),
            u"from line 2001, 50 loads: counted, not listed"_s);
        QVERIFY(tools->index(last, JobToolsModel::TloColumn)
                    .data(Qt::ToolTipRole)
                    .toString()
                    .contains(u"The program loads 1050 distinct tools: the first 1000 are listed"_s));
        // The counted tools' findings, one for each kind, say how many tools they stand for.
        auto *findings = dialog->findChild<QTableView *>(u"jobFindingsView"_s)->model();
        QAbstractItemModelTester findingsTester(
            findings, QAbstractItemModelTester::FailureReportingMode::QtTest);
        int summaries = 0;
        for (int row = 0; row < findings->rowCount(); ++row) {
            const QString tool = findings->index(row, JobFindingsModel::ToolColumn).data().toString();
            if (tool != u"50 tools"_s)
                continue;
            ++summaries;
            QCOMPARE(findings->index(row, JobFindingsModel::LineColumn).data().toInt(), 2001);
            QVERIFY(findings->index(row, JobFindingsModel::MessageColumn)
                        .data()
                        .toString()
                        .startsWith(u"50 more tools"_s));
        }
        QCOMPARE(summaries, 2); // not in the table, not in the rack
        const QString summary = dialog->findChild<QLabel *>(u"jobSummaryLabel"_s)->text();
        QVERIFY2(summary.contains(u"tools: 1050"_s)
                && summary.contains(u"Only the first 1000 tools are listed; the other 50 are counted"_s),
            qPrintable(summary));
        QCOMPARE(dialog->report()->errors(), 1050 - 6);
    }

private:
    QTemporaryDir m_dir;
};

QTEST_MAIN(TestJobCheck)
#include "tst_jobcheck.moc"
