// SPDX-License-Identifier: GPL-3.0-or-later
// A library's schema: checked before a byte is written, and brought up to date in one transaction.
#include "model/library/library.h"

#include <QFileInfo>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QSqlRecord>
#include <QVariant>

#include "model/textparsing.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// Each migration brings the schema from version n - 1 to n. SQL that SQLite and PostgreSQL both run.
const QList<QStringList> kMigrations = {
    {
        u"CREATE TABLE machines (name TEXT PRIMARY KEY, dialect TEXT NOT NULL DEFAULT '', "
        "connection TEXT NOT NULL DEFAULT '')"_s,
        u"CREATE TABLE events (id TEXT PRIMARY KEY, machine TEXT NOT NULL REFERENCES machines (name), "
        "tool INTEGER NOT NULL, measured_at TEXT NOT NULL, kind TEXT NOT NULL CHECK (kind IN ('probe', "
        "'break_test', 'manual_set', 'restore', 'import')), tlo DOUBLE PRECISION, reference_mz DOUBLE "
        "PRECISION, "
        "current_mz DOUBLE PRECISION, tolerance DOUBLE PRECISION, old_tlo DOUBLE PRECISION, new_tlo DOUBLE "
        "PRECISION, failed INTEGER CHECK (failed IN (0, 1)))"_s,
        u"CREATE INDEX events_by_tool ON events (machine, tool, measured_at)"_s,
        u"CREATE INDEX events_by_time ON events (measured_at)"_s,
        u"CREATE TABLE tool_use (id TEXT PRIMARY KEY, machine TEXT NOT NULL REFERENCES machines (name), "
        "tool INTEGER NOT NULL, recorded_at TEXT NOT NULL, program TEXT NOT NULL DEFAULT '', "
        "cutting_seconds DOUBLE PRECISION NOT NULL, feed_path_mm DOUBLE PRECISION NOT NULL)"_s,
        u"CREATE INDEX tool_use_by_tool ON tool_use (machine, tool, recorded_at)"_s,
    },
    {
        // Machine tables: a row per tool with a version, so that a save never overwrites a change it has not
        // seen. A removed tool stays as a row marked deleted, so that its removal has a version too.
        u"CREATE TABLE machine_tables (machine TEXT PRIMARY KEY REFERENCES machines (name), units TEXT NOT "
        "NULL CHECK (units IN ('mm', 'in')), created_at TEXT NOT NULL)"_s,
        u"CREATE TABLE tools (machine TEXT NOT NULL REFERENCES machine_tables (machine), number INTEGER NOT "
        "NULL, version INTEGER NOT NULL, deleted INTEGER NOT NULL DEFAULT 0 CHECK (deleted IN (0, 1)), "
        "data TEXT NOT NULL, tlo DOUBLE PRECISION, updated_at TEXT NOT NULL, updated_by TEXT NOT NULL "
        "DEFAULT '', PRIMARY KEY (machine, number))"_s,
        // What a station could not write to a shared library yet, kept in its own SQLite library.
        u"CREATE TABLE outbox (id TEXT PRIMARY KEY, library TEXT NOT NULL, kind TEXT NOT NULL CHECK (kind IN "
        "('events', 'tools')), payload TEXT NOT NULL, created_at TEXT NOT NULL)"_s,
    },
    {
        // Where each machine's tool setter is, for a controller whose probing cycle is Toffee's (grblHAL):
        // ToolSetter::text(), empty when not set.
        u"ALTER TABLE machines ADD COLUMN setter TEXT NOT NULL DEFAULT ''"_s,
    },
    {
        // A new cutter in a tool's pocket is an event ('new_cutter'): the events table is made again with the
        // kind allowed (neither SQLite nor, in one statement both run, PostgreSQL alters a CHECK), every row
        // copied across.
        u"CREATE TABLE events_v4 (id TEXT PRIMARY KEY, machine TEXT NOT NULL REFERENCES machines (name), "
        "tool INTEGER NOT NULL, measured_at TEXT NOT NULL, kind TEXT NOT NULL CHECK (kind IN ('probe', "
        "'break_test', 'manual_set', 'restore', 'import', 'new_cutter')), tlo DOUBLE PRECISION, reference_mz "
        "DOUBLE PRECISION, current_mz DOUBLE PRECISION, tolerance DOUBLE PRECISION, old_tlo DOUBLE "
        "PRECISION, "
        "new_tlo DOUBLE PRECISION, failed INTEGER CHECK (failed IN (0, 1)))"_s,
        u"INSERT INTO events_v4 (id, machine, tool, measured_at, kind, tlo, reference_mz, current_mz, "
        u"tolerance, "
        "old_tlo, new_tlo, failed) SELECT id, machine, tool, measured_at, kind, tlo, reference_mz, "
        "current_mz, "
        "tolerance, old_tlo, new_tlo, failed FROM events"_s,
        u"DROP TABLE events"_s,
        u"ALTER TABLE events_v4 RENAME TO events"_s,
        u"CREATE INDEX events_by_tool ON events (machine, tool, measured_at)"_s,
        u"CREATE INDEX events_by_time ON events (measured_at)"_s,
    },
    {
        // Which machine each name stands for (Library::bindMachine): its controller and how it is reached;
        // empty for a name no station has bound yet (every machine of an older library).
        u"ALTER TABLE machines ADD COLUMN identity TEXT NOT NULL DEFAULT ''"_s,
    },
    {
        // A tool touched once per cutting edge: each touch's machine Z (space-separated, empty for one touch)
        // and their spread; and each machine's setter repeatability (measure-repeatability), as JSON.
        u"ALTER TABLE events ADD COLUMN touches TEXT NOT NULL DEFAULT ''"_s,
        u"ALTER TABLE events ADD COLUMN spread DOUBLE PRECISION"_s,
        u"ALTER TABLE machines ADD COLUMN repeatability TEXT NOT NULL DEFAULT ''"_s,
    },
};

// PostgreSQL before 14 is past its end of life; ON CONFLICT and pg_notify are older than that.
constexpr int kOldestServer = 140000;

// Every table of the schema this Toffee writes, with the columns it reads and writes: a library that lacks
// one was damaged, or altered by another program, and is not written into.
const QList<std::pair<QString, QStringList>> kTables = {
    { u"machines"_s, { u"name"_s, u"dialect"_s, u"connection"_s, u"setter"_s, u"repeatability"_s } },
    { u"events"_s,
        { u"id"_s, u"machine"_s, u"tool"_s, u"measured_at"_s, u"kind"_s, u"tlo"_s, u"reference_mz"_s,
            u"current_mz"_s, u"tolerance"_s, u"old_tlo"_s, u"new_tlo"_s, u"failed"_s, u"touches"_s,
            u"spread"_s } },
    { u"tool_use"_s,
        { u"id"_s, u"machine"_s, u"tool"_s, u"recorded_at"_s, u"program"_s, u"cutting_seconds"_s,
            u"feed_path_mm"_s } },
    { u"machine_tables"_s, { u"machine"_s, u"units"_s, u"created_at"_s } },
    { u"tools"_s,
        { u"machine"_s, u"number"_s, u"version"_s, u"deleted"_s, u"data"_s, u"tlo"_s, u"updated_at"_s,
            u"updated_by"_s } },
    { u"outbox"_s, { u"id"_s, u"library"_s, u"kind"_s, u"payload"_s, u"created_at"_s } },
};

// No Toffee will write a schema version anywhere near this: a larger one is damage, not the future.
constexpr qint64 kLargestPlausibleVersion = 1000;

} // namespace

Result<void> Library::begin()
{
    QSqlDatabase db = database();
    QSqlQuery query(db);
    // SQLite's IMMEDIATE takes the write lock at once: a read then a write in one transaction is then never
    // refused for another writer's commit in between.
    if (!m_location.isShared()) {
        if (query.exec(u"BEGIN IMMEDIATE"_s))
            return {};
        return failure(tr("Starting a write"), query);
    }
    if (!db.transaction())
        return failure(tr("Starting a write"), db.lastError());
    // The limits again for this transaction alone, whatever the session was set to meanwhile.
    if (auto limited = applyWaitLimit(true); !limited) {
        db.rollback();
        return limited;
    }
    return {};
}

Result<void> Library::beginWrite()
{
    if (auto writable = checkWritable(); !writable)
        return writable;
    return begin();
}

Result<void> Library::setWaitLimit(int milliseconds)
{
    m_options.busyTimeoutMs = std::max(1, milliseconds);
    return applyWaitLimit(false);
}

// SQLite waits for a lock at most its busy timeout; PostgreSQL at most lock_timeout for a lock and
// statement_timeout for a statement, for the session or (`local`) the transaction.
Result<void> Library::applyWaitLimit(bool local)
{
    QSqlQuery query(database());
    if (!m_location.isShared()) {
        if (!query.exec(u"PRAGMA busy_timeout = "_s + QString::number(m_options.busyTimeoutMs)))
            return failure(tr("Setting how long to wait"), query);
        return {};
    }
    const int statementMs
        = m_options.statementTimeoutMs > 0 ? m_options.statementTimeoutMs : m_options.busyTimeoutMs;
    query.prepare(u"SELECT set_config('lock_timeout', ?, ?), set_config('statement_timeout', ?, ?)"_s);
    query.addBindValue(QString(QString::number(m_options.busyTimeoutMs) + u"ms"_s));
    query.addBindValue(local);
    query.addBindValue(QString(QString::number(statementMs) + u"ms"_s));
    query.addBindValue(local);
    if (!query.exec())
        return failure(tr("Setting how long to wait"), query);
    return {};
}

Result<void> Library::commit()
{
    QSqlDatabase db = database();
    if (db.commit())
        return {};
    const QSqlError error = db.lastError();
    db.rollback();
    return failure(tr("Writing"), error);
}

void Library::rollback()
{
    database().rollback();
}

Result<void> Library::prepareSqlite()
{
    QSqlQuery query(database());
    // Read first, write nothing: a damaged file, another program's database or a newer library must be left
    // as it is.
    if (!query.exec(u"SELECT count(*) FROM sqlite_master"_s))
        return Error { tr(
            "%1 is damaged or is not a library: %2. Move it away (Toffee then starts a new one), or "
            "choose another file.")
                           .arg(m_location.path, query.lastError().databaseText()) };
    auto version = schemaVersion();
    if (!version)
        return version.error();
    if (auto checked = checkNotNewer(version.value()); !checked)
        return checked;
    // WAL lets the window read while toffee-cli writes, and the other way round; a read-only file stays in
    // the mode it has, and is still read.
    (void)query.exec(u"PRAGMA journal_mode = WAL"_s);
    // In WAL mode, NORMAL keeps every committed event through a crash of the program (it only waits for the
    // disk at checkpoints): a power cut may lose the last ones, not the library.
    (void)query.exec(u"PRAGMA synchronous = NORMAL"_s);
    if (!query.exec(u"PRAGMA foreign_keys = ON"_s))
        return failure(tr("Reading the library"), query);
    const QFileInfo info(m_location.path);
    m_readOnly = m_options.readOnly || (info.exists() && !info.isWritable());
    // A library that is up to date is only read here: opening it to read the history takes no write lock,
    // so another program's long write does not make a reader fail.
    if (version.value() != kSchemaVersion) {
        // A read-only file cannot be brought up to date: read as it is when its tables have what Toffee reads
        // (version 3 lacks only the new cutters' kind, which it then simply holds none of).
        if (m_readOnly) {
            if (checkTables())
                return {};
            return Error { tr(
                "%1 is a library of version %2, read-only here, and too old to be read as it is. "
                "Open it once where it can be written (Toffee brings it up to date), or copy it.")
                               .arg(m_location.path)
                               .arg(version.value()) };
        }
        if (auto migrated = migrate(); !migrated)
            return migrated;
    }
    return checkTables();
}

Result<void> Library::preparePostgres()
{
    if (auto limited = applyWaitLimit(false); !limited)
        return limited;
    QSqlQuery query(database());
    if (!query.exec(
            u"SELECT current_setting('server_version_num')::integer, current_setting('server_version')"_s)
        || !query.next())
        return failure(tr("Reading the server's version"), query);
    const int oldest = std::max(kOldestServer, m_options.oldestServerVersion);
    if (query.value(0).toInt() < oldest)
        return Error {
            tr("The library (%1) is on PostgreSQL %2, which this Toffee does not support: it needs %3 or "
               "newer. Upgrade the server, or use another one.")
                .arg(m_location.displayName(), query.value(1).toString(), QString::number(oldest / 10000))
        };
    auto version = schemaVersion();
    if (!version)
        return version.error();
    if (auto checked = checkNotNewer(version.value()); !checked)
        return checked;
    if (version.value() == kSchemaVersion) {
        // A role that can read the tools but not change them gets a read-only library, and says so.
        if (!query.exec(u"SELECT has_table_privilege('tools', 'UPDATE') AND has_table_privilege('events', "
                        "'INSERT')"_s)
            || !query.next())
            return failure(tr("Reading your rights in the library"), query);
        m_readOnly = !query.value(0).toBool();
        return checkTables();
    }
    if (auto migrated = migrate(); !migrated)
        return migrated;
    return checkTables();
}

Error Library::damaged(const QString &why) const
{
    return Error { tr("%1 is damaged: %2. Toffee leaves it as it is and writes nothing into it: restore it "
                      "from a backup (docs/LIBRARY.md), or choose another library.")
                       .arg(m_location.displayName(), why) };
}

Result<void> Library::checkTables() const
{
    const QSqlDatabase db = database();
    // A library read as it is, from before touches were kept, is read without them.
    const auto version = schemaVersion();
    const bool beforeTouches = m_readOnly && version && version.value() < kTouchesVersion;
    const QStringList sinceTouches { u"touches"_s, u"spread"_s, u"repeatability"_s };
    for (const auto &[table, columns] : kTables) {
        const QSqlRecord record = db.record(table);
        if (record.isEmpty())
            return damaged(tr("its table \"%1\" is missing").arg(table));
        for (const QString &column : columns) {
            if (record.indexOf(column) < 0 && !(beforeTouches && sinceTouches.contains(column)))
                return damaged(
                    tr("its table \"%1\" was altered: it has no column \"%2\"").arg(table, column));
        }
    }
    return {};
}

Result<void> Library::checkNotNewer(int version) const
{
    if (version <= kSchemaVersion)
        return {};
    return Error { tr("%1 was written by a newer Toffee (library version %2; this Toffee knows up to %3). It "
                      "was not changed: use a newer Toffee with it, or choose another library.")
                       .arg(m_location.displayName())
                       .arg(version)
                       .arg(kSchemaVersion) };
}

Result<int> Library::schemaVersion() const
{
    const QStringList tables = database().tables();
    if (!tables.contains(u"toffee_schema"_s)) {
        if (!tables.isEmpty())
            return Error { tr("%1 is a database, but not a Toffee library (it has tables of its own). Choose "
                              "another one.")
                               .arg(m_location.displayName()) };
        return 0;
    }
    QSqlQuery query(database());
    if (!query.exec(u"SELECT version FROM toffee_schema"_s))
        return failure(tr("Reading the library's version"), query);
    if (!query.next())
        return damaged(
            tr("its version table (toffee_schema) is empty, so it cannot say which Toffee wrote it"));
    const QVariant value = query.value(0);
    if (query.next())
        return damaged(tr("its version table (toffee_schema) holds more than one version"));
    // A version is a whole number Toffee wrote: 2.5, text, a negative number or one no Toffee reaches is
    // damage, never rounded into a version.
    const auto version = value.isNull() ? std::nullopt : parseInteger(value.toString().toUtf8());
    if (!version || *version < 0 || *version > kLargestPlausibleVersion)
        return damaged(tr("its schema version is \"%1\", which is not a version any Toffee writes")
                           .arg(excerpt(value.isNull() ? u"NULL"_s : value.toString())));
    return int(*version);
}

Result<void> Library::migrate()
{
    if (auto begun = begin(); !begun)
        return begun;
    QSqlQuery query(database());
    auto fail = [&](const QString &what) {
        const Error error = failure(what, query);
        rollback();
        return error;
    };
    // Stations that open a new shared library at once: one brings it up to date, the others wait for it and
    // then find it done. (SQLite's IMMEDIATE transaction already does this.)
    if (m_location.isShared() && !query.exec(u"SELECT pg_advisory_xact_lock(7406113)"_s))
        return fail(tr("Bringing the library up to date"));
    auto version = schemaVersion();
    if (!version) {
        rollback();
        return version.error();
    }
    if (version.value() == 0
        && (!query.exec(u"CREATE TABLE toffee_schema (version INTEGER NOT NULL)"_s)
            || !query.exec(u"INSERT INTO toffee_schema (version) VALUES (0)"_s)))
        return fail(tr("Creating the library"));
    for (int next = version.value() + 1; next <= kSchemaVersion; ++next) {
        for (const QString &statement : kMigrations.at(next - 1)) {
            if (!query.exec(statement))
                return fail(tr("Bringing the library to version %1").arg(next));
        }
    }
    query.prepare(u"UPDATE toffee_schema SET version = ?"_s);
    query.addBindValue(kSchemaVersion);
    if (!query.exec())
        return fail(tr("Bringing the library up to date"));
    return commit();
}

} // namespace Toffee
