// SPDX-License-Identifier: GPL-3.0-or-later
// The user's guide's pictures, taken by the suite: one operator's tour of the window (offscreen, 1280×720) on
// the built-in emulator, in the guide's order: the table connected and probed, the History panel, a job
// checked and prepared, tools imported from a CAM library, the rack measured. At each step it asserts what
// the picture is meant to show, so that a picture never shows what is no longer true; with TOFFEE_SCREENSHOTS
// set (`make screenshots`), each is saved under the name docs/GUIDE.md shows it by.
#include <QApplication>
#include <QChartView>
#include <QDockWidget>
#include <QGraphicsTextItem>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QTableView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>

#include "model/document/tooldocument.h"
#include "model/document/tooltablemodel.h"
#include "model/library/historyrecorder.h"
#include "model/library/library.h"
#include "tests/support/camfiles.h"
#include "tests/support/messageboxes.h"
#include "tests/support/station.h"
#include "tests/support/windowsteps.h"
#include "ui/history/historydock.h"
#include "ui/job/jobcheckdialog.h"
#include "ui/job/jobpreparedialog.h"
#include "ui/rack/rackpanel.h"
#include "ui/shell/mainwindow.h"
#include "ui/table/importpreviewdialog.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

const QString kExample = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

// A short job for the Carvera (whose TLO always applies: no G43): T2, then T3, which was never measured.
const QByteArray kProgram = "G21 G90\nM6 T2\nS12000 M3\nG0 X10 Y10 Z5\nG1 Z-1 F600\nG1 X40 F800\n"
                            "M6 T3\nG0 X20 Y20 Z5\nG1 Z-0.5 F400\nG1 Y40 F800\nM5\nM30\n";

} // namespace

class TestGuideTour : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        isolateWindowTest(u"tst_guidetour"_s);
        startFresh(); // a first start's window, whatever an earlier run remembered
    }

    void aTourOfTheWindowInTheGuidesOrder()
    {
        QTemporaryDir dir;
        Station s;
        s.window.resize(1280, 720);
        QVERIFY(s.window.openFile(kExample));
        s.connect();

        // First start, connected and probed: the tool in the spindle has a TLO the machine measured.
        const int tool = s.window.connection()->activeTool().value_or(-1);
        QVERIFY(tool >= 1);
        s.probe();
        QVERIFY(waitIdle(s));
        const Tool *probed = s.table().find(tool);
        QVERIFY(probed && probed->measuredTlo && probed->tloSource == TloSource::Probe);
        QVERIFY2(!s.cell(tool, ToolTableModel::MeasuredTloColumn).contains(u"by hand"_s),
            qPrintable(s.cell(tool, ToolTableModel::MeasuredTloColumn)));
        screenshot(s.window, u"window-light.png"_s);

        // The History panel, on the tool just probed: its probe is there.
        auto *history = s.window.historyDock();
        history->show();
        history->raise();
        auto *table = s.find<QTableView>(u"toolTable"_s);
        table->selectRow(s.window.document()->model()->rowOfTool(tool));
        QTRY_VERIFY(s.window.history()->library()->history({}).value().size() >= 1);
        QTRY_VERIFY(history->isVisible());
        // Its chart's TLO axis is read, not cut to "...": at 1280×720 the panel is short, and Qt Charts cuts
        // a label that does not fit between its neighbours.
        QChartView *chart = nullptr;
        QTRY_VERIFY((chart = history->findChild<QChartView *>()) && chart->isVisible());
        QStringList labels;
        QTRY_VERIFY2(
            [&] {
                labels.clear();
                for (QGraphicsItem *item : chart->scene()->items()) {
                    if (auto *text = dynamic_cast<QGraphicsTextItem *>(item); text && text->isVisible())
                        labels << text->toPlainText();
                }
                return labels.filter(QRegularExpression(u"^4[23]\\.\\d{3}$"_s)).size() >= 2;
            }(),
            qPrintable(labels.join(u" | "_s)));
        QVERIFY2(labels.filter(u"..."_s).isEmpty(), qPrintable(labels.join(u" | "_s)));
        screenshot(s.window, u"history.png"_s);

        // A job checked against the table: its tools in the order of use, findings by line.
        const QString program = dir.filePath(u"pocket.nc"_s);
        QVERIFY(writeFile(program, kProgram));
        JobCheckDialog *check = s.window.openJobCheck(program);
        QVERIFY(check);
        QVERIFY(QTest::qWaitFor([check] { return !check->isRunning() && check->report(); }, 60000));
        QCOMPARE(check->report()->tools.size(), 2);
        QCOMPARE(check->report()->errors(), 0);
        screenshot(*check, u"jobcheck.png"_s);

        // Prepared for the machine: the original beside what Toffee adds.
        bool prepared = false;
        inNextDialog<JobPrepareDialog>([&prepared](JobPrepareDialog *prep) {
            const auto close = qScopeGuard([prep] { prep->close(); });
            QVERIFY(QTest::qWaitFor([prep] { return !prep->isRunning() && prep->summary(); }, 30000));
            QVERIFY(prep->findChild<QTableWidget *>(u"preparePreview"_s)->rowCount() > 0);
            prep->resize(1100, 640);
            screenshot(*prep, u"jobprepare.png"_s);
            prepared = true;
        });
        check->findChild<QPushButton *>(u"jobPrepareButton"_s)->click();
        QTRY_VERIFY(prepared);
        check->close();

        // Tools from a CAM library: each one new or changed, shown before anything is taken.
        const QString cam = dir.filePath(u"shop.hsmlib"_s);
        QVERIFY(writeFile(cam,
            hsmLibrary(hsmTool(2, uR"(diameter="8" flute-length="22" number-of-flutes="3")"_s)
                + hsmTool(12, uR"(diameter="10" flute-length="30" number-of-flutes="4")"_s, u"millimeters"_s,
                    u"10 mm roughing"_s))));
        int rows = 0;
        inNextDialog<ImportPreviewDialog>([&rows](ImportPreviewDialog *preview) {
            rows = preview->findChild<QTreeWidget *>(u"importToolList"_s)->topLevelItemCount();
            screenshot(*preview, u"importpreview.png"_s);
            preview->reject();
        });
        QVERIFY(!s.window.importFile(cam)); // cancelled: nothing taken
        QCOMPARE(rows, 2);
        QVERIFY(!s.table().contains(12));

        // The rack, measured: every pocket's tool with its new TLO.
        s.find<QDockWidget>(u"rackDock"_s)->raise();
        QString question;
        answerNextBox(QMessageBox::Yes, &question);
        QTest::mouseClick(s.find<QPushButton>(u"rackMeasureButton"_s), Qt::LeftButton);
        QVERIFY(QTest::qWaitFor([&s] { return s.idle() && !QApplication::activeModalWidget(); }, 120000));
        auto *rack = s.find<QTableWidget>(u"rackTable"_s);
        QVERIFY(rack->rowCount() >= 6);
        for (int row = 0; row < rack->rowCount(); ++row)
            QCOMPARE(rack->item(row, RackPanel::MeasuredColumn)->text(), u"just now"_s);
        screenshot(s.window, u"rack-measured.png"_s);
    }
};

QTEST_MAIN(TestGuideTour)
#include "tst_guidetour.moc"
