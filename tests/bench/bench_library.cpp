// SPDX-License-Identifier: GPL-3.0-or-later
// The history library on an SQLite file: events recorded per second (batched, as a recorder writes what
// waited, and one at a time, as each probe is written), and one tool's history read from a library of a
// million events.
//   toffee-bench-library [EVENTS]   (default 1,000,000 in the large library)
#include <algorithm>
#include <cstdio>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>

#include "model/library/library.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

QList<HistoryEvent> events(int count, int tools, qint64 firstSecond)
{
    const QDateTime start(QDate(2026, 1, 1), QTime(0, 0), Qt::UTC);
    QList<HistoryEvent> out;
    out.reserve(count);
    for (int i = 0; i < count; ++i) {
        HistoryEvent e;
        e.id = HistoryEvent::newId();
        e.machine = u"Carvera"_s;
        e.tool = i % tools;
        e.at = start.addSecs(firstSecond + i);
        e.kind = i % 10 == 0 ? EventKind::BreakTest : EventKind::Probe;
        e.tlo = -30.0 - (i % 1000) * 0.001;
        e.referenceMz = -72.3;
        e.currentMz = -102.3;
        out.append(std::move(e));
    }
    return out;
}

double median(QList<double> values)
{
    std::sort(values.begin(), values.end());
    return values.at(values.size() / 2);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const int large = argc > 1 ? QByteArray(argv[1]).toInt() : 1000000;
    QTemporaryDir dir;

    // Batched: 100,000 events in batches of 1,000.
    auto library = Library::open({ dir.filePath(u"batched.sqlite"_s) });
    if (!library) {
        std::fprintf(stderr, "%s\n", qPrintable(library.error().message));
        return 1;
    }
    const QList<HistoryEvent> batch = events(100000, 50, 0);
    QElapsedTimer clock;
    clock.start();
    for (qsizetype i = 0; i < batch.size(); i += 1000)
        (void)library.value()->append(batch.mid(i, 1000));
    const double batchedPerSecond = 100000.0 / (double(clock.nsecsElapsed()) / 1e9);

    // One at a time, each its own transaction: 2,000 events.
    const QList<HistoryEvent> single = events(2000, 50, 200000);
    clock.restart();
    for (const HistoryEvent &e : single)
        (void)library.value()->append({ e });
    const double singlePerSecond = 2000.0 / (double(clock.nsecsElapsed()) / 1e9);

    // A library of `large` events over 1,000 tools, then one tool's history, median of 7.
    auto big = Library::open({ dir.filePath(u"large.sqlite"_s) });
    for (int done = 0; done < large; done += 10000)
        (void)big.value()->append(events(std::min(10000, large - done), 1000, done));
    QList<double> times;
    qsizetype rows = 0;
    for (int run = 0; run < 7; ++run) {
        clock.restart();
        const auto history = big.value()->history({ u"Carvera"_s, 500 + run, {}, 0 });
        times.append(double(clock.nsecsElapsed()) / 1e6);
        rows = history ? history.value().size() : -1;
    }
    std::printf("| what | figure |\n|---|---:|\n");
    std::printf("| record 100,000 events, batches of 1,000 | %.0f events/s |\n", batchedPerSecond);
    std::printf("| record 2,000 events, one transaction each | %.0f events/s |\n", singlePerSecond);
    std::printf("| one tool's history (%lld events) from a library of %d | %.2f ms (median of 7) |\n",
        static_cast<long long>(rows), large, median(times));
    return 0;
}
