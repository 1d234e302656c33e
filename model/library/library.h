// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <memory>

#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QString>

#include "model/library/historyevent.h"
#include "model/library/librarylocation.h"
#include "model/library/storedtable.h"
#include "model/result.h"
#include "model/toollife.h"
#include "model/toolsetter.h"

class QSqlDatabase;
class QSqlDriver;
class QSqlError;
class QSqlQuery;

namespace Toffee {

class ToolTable;

// The library: machines, their tool tables, every measurement event, and what each tool cut, in an SQLite
// file or a shared PostgreSQL database through Qt SQL (docs/LIBRARY.md has every table and column). Both run
// the same SQL, every statement prepared. One Library is one connection, for the thread that opened it; the
// window and toffee-cli can each hold one on the same library at once.
class Library
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::Library)
    Q_DISABLE_COPY_MOVE(Library)

public:
    // The schema this Toffee writes. A library with a higher version is refused, never altered.
    static constexpr int kSchemaVersion = 6;
    static constexpr int kTouchesVersion = 6; // events keep each touch and their spread from here on
    // The channel a shared library's changes are announced on; the payload names the machine, the station and
    // the time (LibraryWatcher::announced).
    static constexpr QLatin1StringView kChannel { "toffee_library" };
    struct Options
    {
        // How long a statement may wait for another program's lock or run: SQLite's busy timeout, and
        // PostgreSQL's lock_timeout and statement_timeout. An operation's own limit (toffee-cli --timeout,
        // the window's) bounds it; setWaitLimit() changes it on an open library.
        int busyTimeoutMs = 5000;
        // PostgreSQL's statement_timeout when it is to be longer than the lock wait (the window reads its
        // history for longer than it waits for a lock); 0: busyTimeoutMs.
        int statementTimeoutMs = 0;
        int connectTimeoutS = 5; // PostgreSQL: how long to wait for the server
        int oldestServerVersion = 0; // PostgreSQL: raises the oldest server taken (as server_version_num)
        QString station = {}; // who writes, for updated_by: the computer's name when empty
        // An SQLite library opened to be read only, as a read-only file or share is: nothing is written, an
        // older schema is read as it is when it can be.
        bool readOnly = false;
    };

    // Opens the library, creating it (and its folder) when it does not exist, and brings its schema up to
    // date in one transaction.
    [[nodiscard]] static Result<std::unique_ptr<Library>> open(const LibraryLocation &location);
    [[nodiscard]] static Result<std::unique_ptr<Library>> open(
        const LibraryLocation &location, Options options);
    ~Library();

    [[nodiscard]] const LibraryLocation &location() const { return m_location; }
    // The file cannot be written, or the server's role has only read rights: every write is refused.
    [[nodiscard]] bool isReadOnly() const { return m_readOnly; }
    [[nodiscard]] QString station() const;
    // The wait limit of Options::busyTimeoutMs, for what this library does from now on.
    [[nodiscard]] Result<void> setWaitLimit(int milliseconds);
    [[nodiscard]] int waitLimitMs() const { return m_options.busyTimeoutMs; }
    // Qt's driver, for its notifications (LibraryWatcher).
    [[nodiscard]] QSqlDriver *driver() const;
    // What the server said when it could not be reached, made into what to fix.
    [[nodiscard]] static QString explainConnectFailure(const LibraryLocation &location, const QString &why);
    // Error::code of a shared library whose server did not answer: the one failure that waiting mends (the
    // station works offline meanwhile). Any other needs the URL, the password file or the server fixed.
    static constexpr QLatin1StringView kUnreachable { "library-unreachable" };
    [[nodiscard]] static bool isUnreachable(const QString &why);
    // Error::code of a write or read that waited its whole limit for another station's or program's lock:
    // what the library could not take now is kept on this computer and sent later.
    static constexpr QLatin1StringView kBusy { "library-busy" };
    // True when the last failure was the connection itself (the server gone), not the statement.
    [[nodiscard]] bool isConnectionLost() const;

    // Adds the machine, or updates its dialect and connection.
    [[nodiscard]] Result<void> addMachine(const MachineRecord &machine);
    [[nodiscard]] Result<QList<MachineRecord>> machines() const;
    // Where the machine's tool setter is (grblHAL's probing cycle is Toffee's): kept with the machine, the
    // machine added when new. Nothing when never set.
    [[nodiscard]] Result<void> setToolSetter(const QString &machine, const ToolSetter &setter);
    [[nodiscard]] Result<std::optional<ToolSetter>> toolSetter(const QString &machine) const;
    // The machine's setter repeatability, the newest measured (libraryrepeatability.cpp); none before one.
    [[nodiscard]] Result<void> setRepeatability(const QString &machine, const SetterRepeatability &measured);
    [[nodiscard]] Result<std::optional<SetterRepeatability>> repeatability(const QString &machine) const;
    // Which machine a name stands for: `identity` (MachineIdentity::key(): the controller and how it is
    // reached). A name bound to nothing yet (new, or kept by a library older than identities) is bound to it
    // now: New. The same identity: Same. Another: Other, with the one it is bound to, and nothing changed
    // unless `rebind` (the operator said it is the same machine, reached another way). A library this station
    // may only read binds nothing and answers as if it had.
    struct MachineBinding
    {
        enum class Kind { New, Same, Other };
        Kind kind = Kind::New;
        QString boundTo; // Other: the identity the name is bound to
    };
    [[nodiscard]] Result<MachineBinding> bindMachine(
        const QString &machine, const QString &identity, bool rebind = false);
    // Appends the events in one transaction (their machines added as needed): all or none. An event whose id
    // is already there is skipped, so writing a batch again after an unclear failure duplicates nothing.
    // Each new event also updates its tool in the machine's table, when the library holds one. Returns how
    // many were new.
    [[nodiscard]] Result<int> append(const QList<HistoryEvent> &events);
    [[nodiscard]] Result<int> appendUse(const QList<ToolUse> &uses);
    // Oldest first. A row that is not an event Toffee would write (another program's, a hand's) is left out
    // and, with `unreadable`, named there (the first kMaxUnreadableNamed).
    [[nodiscard]] Result<QList<HistoryEvent>> history(
        const HistoryQuery &query, QStringList *unreadable = nullptr) const;
    static constexpr qsizetype kMaxUnreadableNamed = 20;
    [[nodiscard]] Result<QList<ToolUse>> uses(const QString &machine, std::optional<int> tool) const;
    // What each tool's cutter has done on the machine since it went in: the cutting time and the programs of
    // the runs recorded after the tool's newest new cutter (all of them when it has none). One tool, or all.
    [[nodiscard]] Result<QHash<int, UsedLife>> usedLife(
        const QString &machine, std::optional<int> tool = std::nullopt) const;

    // Machine tables (librarytables.cpp). The machines that have one, by name.
    [[nodiscard]] Result<QStringList> tableMachines() const;
    [[nodiscard]] Result<StoredTable> readTable(const QString &machine) const;
    // Puts a new table for the machine in the library; refused when it has one.
    [[nodiscard]] Result<StoredTable> createTable(const QString &machine, const ToolTable &table);
    // Writes the tools in one transaction. A tool whose row changed since `baseVersion` is not written but
    // returned as a conflict with both sides; everything else is.
    [[nodiscard]] Result<WriteOutcome> writeTools(const QString &machine, const QList<ToolWrite> &writes);

    // The outbox of a station's own SQLite library: what waits for a shared library (libraryoutbox.cpp).
    [[nodiscard]] Result<void> outboxAdd(const OutboxEntry &entry);
    [[nodiscard]] Result<QList<OutboxEntry>> outbox(const QString &library) const;
    [[nodiscard]] Result<void> outboxRemove(const QString &id);

private:
    Library(LibraryLocation location, QString connection);
    [[nodiscard]] QSqlDatabase database() const;
    [[nodiscard]] Result<void> prepareSqlite();
    [[nodiscard]] Result<void> preparePostgres();
    [[nodiscard]] Result<void> checkNotNewer(int version) const;
    [[nodiscard]] Result<void> migrate();
    [[nodiscard]] Result<void> begin();
    [[nodiscard]] Result<void> applyWaitLimit(bool local);
    // A transaction that writes: refused first when the library is read-only.
    [[nodiscard]] Result<void> beginWrite();
    [[nodiscard]] Result<void> commit();
    void rollback();
    [[nodiscard]] Result<void> checkWritable() const;
    [[nodiscard]] Result<void> announce(const QStringList &machines);
    [[nodiscard]] Result<void> applyToTables(const QList<HistoryEvent> &events);
    [[nodiscard]] static bool supersedes(const HistoryEvent &event, const Tool *current);
    [[nodiscard]] Result<std::optional<StoredTool>> readRow(const QString &machine, int number) const;
    [[nodiscard]] Result<std::optional<Units>> tableUnits(const QString &machine) const;
    [[nodiscard]] Result<bool> putRow(
        const QString &machine, Units units, const ToolWrite &write, qint64 currentVersion, bool exists);
    [[nodiscard]] Result<int> schemaVersion() const;
    // Every table and column this Toffee reads and writes is there.
    [[nodiscard]] Result<void> checkTables() const;
    [[nodiscard]] Error damaged(const QString &why) const;
    [[nodiscard]] Error failure(const QString &what, const QSqlQuery &query) const;
    [[nodiscard]] Error failure(const QString &what, const QSqlError &error) const;
    // The read-only refusal, for a library already known to be read-only or found so by a refused write.
    [[nodiscard]] Result<void> checkWritableFor(bool readOnly) const;
    [[nodiscard]] Result<void> ensureMachines(const QStringList &names);
    // Rows that are new (not already there by id) are passed to `after`, in the same transaction.
    [[nodiscard]] Result<int> insertAll(const QString &sql, const QStringList &machines, qsizetype count,
        const std::function<QString(QSqlQuery &, qsizetype)> &bind,
        const std::function<Result<void>(const QList<qsizetype> &)> &after);

    // A row lost to another station's write between reading it and writing it is read again, a few times.
    static constexpr int kRaceRetries = 5;

    LibraryLocation m_location;
    QString m_connection;
    Options m_options;
    bool m_readOnly = false;
};

// The reference MCS Z Toffee kept for `machine`, for a controller that keeps none itself (grblHAL): the
// newest probe's in `library` (when there is one), else the newest measured tool's in `table`. Nothing: the
// next probe makes its tool the reference.
[[nodiscard]] std::optional<double> keptReferenceMz(
    const Library *library, const QString &machine, const ToolTable &table);

} // namespace Toffee
