// SPDX-License-Identifier: GPL-3.0-or-later
// tests/oneclock.cmake must refuse this: a time read past the seam.
#include <QDateTime>

QDateTime stamp()
{
    return QDateTime::currentDateTimeUtc();
}
