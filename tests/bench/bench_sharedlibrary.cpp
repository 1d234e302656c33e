// SPDX-License-Identifier: GPL-3.0-or-later
// A shop's stations on one shared library (issue 15's load test): a throwaway PostgreSQL server, a machine
// table with a tool per station and one they all share, and a process per station recording measurements and
// saving its table while the others do (sharedlibraryworker.h). Then the library is checked: every
// measurement there exactly once, no increment of a counter lost. Exits 1 when a check fails or a station
// was told a write failed.
//   toffee-bench-sharedlibrary [--processes 8] [--measurements 2000] [--seconds 60] [--save-every 20]
//                              [--shared-every 0]
// The same binary is each station: --worker N --url URL, with the rest as above.
#include <cstdio>

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QFile>
#include <QJsonDocument>
#include <QProcess>
#include <QTemporaryDir>

#include "model/library/library.h"
#include "tests/bench/sharedlibrarycheck.h"
#include "tests/bench/sharedlibraryworker.h"
#include "tests/support/pgcluster.h"

using namespace Toffee;
using namespace Toffee::Bench;
using namespace Qt::StringLiterals;

namespace {

const QString kRole = u"toffee_bench"_s;
const QString kDatabase = u"shop"_s;

// The server, the stations' role (which logs in with its password, as a shop's would) and its password file,
// which PGPASSFILE names for this process and the stations it starts.
std::optional<QString> prepareServer(Test::PgCluster &cluster, const QTemporaryDir &dir, QString *why)
{
    const QString password = u"bench-"_s + QString::number(QCoreApplication::applicationPid());
    const QString passFile = dir.filePath(u"pgpass"_s);
    if (!cluster.start(why) || !cluster.createRole(kRole, password, true, why)
        || !cluster.createDatabase(kDatabase, kRole, why)
        || !cluster.writePassFile(passFile, { { kDatabase, kRole, password } }, why))
        return std::nullopt;
    qputenv("PGPASSFILE", QFile::encodeName(passFile));
    return cluster.url(kRole, kDatabase);
}

Result<std::unique_ptr<Library>> openLibrary(const QString &url)
{
    auto location = LibraryLocation::parse(url);
    if (!location)
        return location.error();
    return Library::open(location.value(), Library::Options { .station = u"coordinator"_s });
}

// T1..Tn, one per station, and the shared tool, each counter at 0.
Result<void> createShop(Library &library, int processes)
{
    ToolTable table(Units::Millimetre);
    QList<int> numbers;
    for (int n = 1; n <= processes; ++n)
        numbers << n;
    numbers << kSharedTool;
    for (int n : numbers) {
        Tool tool;
        tool.number = n;
        tool.pocket = n;
        tool.description = n == kSharedTool ? u"shared"_s : u"w%1's"_s.arg(n);
        tool.notes = counterNotes(0, u"coordinator"_s);
        if (auto inserted = table.insert(tool); !inserted)
            return inserted.error();
    }
    if (auto created = library.createTable(kBenchMachine, table); !created)
        return created.error();
    return {};
}

// Every station at once, each writing its result to a file of its own (a pipe that nobody reads while the
// others run would stall it); their failures go to this process's stderr.
QList<QJsonObject> runStations(const QString &url, const WorkerPlan &plan, int processes,
    const QTemporaryDir &dir, QStringList *problems)
{
    std::vector<std::unique_ptr<QProcess>> stations;
    for (int n = 1; n <= processes; ++n) {
        auto station = std::make_unique<QProcess>();
        station->setProcessChannelMode(QProcess::ForwardedErrorChannel);
        station->setStandardOutputFile(dir.filePath(u"w%1.json"_s.arg(n)));
        station->start(QCoreApplication::applicationFilePath(),
            { u"--worker"_s, QString::number(n), u"--url"_s, url, u"--measurements"_s,
                QString::number(plan.measurements), u"--seconds"_s, QString::number(plan.seconds),
                u"--save-every"_s, QString::number(plan.saveEvery), u"--shared-every"_s,
                QString::number(plan.sharedEvery) });
        stations.push_back(std::move(station));
    }
    // Four times the planned time, and a minute, before a station that hangs is called so.
    const QDeadlineTimer deadline(qint64(plan.seconds) * 4000 + 60000);
    QList<QJsonObject> results;
    for (int n = 1; n <= processes; ++n) {
        QProcess &station = *stations.at(size_t(n - 1));
        if (!station.waitForFinished(int(std::max<qint64>(1, deadline.remainingTime())))) {
            station.kill();
            station.waitForFinished();
            *problems << u"w%1 did not finish in time"_s.arg(n);
            continue;
        }
        QFile out(dir.filePath(u"w%1.json"_s.arg(n)));
        const QJsonDocument json
            = out.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(out.readAll()) : QJsonDocument();
        if (station.exitStatus() != QProcess::NormalExit || station.exitCode() != 0 || !json.isObject())
            *problems << u"w%1 failed (exit code %2)"_s.arg(n).arg(station.exitCode());
        else
            results.append(json.object());
    }
    return results;
}

int coordinate(const WorkerPlan &plan, int processes)
{
    Test::PgCluster cluster;
    QTemporaryDir dir;
    QString why;
    const auto url = prepareServer(cluster, dir, &why);
    if (!url) {
        std::fprintf(stderr, "the server: %s\n", qPrintable(why));
        return 1;
    }
    auto library = openLibrary(*url);
    auto created = library ? createShop(*library.value(), processes) : Result<void>(library.error());
    if (!created) {
        std::fprintf(stderr, "%s\n", qPrintable(created.error().message));
        return 1;
    }
    QStringList problems;
    const QList<QJsonObject> results = runStations(*url, plan, processes, dir, &problems);
    Verdict verdict = verify(*library.value(), cluster, kDatabase, results);
    verdict.problems = problems + verdict.problems;
    printReport({ processes, plan.measurements, plan.saveEvery, plan.sharedEvery }, results, verdict);
    return verdict.ok() && stationErrors(results).isEmpty() ? 0 : 1;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    const QCommandLineOption processes(u"processes"_s, u"Stations, each a process."_s, u"n"_s, u"8"_s);
    const QCommandLineOption measurements(
        u"measurements"_s, u"Measurements each station records."_s, u"n"_s, u"2000"_s);
    const QCommandLineOption seconds(u"seconds"_s, u"Over how long."_s, u"s"_s, u"60"_s);
    const QCommandLineOption saveEvery(
        u"save-every"_s, u"A table save after every n measurements."_s, u"n"_s, u"20"_s);
    const QCommandLineOption sharedEvery(u"shared-every"_s,
        u"Every n-th measurement of the tool the stations share (0: none)."_s, u"n"_s, u"0"_s);
    const QCommandLineOption worker(u"worker"_s, u"Run as station n."_s, u"n"_s);
    const QCommandLineOption url(u"url"_s, u"The library, for a station."_s, u"url"_s);
    parser.addOptions({ processes, measurements, seconds, saveEvery, sharedEvery, worker, url });
    parser.addHelpOption();
    parser.process(app);
    WorkerPlan plan { parser.value(worker).toInt(), parser.value(url), parser.value(measurements).toInt(),
        parser.value(seconds).toInt(), parser.value(saveEvery).toInt(), parser.value(sharedEvery).toInt() };
    if (parser.isSet(worker))
        return runWorker(plan);
    const int stations = parser.value(processes).toInt();
    if (stations < 1 || stations >= kSharedTool || plan.measurements < 1 || plan.seconds < 1) {
        std::fprintf(stderr, "--processes 1..%d, --measurements and --seconds at least 1\n", kSharedTool - 1);
        return 2;
    }
    return coordinate(plan, stations);
}
