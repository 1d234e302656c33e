// SPDX-License-Identifier: GPL-3.0-or-later
// Start-up's order (issue 16): the frame is shown before it is built, and its first picture is the whole
// window.
#include <QApplication>
#include <QDockWidget>
#include <QMenuBar>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableView>
#include <QTest>

#include "ui/history/historydock.h"
#include "ui/machine/consoledock.h"
#include "ui/machine/machinedock.h"
#include "ui/shell/mainwindow.h"
#include "ui/table/tooltablepanel.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

// What the window held when it was painted for the first time.
class FirstPaint final : public QObject
{
public:
    explicit FirstPaint(MainWindow *window)
        : m_window(window)
    {
        window->installEventFilter(this);
    }

    bool painted = false;
    bool tableShown = false;
    bool machineDockShown = false;
    bool consoleShown = false;
    int menus = 0;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (watched == m_window && event->type() == QEvent::Paint && !painted) {
            painted = true;
            tableShown = m_window->toolTablePanel() && m_window->toolTablePanel()->isVisible();
            machineDockShown = m_window->machineDock() && m_window->machineDock()->isVisible();
            consoleShown = m_window->consoleDock() && m_window->consoleDock()->isVisible();
            menus = int(m_window->menuBar()->actions().size());
        }
        return false;
    }

private:
    MainWindow *m_window;
};

} // namespace

class TestMainWindowStartup : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_mainwindowstartup"_s);
    }

    void theFrameComesFirstAndHoldsNothingYet()
    {
        MainWindow window(MainWindow::Build::AfterShow);
        QVERIFY(!window.document());
        QVERIFY(!window.toolTablePanel());
        QVERIFY(!window.machineDock());
        // Its size is known before it is built, and building it changes nothing: no jump on the screen.
        const QSize framed = window.size();
        window.build();
        QCOMPARE(window.size(), framed);
        QCOMPARE(framed, MainWindow().size());
    }

    void theFirstPictureIsTheWholeWindow()
    {
        MainWindow window(MainWindow::Build::AfterShow);
        FirstPaint first(&window);
        window.showThenBuild();
        QVERIFY(window.isVisible());
        QVERIFY(window.document());
        QTRY_VERIFY(first.painted);
        QVERIFY(first.tableShown);
        QVERIFY(first.machineDockShown);
        QVERIFY(first.consoleShown);
        QVERIFY(first.menus >= 4);
    }

    // The History panel starts behind the console's tab: its chart (and the module with Qt Charts) waits
    // until the panel is brought forward.
    void theHistoryChartWaitsUntilItsTabIsSeen()
    {
        MainWindow window(MainWindow::Build::AfterShow);
        window.showThenBuild();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTest::qWait(200);
        QVERIFY(window.historyDock()->isVisible()); // Qt's word for it, although it is behind the console
        QVERIFY(!window.historyDock()->chartView());
        const int tableHeight = window.toolTablePanel()->height();
        window.historyDock()->raise();
        QTRY_VERIFY(window.historyDock()->chartView());
        QVERIFY(window.historyDock()->chartView()->isVisible());
        // Its place was kept for it: nothing in the window moves when it comes.
        QTest::qWait(200);
        QCOMPARE(window.toolTablePanel()->height(), tableHeight);
    }

    // A layout saved on quitting comes back on the next start as it does for a window built whole: the docks
    // are laid out once the panels built into the shown frame are shown.
    void aSavedLayoutComesBackAsSaved()
    {
        {
            MainWindow first;
            first.show();
            QVERIFY(QTest::qWaitForWindowExposed(&first));
            first.resizeDocks({ first.consoleDock() }, { 300 }, Qt::Vertical);
            QTest::qWait(50);
            QVERIFY(first.close()); // saves the window's layout
        }
        MainWindow whole;
        whole.show();
        QVERIFY(QTest::qWaitForWindowExposed(&whole));
        QTest::qWait(100);
        MainWindow framed(MainWindow::Build::AfterShow);
        framed.showThenBuild();
        QVERIFY(QTest::qWaitForWindowExposed(&framed));
        QTest::qWait(100);
        QCOMPARE(framed.toolTablePanel()->height(), whole.toolTablePanel()->height());
        QCOMPARE(framed.consoleDock()->height(), whole.consoleDock()->height());
    }

    void buildingTwiceBuildsOnce()
    {
        MainWindow window(MainWindow::Build::AfterShow);
        window.build();
        ToolTablePanel *panel = window.toolTablePanel();
        window.build();
        QCOMPARE(window.toolTablePanel(), panel);
        QCOMPARE(window.findChildren<ToolTablePanel *>().size(), 1);
    }
};

QTEST_MAIN(TestMainWindowStartup)
#include "tst_mainwindowstartup.moc"
