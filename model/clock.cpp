// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/clock.h"

#include <atomic>

#include <QElapsedTimer>
#include <QMutex>

namespace Toffee::Clock {

namespace {

struct TestClock
{
    QMutex mutex;
    QDateTime at; // invalid: the real clock
    QElapsedTimer since;
    Run run = Run::Running;
};

TestClock &testClock()
{
    static TestClock clock;
    return clock;
}

// Read without the lock on the product's path: set only by tests.
std::atomic_bool s_set = false;

// A test that runs toffee-cli or the window as a program sets the child's clock through its environment:
// TOFFEE_TEST_CLOCK=2026-11-21T09:00:00Z, read once, running on from the program's start.
struct EnvironmentClock
{
    QDateTime at;
    QElapsedTimer since;
};

const EnvironmentClock &environmentClock()
{
    static const EnvironmentClock clock = [] {
        EnvironmentClock c;
        const QString text = qEnvironmentVariable("TOFFEE_TEST_CLOCK");
        if (!text.isEmpty())
            c.at = QDateTime::fromString(text, Qt::ISODateWithMs).toUTC();
        c.since.start();
        return c;
    }();
    return clock;
}

QDateTime realNow()
{
    const EnvironmentClock &env = environmentClock();
    return env.at.isValid() ? env.at.addMSecs(env.since.elapsed()) : QDateTime::currentDateTimeUtc();
}

} // namespace

QDateTime now()
{
    if (!s_set.load(std::memory_order_acquire))
        return realNow();
    TestClock &clock = testClock();
    QMutexLocker lock(&clock.mutex);
    if (!clock.at.isValid())
        return realNow();
    return clock.run == Run::Frozen ? clock.at : clock.at.addMSecs(clock.since.elapsed());
}

bool isInFuture(const QDateTime &at, const QDateTime &now)
{
    return at.isValid() && now.isValid() && now.secsTo(at) > kMaxSkewSeconds;
}

bool isInFuture(const QDateTime &at)
{
    return isInFuture(at, now());
}

void setForTests(const QDateTime &at, Run run)
{
    TestClock &clock = testClock();
    QMutexLocker lock(&clock.mutex);
    clock.at = at.isValid() ? at.toUTC() : QDateTime();
    clock.run = run;
    clock.since.start();
    s_set.store(clock.at.isValid(), std::memory_order_release);
}

} // namespace Toffee::Clock
