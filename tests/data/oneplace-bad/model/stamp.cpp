// SPDX-License-Identifier: GPL-3.0-or-later
// tests/oneplace.cmake must refuse this: a time read past the clock's seam, and a length converted past
// units.h.
#include <QDateTime>

QDateTime stamp()
{
    return QDateTime::currentDateTimeUtc();
}

double inchesToMillimetres(double inches)
{
    return inches * 25.4;
}
