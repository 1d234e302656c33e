// SPDX-License-Identifier: GPL-3.0-or-later
// Opening a library: what is refused before a byte is written, and the schema brought up to date.
#include "model/library/library.h"

#include <QAtomicInt>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSqlDatabase>
#include <QSqlDriver>
#include <QSqlError>
#include <QSqlQuery>
#include <QVariant>

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
};

// An SQLite file begins with these 16 bytes; anything else at that path is not a library.
bool looksLikeSqlite(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return true; // let SQLite say why it cannot open it
    return file.read(16) == QByteArrayView("SQLite format 3\0", 16);
}

QAtomicInt connectionCount;

} // namespace

Library::Library(LibraryLocation location, QString connection)
    : m_location(std::move(location))
    , m_connection(std::move(connection))
{ }

Library::~Library()
{
    {
        QSqlDatabase db = QSqlDatabase::database(m_connection, false);
        db.close();
    }
    QSqlDatabase::removeDatabase(m_connection);
}

QSqlDatabase Library::database() const
{
    return QSqlDatabase::database(m_connection, false);
}

Result<std::unique_ptr<Library>> Library::open(const LibraryLocation &location)
{
    return open(location, Options {});
}

Result<std::unique_ptr<Library>> Library::open(const LibraryLocation &location, Options options)
{
    const QString &path = location.path;
    const QFileInfo info(path);
    if (info.isDir())
        return Error { tr("%1 is a folder, not a library file. Choose a file in it, such as %2.")
                           .arg(path, QDir(path).filePath(u"library.sqlite"_s)) };
    if (info.exists() && !info.isFile())
        return Error { tr("%1 is not a regular file: a library is an SQLite file.").arg(path) };
    if (info.exists() && info.size() > 0 && !looksLikeSqlite(path))
        return Error { tr(
            "%1 is not a Toffee library: it is not an SQLite database. Choose another file, or move "
            "this one away.")
                           .arg(path) };
    if (!info.exists() && !QDir().mkpath(info.absolutePath()))
        return Error { tr("The folder of %1 cannot be created.").arg(path) };
    if (!QSqlDatabase::isDriverAvailable(u"QSQLITE"_s))
        return Error { tr("Qt's SQLite driver is missing: install libqt6sql6-sqlite.") };

    const QString name = u"toffee-library-"_s + QString::number(connectionCount.fetchAndAddRelaxed(1) + 1);
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(u"QSQLITE"_s, name);
        db.setDatabaseName(path);
        db.setConnectOptions(u"QSQLITE_BUSY_TIMEOUT="_s + QString::number(options.busyTimeoutMs));
        if (!db.open()) {
            const QString why = db.lastError().text();
            db = QSqlDatabase();
            QSqlDatabase::removeDatabase(name);
            return Error { tr("%1 cannot be opened: %2").arg(path, why) };
        }
    }
    std::unique_ptr<Library> library(new Library(location, name));
    if (auto prepared = library->prepare(); !prepared)
        return prepared.error();
    return library;
}

Error Library::failure(const QString &what, const QSqlQuery &query) const
{
    return Error { tr("%1: %2 failed: %3").arg(m_location.path, what, query.lastError().text()) };
}

Result<void> Library::prepare()
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
    if (version.value() > kSchemaVersion)
        return Error { tr(
            "%1 was written by a newer Toffee (library version %2; this Toffee knows up to %3). It was "
            "not changed: use a newer Toffee with it, or choose another library.")
                           .arg(m_location.path)
                           .arg(version.value())
                           .arg(kSchemaVersion) };
    // WAL lets the window read while toffee-cli writes, and the other way round; a read-only file stays in
    // the mode it has, and is still read.
    (void)query.exec(u"PRAGMA journal_mode = WAL"_s);
    // In WAL mode, NORMAL keeps every committed event through a crash of the program (it only waits for the
    // disk at checkpoints): a power cut may lose the last ones, not the library.
    (void)query.exec(u"PRAGMA synchronous = NORMAL"_s);
    if (!query.exec(u"PRAGMA foreign_keys = ON"_s))
        return failure(tr("Reading the library"), query);
    return migrate(version.value());
}

Result<int> Library::schemaVersion() const
{
    const QStringList tables = database().tables();
    if (!tables.contains(u"toffee_schema"_s)) {
        if (!tables.isEmpty())
            return Error { tr(
                "%1 is an SQLite database, but not a Toffee library (it has tables of its own). "
                "Choose another file.")
                               .arg(m_location.path) };
        return 0;
    }
    QSqlQuery query(database());
    if (!query.exec(u"SELECT version FROM toffee_schema"_s) || !query.next())
        return failure(tr("Reading the library's version"), query);
    return query.value(0).toInt();
}

Result<void> Library::migrate(int version)
{
    if (version == kSchemaVersion)
        return {};
    QSqlDatabase db = database();
    if (!db.transaction())
        return Error { tr("%1 cannot be written: %2").arg(m_location.path, db.lastError().text()) };
    QSqlQuery query(db);
    auto fail = [&](const QString &what) {
        const Error error = failure(what, query);
        db.rollback();
        return error;
    };
    if (version == 0
        && (!query.exec(u"CREATE TABLE toffee_schema (version INTEGER NOT NULL)"_s)
            || !query.exec(u"INSERT INTO toffee_schema (version) VALUES (0)"_s)))
        return fail(tr("Creating the library"));
    for (int next = version + 1; next <= kSchemaVersion; ++next) {
        for (const QString &statement : kMigrations.at(next - 1)) {
            if (!query.exec(statement))
                return fail(tr("Bringing the library to version %1").arg(next));
        }
    }
    query.prepare(u"UPDATE toffee_schema SET version = ?"_s);
    query.addBindValue(kSchemaVersion);
    if (!query.exec())
        return fail(tr("Bringing the library up to date"));
    if (!db.commit())
        return Error { tr("%1 cannot be written: %2").arg(m_location.path, db.lastError().text()) };
    return {};
}

} // namespace Toffee
