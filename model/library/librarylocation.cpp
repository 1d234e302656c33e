// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/librarylocation.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QUrl>
#include <QUrlQuery>

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// The libpq connection keywords a URL's query may carry; Qt's QPSQL passes them on as they are. "host" names
// a Unix socket's folder, which a URL cannot hold in its authority without escaping.
const QStringList kPostgresKeywords = { u"host"_s, u"port"_s, u"sslmode"_s, u"sslrootcert"_s, u"sslcert"_s,
    u"sslkey"_s, u"service"_s, u"connect_timeout"_s, u"application_name"_s, u"target_session_attrs"_s };

Result<LibraryLocation> parsePostgres(const QString &text)
{
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid())
        return Error { LibraryLocation::tr("%1 is not a valid PostgreSQL URL (%2). Write it as "
                                           "postgresql://user@host:port/dbname.")
                           .arg(text, url.errorString()) };
    if (!url.password().isEmpty())
        return Error { LibraryLocation::tr(
            "%1 holds a password. Toffee never stores one: take it out of the URL and put it in the "
            "PostgreSQL password file (~/.pgpass, or the file PGPASSFILE names).")
                           .arg(url.toString(QUrl::RemovePassword)) };
    LibraryLocation location;
    location.kind = LibraryLocation::Kind::Postgresql;
    location.host = url.host();
    location.port = url.port(0);
    location.user = url.userName();
    location.database = url.path().mid(1);
    if (location.database.isEmpty())
        return Error { LibraryLocation::tr("%1 names no database: write it after the host, as in "
                                           "postgresql://toffee@server/tools.")
                           .arg(text) };
    if (location.database.contains(u'/'))
        return Error { LibraryLocation::tr("%1: the database is named by one path part, as in "
                                           "postgresql://host/dbname.")
                           .arg(text) };
    QStringList options;
    for (const auto &[key, value] : QUrlQuery(url).queryItems(QUrl::FullyDecoded)) {
        if (!kPostgresKeywords.contains(key))
            return Error { LibraryLocation::tr("%1: \"%2\" is not a connection setting Toffee passes on (it "
                                               "takes %3).")
                               .arg(text, key, kPostgresKeywords.join(u", "_s)) };
        if (key == u"host"_s)
            location.host = value;
        else if (key == u"port"_s)
            location.port = value.toInt();
        else
            options << key + u'=' + value;
    }
    if (location.port < 0 || location.port > 65535)
        return Error { LibraryLocation::tr("%1: the port must be between 1 and 65535.").arg(text) };
    location.options = options.join(u';');
    return location;
}

} // namespace

Result<LibraryLocation> LibraryLocation::parse(const QString &text)
{
    QString path = text.trimmed();
    if (path.startsWith(u"postgresql://"_s) || path.startsWith(u"postgres://"_s))
        return parsePostgres(path);
    if (path.startsWith(u"sqlite:"_s))
        path = path.mid(7);
    if (path.isEmpty())
        return Error { tr("No library was given: name an SQLite file, such as sqlite:library.sqlite, or a "
                          "PostgreSQL database, such as postgresql://toffee@server/tools.") };
    if (const qsizetype colon = path.indexOf(u"://"_s); colon > 0)
        return Error { tr("%1: Toffee reads a library from an SQLite file (a path, or sqlite:PATH) or from "
                          "PostgreSQL (postgresql://…), not from \"%2\".")
                           .arg(text, path.left(colon)) };
    return LibraryLocation { .path = QFileInfo(path).absoluteFilePath() };
}

// The window's AppDataLocation, whichever program asks: toffee-cli must find the library the window writes.
LibraryLocation LibraryLocation::standard()
{
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation);
    return LibraryLocation { .path = QDir(folder).absoluteFilePath(u"Toffee/Toffee/library.sqlite"_s) };
}

QString LibraryLocation::identity() const
{
    if (kind != Kind::Sqlite)
        return text();
    const QFileInfo file(path);
    const QString canonical = file.canonicalFilePath(); // empty when it does not exist yet
    if (!canonical.isEmpty())
        return u"sqlite:"_s + canonical;
    // Not made yet: its folder's canonical path, and its name.
    const QString folder = QFileInfo(file.absolutePath()).canonicalFilePath();
    return u"sqlite:"_s
        + (folder.isEmpty() ? QDir::cleanPath(file.absoluteFilePath())
                            : QDir(folder).filePath(file.fileName()));
}

QString LibraryLocation::text() const
{
    if (kind == Kind::Sqlite)
        return u"sqlite:"_s + path;
    // Written by hand: QUrl drops an authority that has a user and no host, which is libpq's
    // "postgresql://toffee@/tools" (the local socket).
    const auto encode = [](const QString &s) {
        return QString::fromLatin1(QUrl::toPercentEncoding(s));
    };
    const bool socket = host.startsWith(u'/');
    QString out = u"postgresql://"_s;
    if (!user.isEmpty())
        out += encode(user) + u'@';
    if (!socket)
        out += host.contains(u':') ? u'[' + host + u']' : encode(host);
    if (port > 0 && !socket)
        out += u':' + QString::number(port);
    out += u'/' + encode(database);
    QStringList query;
    if (socket)
        query << u"host="_s + encode(host);
    if (port > 0 && socket)
        query << u"port="_s + QString::number(port);
    for (const QString &option : options.split(u';', Qt::SkipEmptyParts))
        query << encode(option.section(u'=', 0, 0)) + u'=' + encode(option.section(u'=', 1));
    if (!query.isEmpty())
        out += u'?' + query.join(u'&');
    return out;
}

QString LibraryLocation::displayName() const
{
    if (kind == Kind::Sqlite)
        return path;
    QString server = host.isEmpty() ? tr("the local server") : host;
    if (port > 0)
        server += u':' + QString::number(port); // a server on another port is another server
    return tr("database %1 on %2").arg(database, server);
}

} // namespace Toffee
