// SPDX-License-Identifier: GPL-3.0-or-later
// One station of toffee-bench-sharedlibrary, in a process of its own: it records measurements on its own tool
// at a steady pace, saves its table every few of them (a counter in its own tool's notes and one in the
// shared tool's, read, incremented and written over the version read), and times what it hears from the other
// stations. What it did goes to stdout as one JSON object, for the coordinator to add up and check.
#pragma once

#include <memory>

#include <QElapsedTimer>
#include <QJsonObject>
#include <QList>
#include <QMap>
#include <QObject>
#include <QStringList>
#include <QTimer>

namespace Toffee {
class Library;
class LibraryWatcher;
struct Tool;
} // namespace Toffee

namespace Toffee::Bench {

inline const QString kBenchMachine = QStringLiteral("Shop");
// Every station's save increments this tool's counter too, so that the stations really race for one row.
constexpr int kSharedTool = 100;

// A tool's notes hold "<count> <station that wrote it>": the station makes each write differ from every other
// station's, so that two stations writing the same count are a conflict, never "already so"; the other fields
// stay as read, so a stale write touches only the field that the other station changed too.
[[nodiscard]] int counterOf(const Tool &tool);
[[nodiscard]] QString counterNotes(int count, const QString &station);

struct WorkerPlan
{
    int index = 1; // the station is "w<index>", its tool T<index>
    QString url;
    int measurements = 2000;
    int seconds = 60;
    int saveEvery = 20; // a save after every this many measurements
    int sharedEvery
        = 0; // every this many measurements one of the shared tool (0: none), as the others save it
};

class SharedLibraryWorker final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(SharedLibraryWorker)

public:
    explicit SharedLibraryWorker(WorkerPlan plan, QObject *parent = nullptr);
    ~SharedLibraryWorker() override;

    // Opens the library and its watcher and starts the pace; false with the reason in `error`.
    bool start(QString *error);
    [[nodiscard]] QJsonObject result() const;

Q_SIGNALS:
    // The measurements are done and the other stations have been quiet for a while.
    void finished();

private:
    void tick();
    void measure();
    void save();
    // Writes the shared tool's counter + 1 over the version just read, until a write of it goes through.
    bool incrementShared();
    void heard(const QString &station, qint64 saidAtMs);
    void error(const QString &message);

    // A station that finished keeps listening until the others have been quiet this long (or kLingerMs).
    static constexpr int kQuietMs = 1000;
    static constexpr int kLingerMs = 10000;
    static constexpr int kAppendTries = 3;
    static constexpr int kSharedTries = 200;

    WorkerPlan m_plan;
    QString m_station;
    std::unique_ptr<Library> m_library;
    std::unique_ptr<LibraryWatcher> m_watcher;
    QTimer m_pace;
    QTimer m_quiet;
    QTimer m_linger;
    qint64 m_startMs = 0;
    qint64 m_endMs = 0;
    int m_done = 0;
    QStringList m_recorded; // ids whose append said it committed
    QStringList m_unclear; // ids whose every append failed: in the library or not
    std::optional<double> m_lastTlo; // the TLO of the last measurement recorded
    QList<double> m_appendMs;
    QList<double> m_saveMs;
    QList<double> m_heardMs;
    int m_announced = 0; // commits of this station that the others should hear of
    int m_ownIncrements = 0;
    int m_sharedIncrements = 0;
    int m_conflicts = 0; // writes of the shared tool refused for another station's
    int m_mostTries = 0; // the most writes one increment of the shared tool took
    QMap<QString, int> m_errors; // each failure's message, and how often
};

// A worker process's main: runs the station with an event loop, prints its result; 0 when it could run.
int runWorker(const WorkerPlan &plan);

} // namespace Toffee::Bench
