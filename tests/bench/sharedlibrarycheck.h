// SPDX-License-Identifier: GPL-3.0-or-later
// The coordinator's side of toffee-bench-sharedlibrary: what the stations said they wrote, checked against
// the library (every measurement there exactly once, no increment of a counter lost), and the figures.
#pragma once

#include <QJsonObject>
#include <QList>
#include <QStringList>

namespace Toffee {
class Library;
namespace Test {
class PgCluster;
}
} // namespace Toffee

namespace Toffee::Bench {

struct Verdict
{
    qint64 rows = 0; // events in the library
    qint64 ids = 0; // distinct ids among them
    qint64 recorded = 0; // events the stations said they recorded
    qint64 unclear = 0; // events whose every append failed
    qint64 unclearPresent = 0; // of them, those found in the library all the same
    qint64 missing = 0; // recorded, not in the library
    qint64 unknown = 0; // in the library, never sent
    qint64 sharedExpected = 0; // increments of the shared tool's counter the stations made
    qint64 sharedFound = 0; // its counter at the end
    qint64 lostUpdates = 0; // increments the counters lack, the shared one's and each station's own
    QStringList problems; // each failed check, in words

    [[nodiscard]] bool ok() const { return problems.isEmpty(); }
};

// `database` is the library's database on `cluster`, for the counts that only SQL can give.
[[nodiscard]] Verdict verify(Library &library, const Test::PgCluster &cluster, const QString &database,
    const QList<QJsonObject> &results);

// Each station's failures, by message, as "w3: message (×2)".
[[nodiscard]] QStringList stationErrors(const QList<QJsonObject> &results);

// The nearest-rank percentile, `p` in 0..1; 0 for no values.
[[nodiscard]] double percentile(QList<double> values, double p);

struct RunShape
{
    int processes = 0;
    int measurements = 0;
    int saveEvery = 0;
    int sharedEvery = 0;
};

// The report, a Markdown table as the other benchmarks print.
void printReport(const RunShape &shape, const QList<QJsonObject> &results, const Verdict &verdict);

} // namespace Toffee::Bench
