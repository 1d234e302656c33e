// SPDX-License-Identifier: GPL-3.0-or-later
// One tool's history in the window: the chart for no, one and many measurements, a failed break test in red,
// the trend and its band, the table, and the CSV export.
#include <algorithm>
#include <cmath>

#include <QAreaSeries>
#include <QChart>
#include <QChartView>
#include <QClipboard>
#include <QFile>
#include <QGuiApplication>
#include <QLabel>
#include <QLineSeries>
#include <QPushButton>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QValueAxis>
#include <QXYSeries>

#include "model/library/historyrecorder.h"
#include "model/modules.h"
#include "ui/common/appearance.h"
#include "ui/history/historydock.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

const QDateTime kStart(QDate(2026, 11, 2), QTime(7, 0), Qt::UTC);

HistoryEvent makeEvent(int tool, int hours, EventKind kind, double tlo, std::optional<bool> failed = {})
{
    HistoryEvent e;
    e.id = HistoryEvent::newId();
    e.machine = u"Carvera"_s;
    e.tool = tool;
    e.at = kStart.addSecs(qint64(hours) * 3600);
    e.kind = kind;
    e.tlo = tlo;
    if (kind == EventKind::BreakTest) {
        e.tolerance = 0.1;
        e.oldTlo = tlo;
        e.newTlo = failed.value_or(false) ? tlo - 0.5 : tlo;
        e.failed = failed;
    }
    return e;
}

QXYSeries *series(QChart *chart, const QString &name)
{
    for (QAbstractSeries *s : chart->series()) {
        if (s->name() == name)
            return qobject_cast<QXYSeries *>(s);
    }
    qFatal("no series named %s", qPrintable(name));
}

// The chart the module drew in the panel, or null.
QChart *chartOf(const HistoryDock &dock)
{
    auto *view = qobject_cast<QChartView *>(dock.chartView());
    return view ? view->chart() : nullptr;
}

} // namespace

class TestHistoryDock : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    HistoryRecorder m_recorder;

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_recorder.setLocation({ m_dir.filePath(u"library.sqlite"_s) }));
        QList<HistoryEvent> events { makeEvent(1, 0, EventKind::Probe, -10.0) }; // T1: one point
        for (int i = 0; i < 6;
             ++i) // T2: a worn tool, a passed and a failed break test, an offset set by hand
            events.append(makeEvent(2, i * 24, EventKind::Probe, -33.388 - i * 0.004));
        events.append(makeEvent(2, 30, EventKind::BreakTest, -33.39, false));
        events.append(makeEvent(2, 130, EventKind::BreakTest, -33.41, true));
        events.append(makeEvent(2, 140, EventKind::ManualSet, -30.488));
        for (int i = 0; i < 10000; ++i) // T3: ten thousand
            events.append(makeEvent(3, i, EventKind::Probe, -20.0 - (i % 97) * 0.001));
        // T4, a face mill touched on four edges twice: the second time one edge 0.08 short.
        for (int i = 0; i < 2; ++i) {
            HistoryEvent e = makeEvent(4, i * 24, EventKind::Probe, -5.0);
            e.touches = { -120.0, -120.02, -120.01, i == 0 ? -120.015 : -120.08 };
            events.append(e);
        }
        QCOMPARE(m_recorder.library()->append(events).value(), 10012);
    }

    // First, before the chart module is loaded by any other test: without it, the panel says what is wrong
    // and what to do, the measurements are still listed, and the chart comes once the module is back.
    void withoutTheChartModuleSaysSoAndStillListsTheMeasurements()
    {
        QTemporaryDir empty;
        setModuleDirectory(empty.path());
        HistoryDock dock(&m_recorder);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        dock.showTool(2, u"Carvera"_s, 0.1);
        auto *problem = dock.findChild<QLabel *>(u"historyChartPlace"_s);
        QVERIFY(problem);
        QVERIFY2(problem->text().contains(u"toffee_historychart.so is missing. Reinstall Toffee"_s),
            qPrintable(problem->text()));
        QVERIFY(problem->isVisible());
        // Readable whole: the place is tall enough for the message's lines at its width.
        QVERIFY(problem->height() >= problem->heightForWidth(problem->width()));
        QVERIFY(!dock.chartView());
        QVERIFY(!dock.findChild<QPushButton *>(u"historyCopyButton"_s)->isEnabled()); // no chart to copy
        QCOMPARE(dock.findChild<QTableView *>(u"historyTable"_s)->model()->rowCount(), 9);
        setModuleDirectory({});
        dock.showTool(1, u"Carvera"_s, 0.1);
        QVERIFY(!dock.findChild<QLabel *>(u"historyChartPlace"_s));
        QVERIFY(dock.findChild<QPushButton *>(u"historyCopyButton"_s)->isEnabled());
        QVERIFY(chartOf(dock));
        QCOMPARE(series(chartOf(dock), u"Probes"_s)->points().size(), 1);
    }

    // A tool touched on each edge: the Spread column, each touch in its tooltip, and every edge's TLO drawn
    // beside the measurement (the highest at the TLO), so that a growing spread is seen.
    void showsEachEdgeAndTheSpread()
    {
        HistoryDock dock(&m_recorder);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        dock.showTool(4, u"Carvera"_s, 0.1);
        auto *model = dock.findChild<QTableView *>(u"historyTable"_s)->model();
        QCOMPARE(model->rowCount(), 2);
        QCOMPARE(model->headerData(8, Qt::Horizontal).toString(), u"Spread"_s);
        QCOMPARE(model->index(0, 8).data().toString(), u"0.080"_s); // newest first
        QCOMPARE(model->index(1, 8).data().toString(), u"0.020"_s);
        QVERIFY2(model->index(0, 8).data(Qt::ToolTipRole).toString().contains(u"-120.080"_s),
            qPrintable(model->index(0, 8).data(Qt::ToolTipRole).toString()));
        const QList<QPointF> edges = series(chartOf(dock), u"Each edge"_s)->points();
        QCOMPARE(edges.size(), 8);
        const auto [low, high] = std::minmax_element(
            edges.cbegin(), edges.cend(), [](const QPointF &a, const QPointF &b) { return a.y() < b.y(); });
        QVERIFY(std::fabs(high->y() - (-5.0)) < 1e-9);
        QVERIFY(std::fabs(low->y() - (-5.08)) < 1e-9);
    }

    void saysWhatToDoWithNoToolAndWithNoMeasurement()
    {
        HistoryDock dock(&m_recorder);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        QCOMPARE(
            dock.findChild<QLabel *>(u"historyTitle"_s)->text(), u"Select one tool to see its history."_s);
        dock.showTool(9, u"Carvera"_s, 0.1);
        QCOMPARE(dock.findChild<QLabel *>(u"historyTitle"_s)->text(), u"T9 on Carvera: 0 measurements"_s);
        QCOMPARE(chartOf(dock)->title(), u"No measurements of T9 yet"_s);
        QVERIFY(series(chartOf(dock), u"Probes"_s)->points().isEmpty());
        QVERIFY(!dock.findChild<QWidget *>(u"historyExportButton"_s)->isEnabled());
        QVERIFY(!dock.grab().isNull());
    }

    void drawsOnePointInARangeAroundIt()
    {
        HistoryDock dock(&m_recorder);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        dock.showTool(1, u"Carvera"_s, 0.1);
        QCOMPARE(series(chartOf(dock), u"Probes"_s)->points().size(), 1);
        auto *axis = qobject_cast<QValueAxis *>(chartOf(dock)->axes(Qt::Vertical).front());
        QVERIFY(axis->min() < -10.0 && axis->max() > -10.0);
        QCOMPARE(dock.findChild<QTableView *>(u"historyTable"_s)->model()->rowCount(), 1);
        QVERIFY(!dock.grab().isNull());
    }

    void marksBreakTestsAndTheTrendWithItsBand()
    {
        HistoryDock dock(&m_recorder);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        dock.resize(900, 500);
        dock.showTool(2, u"Carvera"_s, 0.1);
        QCOMPARE(dock.findChild<QLabel *>(u"historyTitle"_s)->text(), u"T2 on Carvera: 9 measurements"_s);
        QCOMPARE(series(chartOf(dock), u"Probes"_s)->points().size(), 6);
        QCOMPARE(series(chartOf(dock), u"Break test passed"_s)->points().size(), 1);
        QXYSeries *failed = series(chartOf(dock), u"Break test failed"_s);
        QCOMPARE(failed->points().size(), 1);
        QCOMPARE(failed->points().front().y(), -33.91); // drawn at what it measured
        QCOMPARE(failed->color(), alarmColor(dock.palette())); // in red
        QCOMPARE(series(chartOf(dock), u"Set by hand"_s)->points().size(), 1);
        QVERIFY(chartOf(dock)->localizeNumbers()); // "-33,400" in German, like the rest of the window
        QLineSeries *trend = nullptr;
        QAreaSeries *band = nullptr;
        for (QAbstractSeries *s : chartOf(dock)->series()) {
            if (s->name() == u"Wear trend")
                trend = qobject_cast<QLineSeries *>(s);
            if (s->name().startsWith(u"± 0.1"))
                band = qobject_cast<QAreaSeries *>(s);
        }
        QVERIFY(trend && band);
        QCOMPARE(trend->points().size(), 6);
        // The probes wear 0.004 mm a day, exactly on the line: the trend passes through them.
        QVERIFY(std::fabs(trend->points().last().y() - (-33.408)) < 1e-9);
        QVERIFY(
            std::fabs(band->upperSeries()->points().last().y() - trend->points().last().y() - 0.1) < 1e-9);
        // The table, newest first, says which test found the tool broken.
        auto *model = dock.findChild<QTableView *>(u"historyTable"_s)->model();
        QCOMPARE(model->rowCount(), 9);
        QCOMPARE(model->index(0, 1).data().toString(), u"set by hand"_s);
        QCOMPARE(model->index(1, 9).data().toString(), u"BROKEN?"_s);
        QVERIFY(model->index(1, 8).data().toString().isEmpty()); // one touch: no spread
        QVERIFY(!dock.grab().isNull());
    }

    void drawsTenThousandPoints()
    {
        HistoryDock dock(&m_recorder);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        dock.resize(900, 500);
        dock.showTool(3, u"Carvera"_s, 0.1);
        QCOMPARE(series(chartOf(dock), u"Probes"_s)->points().size(), 10000);
        const QPixmap drawn = dock.grab();
        QVERIFY(!drawn.isNull());
        QCOMPARE(drawn.size(), QSize(900, 500));
    }

    void exportsTheMeasurementsAsCsv()
    {
        HistoryDock dock(&m_recorder);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        dock.showTool(2, u"Carvera"_s, 0.1);
        const QString path = m_dir.filePath(u"T2.csv"_s);
        QVERIFY(dock.exportCsv(path));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().split('\n');
        QCOMPARE(lines.front(),
            "id,machine,tool,measured_at,kind,tlo,reference_mz,current_mz,tolerance,old_tlo,new_tlo,failed,"
            "touches,"
            "spread");
        QCOMPARE(lines.size(), 11); // the header, nine events, and the last line's end
        QVERIFY(lines.at(8).contains(",break_test,-33.41,,,0.1,-33.41,-33.91,1,,"));
        // A folder where the file should be: the export fails with the system's reason, nothing written.
        QVERIFY(!dock.exportCsv(m_dir.path()));
    }

    void copiesTheChartAsAnImage()
    {
        HistoryDock dock(&m_recorder);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        dock.resize(700, 400);
        dock.showTool(2, u"Carvera"_s, 0.1);
        QGuiApplication::clipboard()->clear();
        dock.copyChart();
        const QImage copied = QGuiApplication::clipboard()->image();
        QVERIFY(!copied.isNull());
        QVERIFY(copied.width() > 300 && copied.height() > 100);
    }

    // A panel behind another tab builds no chart; it draws the tool when it is seen.
    void drawsOnlyWhenSeen()
    {
        HistoryDock dock(&m_recorder);
        dock.showTool(2, u"Carvera"_s, 0.1);
        QVERIFY(dock.events().isEmpty()); // hidden: nothing read, nothing built
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        QTRY_COMPARE(dock.events().size(), 9);
        QCOMPARE(series(chartOf(dock), u"Probes"_s)->points().size(), 6);
    }

    void followsWhatIsRecordedForItsTool()
    {
        HistoryDock dock(&m_recorder);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        dock.showTool(1, u"Carvera"_s, 0.1);
        m_recorder.record(makeEvent(1, 5, EventKind::Probe, -10.002));
        QCOMPARE(series(chartOf(dock), u"Probes"_s)->points().size(), 2);
        m_recorder.record(makeEvent(7, 5, EventKind::Probe, -1.0)); // another tool's: no reload needed
        QCOMPARE(dock.events().size(), 2);
    }
};

QTEST_MAIN(TestHistoryDock)
#include "tst_historydock.moc"
