// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/librarylocation.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

using namespace Qt::StringLiterals;

namespace Toffee {

Result<LibraryLocation> LibraryLocation::parse(const QString &text)
{
    QString path = text.trimmed();
    if (path.startsWith(u"postgresql://"_s) || path.startsWith(u"postgres://"_s))
        return Error { tr(
            "%1: a shared library on PostgreSQL is not supported by this version of Toffee; use an "
            "SQLite file (a path, or sqlite:PATH).")
                           .arg(text) };
    if (path.startsWith(u"sqlite:"_s))
        path = path.mid(7);
    if (path.isEmpty())
        return Error { tr("No library file was given: name an SQLite file, such as sqlite:library.sqlite.") };
    if (const qsizetype colon = path.indexOf(u"://"_s); colon > 0)
        return Error { tr("%1: Toffee reads a library from an SQLite file (a path, or sqlite:PATH), not from "
                          "\"%2\".")
                           .arg(text, path.left(colon)) };
    return LibraryLocation { QFileInfo(path).absoluteFilePath() };
}

// The window's AppDataLocation, whichever program asks: toffee-cli must find the library the window writes.
LibraryLocation LibraryLocation::standard()
{
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation);
    return LibraryLocation { QDir(folder).absoluteFilePath(u"Toffee/Toffee/library.sqlite"_s) };
}

QString LibraryLocation::text() const
{
    return u"sqlite:"_s + path;
}

} // namespace Toffee
