// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

#include "model/result.h"

namespace Toffee {

// Where the library is: an SQLite file, named as a path or as "sqlite:PATH", or a PostgreSQL database named
// by a URL, "postgresql://user@host:port/dbname?sslmode=require". Toffee never holds a password: libpq finds
// it in the shop's password file (~/.pgpass, PGPASSFILE) or service file, so a URL with one is refused.
struct LibraryLocation
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::LibraryLocation)

public:
    enum class Kind : quint8 { Sqlite, Postgresql };

    QString path = {}; // the SQLite file, absolute
    Kind kind = Kind::Sqlite;
    // PostgreSQL: each empty one is left to libpq (its environment, service file and defaults).
    QString host = {}; // a name, an address, or a folder holding the server's Unix socket
    int port = 0; // 0: libpq's default
    QString user = {};
    QString database = {};
    QString options
        = {}; // libpq keywords from the URL's query, "sslmode=require;service=shop", as Qt takes them

    [[nodiscard]] static Result<LibraryLocation> parse(const QString &text);
    // The window's <AppDataLocation>/library.sqlite (~/.local/share/Toffee/Toffee/library.sqlite), for the
    // window and toffee-cli alike: where the library lives when nothing else is chosen.
    [[nodiscard]] static LibraryLocation standard();
    [[nodiscard]] bool isShared() const { return kind == Kind::Postgresql; }
    // Names a library at all (a default-made location does not).
    [[nodiscard]] bool isSet() const { return isShared() || !path.isEmpty(); }
    // "sqlite:/home/…/library.sqlite" or "postgresql://…", as a setting or --library takes it back.
    [[nodiscard]] QString text() const;
    // Which library this is, whatever the spelling that named it: an SQLite file by its canonical path (a
    // symlink, a relative path or "a/../b" name the same file), a server's database by its normalised URL.
    // The outbox keeps and finds what waits for a library by it.
    [[nodiscard]] QString identity() const;
    // For messages: the file, or "database shop on host".
    [[nodiscard]] QString displayName() const;
    friend bool operator==(const LibraryLocation &, const LibraryLocation &) = default;
};

} // namespace Toffee
