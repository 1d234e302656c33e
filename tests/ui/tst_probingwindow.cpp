// SPDX-License-Identifier: GPL-3.0-or-later
// An operator's story through the real window (offscreen) on the built-in emulator (the community firmware's
// M491 R<n> and X, as the firmware runs them): T1 becomes a face mill measured 20 mm off the setter's centre
// on its four edges, typed into its Probing cell; the probe's question says so, the machine is sent M491 R4
// X20, the table takes the longest edge's TLO (the firmware kept the shortest's: set right), the spread
// beyond the tool's limit is said, and the History panel shows it with each touch. Undo takes the settings
// back.
#include <QApplication>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QTableView>
#include <QTest>

#include "model/document/tooltablemodel.h"
#include "model/probing.h"
#include "tests/support/messageboxes.h"
#include "tests/support/station.h"
#include "tests/support/windowsteps.h"
#include "ui/history/historydock.h"
#include "ui/table/tooltablepanel.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

class TestProbingWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { isolateWindowTest(u"tst_probingwindow"_s); }
    void init() { startFresh(); }

    void aFaceMillIsProbedOnFourEdgesOffCentre()
    {
        Station s;
        QVERIFY(s.window.openFile(kExampleTable));
        s.connect();
        s.machine()->setRepeatability(0.01); // its edges touch 0.01 apart: a spread of 0.02
        auto *view = s.window.findChild<QTableView *>(u"toolTable"_s);
        s.window.findChild<ToolTablePanel *>()->selectTool(1);
        QApplication::processEvents();

        // Typed into T1's Probing cell from the keyboard.
        view->setCurrentIndex(
            view->model()->index(view->currentIndex().row(), ToolTableModel::ProbingColumn));
        view->setFocus();
        QTest::keyClick(view, Qt::Key_F2);
        QWidget *editor = view->indexWidget(view->currentIndex());
        QVERIFY(editor);
        QTest::keyClicks(editor, u"X 20, 4 edges, spread 0.01"_s);
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE(s.table().find(1)->flutes, std::optional(4));
        QCOMPARE(s.table().find(1)->probing.offsetX, 20.0);
        QCOMPARE(s.cell(1, ToolTableModel::ProbingColumn), u"X 20, 4 edges, spread 0.01"_s);
        // A setting that is none is refused with how to type one, and the cell keeps what it had.
        auto *model = s.window.document()->model();
        QString refusal;
        answerNextBox(QMessageBox::Ok, &refusal);
        QVERIFY(
            !model->setData(model->index(model->rowOfTool(1), ToolTableModel::ProbingColumn), u"X 500"_s));
        QVERIFY2(refusal.contains(u"from the setter's centre"_s), qPrintable(refusal));
        QCOMPARE(s.cell(1, ToolTableModel::ProbingColumn), u"X 20, 4 edges, spread 0.01"_s);

        // The probe's question says how T1 is measured; the machine is sent the firmware's own M491.
        const QString question = s.probe();
        QVERIFY2(
            question.contains(u"4 touches, X 20 Y 0 mm from the setter's centre"_s), qPrintable(question));
        QVERIFY2(s.sent.contains("M491 R4 X20"), s.sent.join(" / ").constData());
        const Tool *t1 = s.table().find(1);
        QVERIFY(t1->measuredTlo);
        // The longest edge's TLO is in force on the machine and in the table.
        QCOMPARE(*t1->measuredTlo, s.machine()->tlo());
        const QString said = s.find<QLabel>(u"probeResultLabel"_s)->text();
        QVERIFY2(said.contains(u"T1's edges differ by 0.020 mm"_s) && said.contains(u"chipped edge"_s),
            qPrintable(said));
        QVERIFY2(said.contains(u"Toffee set the longest edge's"_s), qPrintable(said));

        // The History panel: the probe with its spread, each touch in its tooltip.
        s.window.findChild<ToolTablePanel *>()->selectTool(1);
        s.window.historyDock()->show(); // View ▸ History
        s.window.historyDock()->raise();
        auto *history = s.window.historyDock()->findChild<QTableView *>(u"historyTable"_s);
        QTRY_COMPARE_WITH_TIMEOUT(history->model()->rowCount(), 1, 10000);
        int spreadColumn = -1;
        for (int c = 0; c < history->model()->columnCount(); ++c) {
            if (history->model()->headerData(c, Qt::Horizontal).toString() == u"Spread"_s)
                spreadColumn = c;
        }
        QVERIFY(spreadColumn >= 0);
        const QModelIndex spread = history->model()->index(0, spreadColumn);
        QVERIFY2(spread.data().toString().startsWith(u"0.020"_s), qPrintable(spread.data().toString()));
        QVERIFY2(spread.data(Qt::ToolTipRole).toString().startsWith(u"4 touches"_s),
            qPrintable(spread.data(Qt::ToolTipRole).toString()));
        history->scrollTo(spread); // the Spread column in sight, for the picture
        QTest::qWait(100); // the panels laid out for the result's words
        screenshot(s.window, u"probing-face-mill.png"_s);

        // Undo takes the settings back: the next probe is one touch at the centre.
        s.trigger(u"actionUndo"_s); // the measurement
        s.trigger(u"actionUndo"_s); // the settings
        QTRY_VERIFY(s.table().find(1)->probing.isDefault());
        s.sent.clear();
        s.probe();
        QVERIFY2(s.sent.contains("M491"), s.sent.join(" / ").constData());
        QCOMPARE(history->model()->rowCount(), 2);
        QVERIFY(history->model()->index(0, spreadColumn).data().toString().isEmpty());
    }
};

QTEST_MAIN(TestProbingWindow)
#include "tst_probingwindow.moc"
