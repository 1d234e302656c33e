// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

#include "model/result.h"

namespace Toffee {

// Where the history library is: an SQLite file, named as a path or as "sqlite:PATH". A "postgresql://…" URL
// is the shared library of a later version, refused here with a message that says so.
struct LibraryLocation
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::LibraryLocation)

public:
    QString path; // the SQLite file, absolute

    [[nodiscard]] static Result<LibraryLocation> parse(const QString &text);
    // The window's <AppDataLocation>/library.sqlite (~/.local/share/Toffee/Toffee/library.sqlite), for the
    // window and toffee-cli alike: where the library lives when nothing else is chosen.
    [[nodiscard]] static LibraryLocation standard();
    // "sqlite:/home/…/library.sqlite", as a setting or --library takes it back.
    [[nodiscard]] QString text() const;
};

} // namespace Toffee
