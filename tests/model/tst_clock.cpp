// SPDX-License-Identifier: GPL-3.0-or-later
// The product's one clock (model/clock.h): a test sets it and every reading follows; a time from outside
// that lies beyond it by more than the skew is in the future; an age is never counted from a future time.
#include <QTest>

#include "model/clock.h"
#include "model/timetext.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestClock : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void cleanup() { Clock::setForTests({}); }

    void aSetClockRunsOnFromWhereItWasSet()
    {
        const QDateTime at(QDate(2031, 2, 3), QTime(4, 5, 6), Qt::UTC);
        Clock::setForTests(at);
        const QDateTime first = Clock::now();
        QVERIFY(first >= at && first < at.addSecs(5));
        QCOMPARE(first.timeSpec(), Qt::UTC);
        QTest::qWait(20);
        QVERIFY(Clock::now() > first);
    }

    void aFrozenClockStays()
    {
        const QDateTime at(QDate(2039, 3, 14), QTime(9, 26, 53), Qt::UTC);
        Clock::setForTests(at, Clock::Run::Frozen);
        QTest::qWait(20);
        QCOMPARE(Clock::now(), at);
    }

    void anInvalidTimeGivesTheRealClockBack()
    {
        Clock::setForTests(QDateTime(QDate(2000, 1, 1), QTime(0, 0), Qt::UTC));
        QCOMPARE(Clock::now().date().year(), 2000);
        Clock::setForTests({});
        QVERIFY(qAbs(Clock::now().secsTo(QDateTime::currentDateTimeUtc())) < 5);
    }

    void aTimeBeyondTheSkewIsInTheFuture_data()
    {
        QTest::addColumn<qint64>("secondsAhead");
        QTest::addColumn<bool>("inFuture");
        QTest::newRow("an hour ago") << qint64(-3600) << false;
        QTest::newRow("now") << qint64(0) << false;
        QTest::newRow("another station's clock, 4 min ahead") << qint64(240) << false;
        QTest::newRow("just past the skew") << Clock::kMaxSkewSeconds + 1 << true;
        QTest::newRow("in 2100") << qint64(74) * 365 * 24 * 3600 << true;
    }

    void aTimeBeyondTheSkewIsInTheFuture()
    {
        QFETCH(qint64, secondsAhead);
        QFETCH(bool, inFuture);
        const QDateTime now(QDate(2026, 11, 21), QTime(9, 0), Qt::UTC);
        Clock::setForTests(now, Clock::Run::Frozen);
        QCOMPARE(Clock::isInFuture(now.addSecs(secondsAhead)), inFuture);
        QCOMPARE(Clock::isInFuture(QDateTime()), false); // no time is not a future one
    }

    void theAgeOfAMeasurementFollowsTheClock()
    {
        const QDateTime measured(QDate(2026, 11, 20), QTime(8, 15), Qt::UTC);
        Clock::setForTests(measured.addSecs(9 * 24 * 3600), Clock::Run::Frozen);
        QCOMPARE(ageText(measured), u"9 days ago"_s);
        Clock::setForTests(measured.addSecs(12 * 60), Clock::Run::Frozen);
        QCOMPARE(ageText(measured), u"12 min ago"_s);
        // Not "just now" for a time beyond the clock: it is said as what it is.
        QCOMPARE(ageText(QDateTime(QDate(2100, 1, 1), QTime(0, 0), Qt::UTC)),
            u"dated in the future (2100-01-01 00:00 UTC)"_s);
        QCOMPARE(ageText(measured.addSecs(12 * 60 + 120)), u"just now"_s); // two minutes ahead: the skew
    }
};

QTEST_GUILESS_MAIN(TestClock)
#include "tst_clock.moc"
