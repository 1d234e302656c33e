// SPDX-License-Identifier: GPL-3.0-or-later
// A tool's wear trend, on rows computed by hand, and the warning a probe off the trend gets.
#include <limits>

#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTest>

#include "model/clock.h"
#include "model/library/library.h"
#include "model/library/weartrend.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

const QDateTime kStart(QDate(2026, 11, 2), QTime(7, 0), Qt::UTC);

HistoryEvent probe(int hours, double tlo, EventKind kind = EventKind::Probe)
{
    HistoryEvent e;
    e.id = HistoryEvent::newId();
    e.machine = u"Carvera"_s;
    e.tool = 3;
    e.at = kStart.addSecs(hours * 3600);
    e.kind = kind;
    e.tlo = tlo;
    return e;
}

ToolUse use(int hours, double cuttingSeconds)
{
    return { HistoryEvent::newId(), u"Carvera"_s, 3, kStart.addSecs(hours * 3600), u"job.nc"_s,
        cuttingSeconds, 1000.0 };
}

} // namespace

class TestWearTrend : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void fitsAStraightLineExactly()
    {
        const auto t
            = WearTrend::fit({ { 0, -10.0 }, { 3600, -10.01 }, { 7200, -10.02 }, { 10800, -10.03 } });
        QVERIFY(t);
        QCOMPARE(t->points, 4);
        QVERIFY(std::fabs(t->slope * 3600 + 0.01) < 1e-12); // -0.01 mm an hour
        QVERIFY(std::fabs(t->intercept + 10.0) < 1e-9);
        QVERIFY(t->spread < 1e-9);
    }

    void fitsNoisyProbesAsComputedByHand()
    {
        // By hand: mean x 5400, mean TLO -10.015, Sxy -172.8, Sxx 64,800,000: slope -2.6667e-6 mm/s
        // (-0.0096 mm an hour), intercept -10.0006; residuals 0.0006, -0.0018, 0.0018, -0.0006: SS 7.2e-6
        // over 2 degrees of freedom, spread sqrt(3.6e-6) = 0.0018974.
        const auto t
            = WearTrend::fit({ { 0, -10.0 }, { 3600, -10.012 }, { 7200, -10.018 }, { 10800, -10.03 } });
        QVERIFY(t);
        QVERIFY(std::fabs(t->slope * 3600 + 0.0096) < 1e-9);
        QVERIFY(std::fabs(t->intercept + 10.0006) < 1e-9);
        QVERIFY(std::fabs(t->spread - 0.0018974) < 1e-6);
        QVERIFY(std::fabs(t->predict(14400) + 10.039) < 1e-9);
    }

    void fitsNothingToNoPointAndALevelLineToOne()
    {
        QVERIFY(!WearTrend::fit({}));
        const auto one = WearTrend::fit({ { 500, -7.5 } });
        QCOMPARE(one->slope, 0.0);
        QCOMPARE(one->predict(99999), -7.5);
        QCOMPARE(one->spread, 0.0);
    }

    // Values no machine measures (rows another program wrote): no trend, no "nan mm longer".
    void fitsNoTrendToValuesThatOverflowAndWarnsOfNoNumberThatIsNot()
    {
        QVERIFY(!WearTrend::fit({ { 0, 1e308 }, { 3600, 1e308 }, { 7200, -1e308 } }));
        const auto trend = WearTrend::fit({ { 0, -10.0 }, { 3600, -10.01 } });
        QVERIFY(trend);
        QVERIFY(!trend->check(3, 7200, std::numeric_limits<double>::quiet_NaN(), 0.1));
        QVERIFY(!trend->check(3, std::numeric_limits<double>::infinity(), -10.0, 0.1));
    }

    void warnsWithNumbersWhenAProbeIsOffTheTrend()
    {
        const auto t
            = WearTrend::fit({ { 0, -10.0 }, { 3600, -10.012 }, { 7200, -10.018 }, { 10800, -10.03 } });
        const auto shorter = t->check(3, 14400, -10.22, 0.05);
        QVERIFY(shorter);
        QCOMPARE(*shorter, u"T3 measured 0.181 mm shorter than its trend predicts (±0.05): check the tip."_s);
        QVERIFY(t->check(3, 14400, -10.5, 0.05)->contains(u"0.461 mm shorter"_s));
        QVERIFY(t->check(3, 14400, -9.9, 0.05)->contains(u"longer than its trend"_s));
        QVERIFY(!t->check(3, 14400, -10.05, 0.05)); // 0.011 off: within the tolerance
    }

    void takesCuttingTimeWhenItIsRecordedAndWallTimeWhenNot()
    {
        const QList<HistoryEvent> events { probe(0, -10.0), probe(24, -10.01, EventKind::BreakTest),
            probe(48, -10.02) };
        bool cutting = true;
        QList<TrendPoint> wall = WearTrend::pointsOf(events, {}, &cutting);
        QVERIFY(!cutting);
        QCOMPARE(wall.size(), 2); // probes only: a break test is no measurement of the trend
        QCOMPARE(wall.at(1).x, 48 * 3600.0);
        const QList<ToolUse> uses { use(10, 1200), use(30, 600), use(60, 999) };
        QList<TrendPoint> cut = WearTrend::pointsOf(events, uses, &cutting);
        QVERIFY(cutting);
        QCOMPARE(cut.at(0).x, 0.0);
        QCOMPARE(cut.at(1).x, 1800.0); // what was cut before the probe at 48 h, not after
    }

    void aNewCutterStartsTheTrendAndTheCuttingTimeAgain()
    {
        HistoryEvent ended = probe(30, -10.0);
        ended.kind = EventKind::NewCutter;
        ended.tlo.reset();
        ended.oldTlo = -10.02;
        const QList<HistoryEvent> events { probe(0, -10.0), probe(24, -10.02), ended, probe(40, -25.5),
            probe(50, -25.51) };
        const QList<ToolUse> uses { use(10, 1200), use(35, 600), use(45, 300) };
        bool cutting = false;
        const QList<TrendPoint> points = WearTrend::pointsOf(events, uses, &cutting);
        // Only the new cutter's probes, and only what it cut: the old cutter's 1200 s are not its wear.
        QVERIFY(cutting);
        QCOMPARE(points.size(), 2);
        QCOMPARE(points.at(0).tlo, -25.5);
        QCOMPARE(points.at(0).x, 600.0);
        QCOMPARE(points.at(1).x, 900.0);
        // A new cutter's first probe, 15 mm away from the old one's, is no warning of a broken tip.
        QTemporaryDir dir;
        auto library = Library::open({ dir.filePath(u"l.sqlite"_s) });
        QVERIFY(library.value()->append({ probe(0, -10.0), probe(24, -10.02), ended }));
        const HistoryEvent first = probe(40, -25.5);
        QVERIFY(library.value()->append({ first }));
        QVERIFY(!checkProbeAgainstTrend(*library.value(), first, 0.05));
    }

    void checksANewProbeAgainstTheLibrarysHistory()
    {
        QTemporaryDir dir;
        auto library = Library::open({ dir.filePath(u"l.sqlite"_s) });
        QVERIFY(library);
        QList<HistoryEvent> before;
        const double tlos[] = { -10.0, -10.012, -10.018, -10.03 };
        QList<ToolUse> uses;
        for (int i = 0; i < 4; ++i) {
            before.append(probe(i * 10, tlos[i]));
            uses.append(use(i * 10 + 5, 3600)); // an hour of cutting between probes
        }
        QVERIFY(library.value()->append(before));
        QVERIFY(library.value()->appendUse(uses));
        HistoryEvent fine = probe(45, -10.04); // 0.001 off the trend's -10.039
        QVERIFY(!checkProbeAgainstTrend(*library.value(), fine, 0.05));
        HistoryEvent broken = probe(45, -10.22);
        QVERIFY(library.value()->append(
            { broken })); // recorded first, as the window does: it is not its own trend
        const auto warning = checkProbeAgainstTrend(*library.value(), broken, 0.05);
        QVERIFY(warning);
        QCOMPARE(*warning, u"T3 measured 0.181 mm shorter than its trend predicts (±0.05): check the tip."_s);
        HistoryEvent other = broken;
        other.tool = 4; // no history: nothing to compare with
        QVERIFY(!checkProbeAgainstTrend(*library.value(), other, 0.05));
    }

    // One range: a TLO beyond any tool never reaches the history (refused with the whole batch, nothing of
    // it written), and one an older Toffee wrote there is no point of the trend: a normal probe after it is
    // not "54423.558 mm shorter than its trend predicts".
    void aTloBeyondAnyToolNeitherEntersTheHistoryNorBendsTheTrend()
    {
        QTemporaryDir dir;
        auto library = Library::open({ dir.filePath(u"l.sqlite"_s) });
        QVERIFY(library);
        const auto refused = library.value()->append({ probe(0, -10.0), probe(10, 50000.0) });
        QVERIFY(!refused);
        QVERIFY2(refused.error().message.contains(u"holds a TLO of 50000.000 mm, beyond any tool"_s),
            qPrintable(refused.error().message));
        QVERIFY(library.value()->history({}).value().isEmpty());
        HistoryEvent far = probe(10, -10.0);
        far.referenceMz = 1e9;
        QVERIFY(!library.value()->append({ far }));

        const QList<HistoryEvent> written { probe(0, -10.0), probe(10, 50000.0), probe(20, -10.01) };
        const QList<TrendPoint> points = WearTrend::pointsOf(written, {});
        QCOMPARE(points.size(), 2);
        const auto trend = WearTrend::fit(points);
        QVERIFY(trend);
        QVERIFY(!trend->check(3, points.last().x + 36000.0, -10.02, 0.05));
    }

    // A new cutter dated in the future (a station's clock set to 2100) ends nothing: the trend and the
    // cutting time go on from the cutter before it.
    void aNewCutterFromTheFutureEndsNothing()
    {
        Clock::setForTests(kStart.addDays(30));
        const auto real = qScopeGuard([] { Clock::setForTests({}); });
        HistoryEvent future = probe(0, -10.0);
        future.at = QDateTime(QDate(2100, 1, 1), QTime(0, 0), Qt::UTC);
        future.kind = EventKind::NewCutter;
        future.tlo.reset();
        const QList<HistoryEvent> events { probe(0, -10.0), future, probe(20, -10.01) };
        QVERIFY(!cutterSince(events).isValid());
        bool cutting = false;
        const QList<TrendPoint> points = WearTrend::pointsOf(events, { use(10, 600) }, &cutting);
        QCOMPARE(points.size(), 2);
        QVERIFY(cutting);
    }
};

QTEST_GUILESS_MAIN(TestWearTrend)
#include "tst_weartrend.moc"
