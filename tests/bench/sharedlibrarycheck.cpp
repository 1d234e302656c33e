// SPDX-License-Identifier: GPL-3.0-or-later
#include "tests/bench/sharedlibrarycheck.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <QJsonArray>
#include <QSet>

#include "model/library/library.h"
#include "tests/bench/sharedlibraryworker.h"
#include "tests/support/pgcluster.h"

using namespace Qt::StringLiterals;

namespace Toffee::Bench {

namespace {

QSet<QString> idsOf(const QList<QJsonObject> &results, const QString &key)
{
    QSet<QString> out;
    for (const QJsonObject &r : results) {
        for (const QJsonValue &id : r.value(key).toArray())
            out.insert(id.toString());
    }
    return out;
}

QList<double> valuesOf(const QList<QJsonObject> &results, const QString &key)
{
    QList<double> out;
    for (const QJsonObject &r : results) {
        for (const QJsonValue &v : r.value(key).toArray())
            out.append(v.toDouble());
    }
    return out;
}

qint64 sumOf(const QList<QJsonObject> &results, const QString &key)
{
    qint64 sum = 0;
    for (const QJsonObject &r : results)
        sum += r.value(key).toInteger();
    return sum;
}

// Every id the stations recorded in the library, once; nothing there that no station sent.
void checkEvents(Library &library, const Test::PgCluster &cluster, const QString &database,
    const QList<QJsonObject> &results, Verdict &v)
{
    QString why;
    v.rows = cluster.value(u"SELECT count(*) FROM events"_s, &why, database).toLongLong();
    v.ids = cluster.value(u"SELECT count(DISTINCT id) FROM events"_s, &why, database).toLongLong();
    if (!why.isEmpty())
        v.problems << u"counting the events failed: %1"_s.arg(why);
    if (v.rows != v.ids)
        v.problems << u"%1 events for %2 ids: some written more than once"_s.arg(v.rows).arg(v.ids);
    auto history = library.history({ kBenchMachine, std::nullopt, {}, 0 });
    if (!history) {
        v.problems << history.error().message;
        return;
    }
    QSet<QString> stored;
    for (const HistoryEvent &e : history.value())
        stored.insert(e.id);
    const QSet<QString> recorded = idsOf(results, u"recorded"_s);
    const QSet<QString> unclear = idsOf(results, u"unclear"_s);
    v.recorded = recorded.size();
    v.unclear = unclear.size();
    v.unclearPresent = QSet<QString>(unclear).intersect(stored).size();
    v.missing = QSet<QString>(recorded).subtract(stored).size();
    v.unknown = QSet<QString>(stored).subtract(recorded).subtract(unclear).size();
    if (v.missing > 0)
        v.problems << u"%1 recorded measurements are not in the library"_s.arg(v.missing);
    if (v.unknown > 0)
        v.problems << u"%1 events in the library were never sent"_s.arg(v.unknown);
}

// The counters hold every increment a station was told it wrote; each tool's TLO is its last measurement's.
void checkCounters(Library &library, const QList<QJsonObject> &results, Verdict &v)
{
    auto read = library.readTable(kBenchMachine);
    if (!read) {
        v.problems << read.error().message;
        return;
    }
    const StoredTool *shared = read.value().row(kSharedTool);
    v.sharedExpected = sumOf(results, u"sharedIncrements"_s);
    v.sharedFound = shared && shared->tool ? counterOf(*shared->tool) : -1;
    v.lostUpdates += std::abs(v.sharedExpected - v.sharedFound);
    if (v.sharedFound != v.sharedExpected)
        v.problems << u"T%1's counter is %2, the stations made %3 increments"_s.arg(kSharedTool)
                          .arg(v.sharedFound)
                          .arg(v.sharedExpected);
    for (const QJsonObject &r : results) {
        const int number = r.value(u"worker"_s).toInt();
        const StoredTool *own = read.value().row(number);
        const qint64 expected = r.value(u"ownIncrements"_s).toInteger();
        const qint64 found = own && own->tool ? counterOf(*own->tool) : -1;
        v.lostUpdates += std::abs(expected - found);
        if (found != expected)
            v.problems << u"T%1's counter is %2, its station made %3 increments"_s.arg(number).arg(found).arg(
                expected);
        const QJsonValue lastTlo = r.value(u"lastTlo"_s);
        if (!lastTlo.isNull() && (!own || !own->tool || own->tool->measuredTlo != lastTlo.toDouble()))
            v.problems << u"T%1's TLO is not its last measurement's (%2)"_s.arg(number).arg(
                lastTlo.toDouble());
    }
}

QString figures(const QList<double> &values)
{
    return u"%1 / %2 / %3 ms"_s.arg(percentile(values, 0.5), 0, 'f', 1)
        .arg(percentile(values, 0.99), 0, 'f', 1)
        .arg(values.isEmpty() ? 0.0 : *std::max_element(values.cbegin(), values.cend()), 0, 'f', 1);
}

void row(const QString &what, const QString &figure)
{
    std::printf("| %s | %s |\n", qPrintable(what), qPrintable(figure));
}

} // namespace

Verdict verify(Library &library, const Test::PgCluster &cluster, const QString &database,
    const QList<QJsonObject> &results)
{
    Verdict v;
    checkEvents(library, cluster, database, results, v);
    checkCounters(library, results, v);
    return v;
}

QStringList stationErrors(const QList<QJsonObject> &results)
{
    QStringList out;
    for (const QJsonObject &r : results) {
        const QJsonObject errors = r.value(u"errors"_s).toObject();
        for (auto it = errors.constBegin(); it != errors.constEnd(); ++it)
            out << u"%1: %2 (×%3)"_s.arg(r.value(u"station"_s).toString(), it.key()).arg(it.value().toInt());
    }
    return out;
}

double percentile(QList<double> values, double p)
{
    if (values.isEmpty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const auto rank = qsizetype(std::ceil(p * double(values.size())));
    return values.at(std::clamp<qsizetype>(rank - 1, 0, values.size() - 1));
}

void printReport(const RunShape &shape, const QList<QJsonObject> &results, const Verdict &verdict)
{
    double first = 0, last = 0;
    int mostTries = 0;
    for (const QJsonObject &r : results) {
        mostTries = std::max(mostTries, r.value(u"mostTries"_s).toInt());
        const double start = r.value(u"startMs"_s).toDouble(), end = r.value(u"endMs"_s).toDouble();
        first = first == 0 ? start : std::min(first, start);
        last = std::max(last, end);
    }
    const double seconds = std::max(0.001, (last - first) / 1000.0);
    const QList<double> appends = valuesOf(results, u"appendMs"_s);
    const QList<double> saves = valuesOf(results, u"saveMs"_s);
    const QList<double> heard = valuesOf(results, u"heardMs"_s);
    std::printf("| what | figure |\n|---|---:|\n");
    const QString ofShared
        = shape.sharedEvery > 0 ? u", one in %1 on T%2"_s.arg(shape.sharedEvery).arg(kSharedTool) : QString();
    row(u"stations × measurements (a save every %1%2)"_s.arg(shape.saveEvery).arg(ofShared),
        u"%1 × %2"_s.arg(shape.processes).arg(shape.measurements));
    row(u"wall time, first measurement to last"_s, u"%1 s"_s.arg(seconds, 0, 'f', 1));
    row(u"writes/s: measurements + table saves"_s,
        u"%1 (%2 + %3)"_s.arg(double(appends.size() + saves.size()) / seconds, 0, 'f', 0)
            .arg(double(appends.size()) / seconds, 0, 'f', 0)
            .arg(double(saves.size()) / seconds, 0, 'f', 1));
    row(u"record a measurement, p50 / p99 / max (%1)"_s.arg(appends.size()), figures(appends));
    row(u"save a table (2 tools, retries included), p50 / p99 / max (%1)"_s.arg(saves.size()),
        figures(saves));
    row(u"shared tool: writes refused for another station's, retried"_s,
        u"%1 (at most %2 writes for one increment)"_s.arg(sumOf(results, u"conflicts"_s)).arg(mostTries));
    // Each station hears every other station's commits, those made before it listened and after it left
    // aside.
    const qint64 said = sumOf(results, u"announced"_s) * std::max(0, shape.processes - 1);
    row(u"notification, station to station, p50 / p99 / max (%1 heard of %2 said)"_s.arg(heard.size())
            .arg(said),
        figures(heard));
    row(u"every measurement exactly once"_s,
        u"%1: %2 events, %3 ids, %4 recorded, %5 missing, %6 unknown"_s
            .arg(verdict.missing == 0 && verdict.unknown == 0 && verdict.rows == verdict.ids ? u"OK"_s
                                                                                             : u"FAILED"_s)
            .arg(verdict.rows)
            .arg(verdict.ids)
            .arg(verdict.recorded)
            .arg(verdict.missing)
            .arg(verdict.unknown));
    row(u"lost updates"_s,
        u"%1 (T%2: %3 of %4 increments)"_s.arg(verdict.lostUpdates)
            .arg(kSharedTool)
            .arg(verdict.sharedFound)
            .arg(verdict.sharedExpected));
    if (verdict.unclear > 0)
        std::printf(
            "%lld measurements were refused every time they were sent; %lld of them are in the library\n",
            static_cast<long long>(verdict.unclear), static_cast<long long>(verdict.unclearPresent));
    for (const QString &problem : verdict.problems)
        std::printf("FAILED: %s\n", qPrintable(problem));
    for (const QString &error : stationErrors(results))
        std::printf("error: %s\n", qPrintable(error));
}

} // namespace Toffee::Bench
