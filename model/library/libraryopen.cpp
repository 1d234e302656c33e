// SPDX-License-Identifier: GPL-3.0-or-later
// Opening a library, an SQLite file or a PostgreSQL database: what is refused before a byte is written, and
// what a failed connection tells the operator to fix.
#include "model/library/library.h"

#include <QAtomicInt>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// An SQLite file begins with these 16 bytes; anything else at that path is not a library.
bool looksLikeSqlite(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return true; // let SQLite say why it cannot open it
    return file.read(16) == QByteArrayView("SQLite format 3\0", 16);
}

QAtomicInt connectionCount;

QString nextConnectionName()
{
    return u"toffee-library-"_s + QString::number(connectionCount.fetchAndAddRelaxed(1) + 1);
}

Result<void> checkSqlitePath(const QString &path)
{
    const QFileInfo info(path);
    if (info.isDir())
        return Error { Library::tr("%1 is a folder, not a library file. Choose a file in it, such as %2.")
                           .arg(path, QDir(path).filePath(u"library.sqlite"_s)) };
    if (info.exists() && !info.isFile())
        return Error { Library::tr("%1 is not a regular file: a library is an SQLite file.").arg(path) };
    if (info.exists() && info.size() > 0 && !looksLikeSqlite(path))
        return Error { Library::tr(
            "%1 is not a Toffee library: it is not an SQLite database. Choose another file, or move "
            "this one away.")
                           .arg(path) };
    if (!info.exists() && !QDir().mkpath(info.absolutePath()))
        return Error { Library::tr("The folder of %1 cannot be created.").arg(path) };
    if (!QSqlDatabase::isDriverAvailable(u"QSQLITE"_s))
        return Error { Library::tr("Qt's SQLite driver is missing: install libqt6sql6-sqlite.") };
    return {};
}

} // namespace

bool Library::isUnreachable(const QString &why)
{
    // libpq's words for a server that is not there (a socket without a server, a refused or timed-out
    // connection, one closed under it); a wrong password, role, database or encryption is something else.
    static const QStringList kGone = { u"could not connect"_s, u"Connection refused"_s,
        u"No such file or directory"_s, u"timeout expired"_s, u"server closed the connection"_s,
        u"Is the server running"_s, u"the database system is starting up"_s,
        u"the database system is shutting down"_s, u"the database system is in recovery mode"_s,
        u"No route to host"_s, u"Network is unreachable"_s };
    return std::any_of(
        kGone.cbegin(), kGone.cend(), [&why](const QString &gone) { return why.contains(gone); });
}

// What libpq said, turned into what to fix. The server's own words stay at the end, for whoever runs it.
QString Library::explainConnectFailure(const LibraryLocation &location, const QString &why)
{
    const QString where = location.displayName();
    const QString user = location.user.isEmpty() ? tr("your login name") : location.user;
    QString what;
    if (why.contains(u"password authentication failed"_s) || why.contains(u"no password supplied"_s))
        what = tr("The server refused %1's password. Put the right one in the PostgreSQL password file "
                  "(~/.pgpass, or the file PGPASSFILE names): Toffee never stores one.")
                   .arg(user);
    else if (why.contains(u"does not exist"_s) && why.contains(u"database"_s))
        what = tr("The server has no database \"%1\". Check the name in the URL, or have it created "
                  "(createdb %1; docs/LIBRARY.md).")
                   .arg(location.database);
    else if (why.contains(u"role"_s) && why.contains(u"does not exist"_s))
        what = tr("The server has no user \"%1\". Check the user in the URL, or have the role created "
                  "(docs/LIBRARY.md).")
                   .arg(user);
    else if (why.contains(u"translate host name"_s))
        what
            = tr("The server's name \"%1\" is not known here. Check the host in the URL.").arg(location.host);
    else if (why.contains(u"SSL"_s, Qt::CaseInsensitive))
        what = tr("The connection's encryption failed. Check sslmode in the URL against the server's "
                  "settings.");
    else
        what = tr("The server cannot be reached. Check that it is running and that the host and port in the "
                  "URL are right.");
    return tr("The library (%1) cannot be opened. %2 (The server said: %3)").arg(where, what, why.trimmed());
}

Result<std::unique_ptr<Library>> Library::open(const LibraryLocation &location)
{
    return open(location, Options {});
}

Result<std::unique_ptr<Library>> Library::open(const LibraryLocation &location, Options options)
{
    const bool shared = location.isShared();
    if (!shared) {
        if (auto checked = checkSqlitePath(location.path); !checked)
            return checked.error();
    } else if (!QSqlDatabase::isDriverAvailable(u"QPSQL"_s)) {
        return Error { tr("Qt's PostgreSQL driver is missing: install libqt6sql6-psql to use %1.")
                           .arg(location.displayName()) };
    }
    const QString name = nextConnectionName();
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(shared ? u"QPSQL"_s : u"QSQLITE"_s, name);
        if (shared) {
            db.setHostName(location.host);
            if (location.port > 0)
                db.setPort(location.port);
            db.setUserName(location.user);
            db.setDatabaseName(location.database);
            QStringList connect = location.options.split(u';', Qt::SkipEmptyParts);
            connect << u"connect_timeout="_s + QString::number(std::max(1, options.connectTimeoutS));
            // A server whose network went away is noticed in seconds, not at TCP's own timeout (minutes).
            connect << u"keepalives_idle=10"_s << u"keepalives_interval=3"_s << u"keepalives_count=3"_s
                    << u"tcp_user_timeout=10000"_s;
            db.setConnectOptions(connect.join(u';'));
        } else {
            db.setDatabaseName(location.path);
            db.setConnectOptions(u"QSQLITE_BUSY_TIMEOUT="_s + QString::number(options.busyTimeoutMs)
                + (options.readOnly ? u";QSQLITE_OPEN_READONLY"_s : QString()));
        }
        if (!db.open()) {
            const QString why = db.lastError().text();
            db = QSqlDatabase();
            QSqlDatabase::removeDatabase(name);
            Error error { shared ? explainConnectFailure(location, why)
                                 : tr("%1 cannot be opened: %2").arg(location.path, why) };
            if (shared && isUnreachable(why))
                error.code = QString(kUnreachable);
            return error;
        }
    }
    std::unique_ptr<Library> library(new Library(location, name));
    library->m_options = options;
    if (auto prepared = shared ? library->preparePostgres() : library->prepareSqlite(); !prepared)
        return prepared.error();
    return library;
}

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

Error Library::failure(const QString &what, const QSqlQuery &query) const
{
    return failure(what, query.lastError());
}

// What a failed statement means, in Toffee's words first; the driver's own text follows for whoever runs the
// database, and never stands alone.
Error Library::failure(const QString &what, const QSqlError &error) const
{
    const QString code = error.nativeErrorCode();
    const QString text = error.text().trimmed();
    const bool shared = m_location.isShared();
    // SQLite: SQLITE_BUSY, SQLITE_LOCKED. PostgreSQL: lock_timeout, statement_timeout, a deadlock given up.
    const bool busy = shared ? (code == u"55P03"_s || code == u"57014"_s || code == u"40P01"_s)
                             : (code == u"5"_s || code == u"6"_s || text.contains(u"database is locked"_s));
    if (busy) {
        Error e { tr("The library (%1) was busy: another station or program held what Toffee needed (%2) for "
                     "more than %3 s, Toffee's limit.")
                      .arg(m_location.displayName(), what.toLower(),
                          QString::number(double(m_options.busyTimeoutMs) / 1000.0, 'g', 3)) };
        e.code = QString(kBusy);
        return e;
    }
    if (shared && code == u"42501"_s && m_location.isShared())
        return checkWritableFor(true).error();
    const bool schemaGone = shared
        ? (code == u"42P01"_s || code == u"42703"_s)
        : (text.contains(u"no such table"_s) || text.contains(u"no such column"_s)
            || text.contains(u"has no column named"_s) || text.contains(u"Parameter count mismatch"_s));
    if (schemaGone) {
        // SQLite can look now; PostgreSQL's transaction is aborted, so its own words say which.
        if (!shared) {
            if (auto checked = checkTables(); !checked)
                return checked.error();
        }
        return damaged(tr("a table or column Toffee needs is missing (%1)").arg(text));
    }
    return Error { tr("%1: %2 failed: %3")
                       .arg(m_location.displayName(), what,
                           text.isEmpty() ? tr("the database gave no reason") : text) };
}

} // namespace Toffee
