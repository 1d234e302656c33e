// SPDX-License-Identifier: GPL-3.0-or-later
#include "tests/bench/sharedlibraryworker.h"

#include <cstdio>

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>

#include "model/library/library.h"
#include "model/library/librarywatcher.h"

using namespace Qt::StringLiterals;

namespace Toffee::Bench {

namespace {

QJsonArray asArray(const QList<double> &values)
{
    QJsonArray out;
    for (double v : values)
        out.append(v);
    return out;
}

double msSince(const QElapsedTimer &clock)
{
    return double(clock.nsecsElapsed()) / 1e6;
}

} // namespace

int counterOf(const Tool &tool)
{
    return tool.notes.section(u' ', 0, 0).toInt();
}

QString counterNotes(int count, const QString &station)
{
    return QString::number(count) + u' ' + station;
}

SharedLibraryWorker::SharedLibraryWorker(WorkerPlan plan, QObject *parent)
    : QObject(parent)
    , m_plan(std::move(plan))
    , m_station(u"w"_s + QString::number(m_plan.index))
{
    // Each timeout is one measurement: a station that falls behind takes longer rather than bunching them.
    m_pace.setTimerType(Qt::PreciseTimer);
    m_pace.setInterval(std::max(1, m_plan.seconds * 1000 / std::max(1, m_plan.measurements)));
    connect(&m_pace, &QTimer::timeout, this, &SharedLibraryWorker::tick);
    m_quiet.setSingleShot(true);
    m_quiet.setInterval(kQuietMs);
    connect(&m_quiet, &QTimer::timeout, this, &SharedLibraryWorker::finished);
    m_linger.setSingleShot(true);
    m_linger.setInterval(kLingerMs);
    connect(&m_linger, &QTimer::timeout, this, &SharedLibraryWorker::finished);
}

SharedLibraryWorker::~SharedLibraryWorker() = default;

bool SharedLibraryWorker::start(QString *error)
{
    auto location = LibraryLocation::parse(m_plan.url);
    if (!location) {
        *error = location.error().message;
        return false;
    }
    auto library = Library::open(location.value(), Library::Options { .station = m_station });
    if (!library) {
        *error = library.error().message;
        return false;
    }
    m_library = std::move(library.value());
    m_watcher = std::make_unique<LibraryWatcher>(m_library.get());
    connect(m_watcher.get(), &LibraryWatcher::announced, this,
        [this](const QString &, const QString &station, qint64 saidAtMs) { heard(station, saidAtMs); });
    m_startMs = QDateTime::currentMSecsSinceEpoch();
    m_pace.start();
    return true;
}

void SharedLibraryWorker::tick()
{
    if (m_done >= m_plan.measurements) {
        m_pace.stop();
        m_endMs = QDateTime::currentMSecsSinceEpoch();
        m_quiet.start();
        m_linger.start();
        return;
    }
    measure();
    ++m_done;
    if (m_plan.saveEvery > 0 && m_done % m_plan.saveEvery == 0)
        save();
}

void SharedLibraryWorker::measure()
{
    HistoryEvent e;
    e.id = HistoryEvent::newId();
    e.machine = kBenchMachine;
    const bool ofShared = m_plan.sharedEvery > 0 && (m_done + 1) % m_plan.sharedEvery == 0;
    e.tool = ofShared ? kSharedTool : m_plan.index;
    e.at = QDateTime::currentDateTimeUtc();
    e.kind = EventKind::Probe;
    e.tlo = -30.0 - m_done * 0.001;
    e.referenceMz = -72.3;
    e.currentMz = -102.3 + *e.tlo;
    QElapsedTimer clock;
    clock.start();
    // A failed append is sent again with the same id, as the outbox replays it: it must still be one row.
    for (int attempt = 0; attempt < kAppendTries; ++attempt) {
        auto written = m_library->append({ e });
        if (written) {
            m_announced += written.value() > 0 ? 1 : 0;
            m_appendMs.append(msSince(clock));
            m_recorded.append(e.id);
            if (!ofShared)
                m_lastTlo = e.tlo;
            return;
        }
        error(u"recording T"_s + QString::number(e.tool) + u": "_s + written.error().message);
    }
    m_unclear.append(e.id);
}

void SharedLibraryWorker::save()
{
    QElapsedTimer clock;
    clock.start();
    auto read = m_library->readTable(kBenchMachine);
    if (!read)
        return error(u"reading the table: "_s + read.error().message);
    const StoredTool *own = read.value().row(m_plan.index);
    const StoredTool *shared = read.value().row(kSharedTool);
    if (!own || !own->tool || !shared || !shared->tool)
        return error(u"%1's table has no T%2 or T%3"_s.arg(kBenchMachine).arg(m_plan.index).arg(kSharedTool));
    Tool mine = *own->tool;
    mine.notes = counterNotes(counterOf(mine) + 1, m_station);
    Tool ours = *shared->tool;
    ours.notes = counterNotes(counterOf(ours) + 1, m_station);
    // Each write carries what it was made over, as the window's do: the counter is one field changed on both
    // sides, which the library must refuse rather than merge.
    auto outcome = m_library->writeTools(kBenchMachine,
        { { m_plan.index, mine, own->version, own->tool },
            { kSharedTool, ours, shared->version, shared->tool } });
    if (!outcome)
        return error(u"saving the table: "_s + outcome.error().message);
    m_announced += outcome.value().written.isEmpty() ? 0 : 1;
    // Only a new version counts as an increment: "already so" would be a write that did not happen.
    if (outcome.value().written.value(m_plan.index) > own->version)
        ++m_ownIncrements;
    else
        error(u"T%1, which only this station writes, was not written"_s.arg(m_plan.index));
    if (outcome.value().written.value(kSharedTool) > shared->version) {
        ++m_sharedIncrements;
        m_mostTries = std::max(m_mostTries, 1);
    } else {
        ++m_conflicts;
        (void)incrementShared();
    }
    m_saveMs.append(msSince(clock));
}

bool SharedLibraryWorker::incrementShared()
{
    for (int attempt = 2; attempt <= kSharedTries; ++attempt) {
        auto read = m_library->readTable(kBenchMachine);
        if (!read) {
            error(u"reading the table: "_s + read.error().message);
            continue;
        }
        const StoredTool *shared = read.value().row(kSharedTool);
        if (!shared || !shared->tool) {
            error(u"%1's table has no T%2"_s.arg(kBenchMachine).arg(kSharedTool));
            return false;
        }
        Tool ours = *shared->tool;
        ours.notes = counterNotes(counterOf(ours) + 1, m_station);
        auto outcome
            = m_library->writeTools(kBenchMachine, { { kSharedTool, ours, shared->version, shared->tool } });
        if (!outcome) {
            error(u"saving the table: "_s + outcome.error().message);
            continue;
        }
        if (outcome.value().written.value(kSharedTool) > shared->version) {
            ++m_announced;
            ++m_sharedIncrements;
            m_mostTries = std::max(m_mostTries, attempt);
            return true;
        }
        ++m_conflicts;
    }
    error(u"T%1 was refused %2 times in a row"_s.arg(kSharedTool).arg(kSharedTries));
    return false;
}

void SharedLibraryWorker::heard(const QString &station, qint64 saidAtMs)
{
    if (station == m_station || saidAtMs <= 0)
        return; // its own commits come back too
    m_heardMs.append(double(QDateTime::currentMSecsSinceEpoch() - saidAtMs));
    if (m_quiet.isActive())
        m_quiet.start();
}

void SharedLibraryWorker::error(const QString &message)
{
    ++m_errors[message];
}

QJsonObject SharedLibraryWorker::result() const
{
    QJsonObject errors;
    for (auto it = m_errors.cbegin(); it != m_errors.cend(); ++it)
        errors.insert(it.key(), it.value());
    return {
        { u"worker"_s, m_plan.index },
        { u"station"_s, m_station },
        { u"startMs"_s, double(m_startMs) },
        { u"endMs"_s, double(m_endMs) },
        { u"recorded"_s, QJsonArray::fromStringList(m_recorded) },
        { u"unclear"_s, QJsonArray::fromStringList(m_unclear) },
        { u"lastTlo"_s, m_lastTlo ? QJsonValue(*m_lastTlo) : QJsonValue() },
        { u"appendMs"_s, asArray(m_appendMs) },
        { u"saveMs"_s, asArray(m_saveMs) },
        { u"heardMs"_s, asArray(m_heardMs) },
        { u"announced"_s, m_announced },
        { u"ownIncrements"_s, m_ownIncrements },
        { u"sharedIncrements"_s, m_sharedIncrements },
        { u"conflicts"_s, m_conflicts },
        { u"mostTries"_s, m_mostTries },
        { u"errors"_s, errors },
    };
}

int runWorker(const WorkerPlan &plan)
{
    SharedLibraryWorker worker(plan);
    QString why;
    if (!worker.start(&why)) {
        std::fprintf(stderr, "w%d: %s\n", plan.index, qPrintable(why));
        return 1;
    }
    QObject::connect(&worker, &SharedLibraryWorker::finished, qApp, &QCoreApplication::quit);
    QCoreApplication::exec();
    const QByteArray json = QJsonDocument(worker.result()).toJson(QJsonDocument::Compact);
    std::fwrite(json.constData(), 1, size_t(json.size()), stdout);
    return 0;
}

} // namespace Toffee::Bench
