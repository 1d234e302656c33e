// SPDX-License-Identifier: GPL-3.0-or-later
// The day a test lives in, whatever day it runs: the example table's tools were measured on 2026-11-20, so
// a test that checks their ages sets the clock to the morning after, in its own process and in every program
// it starts (toffee-cli, the window), through the product's one clock (model/clock.h).
#pragma once

#include <QDateTime>

#include "model/clock.h"

namespace Toffee::Test {

inline QDateTime exampleMorningAfter()
{
    return QDateTime(QDate(2026, 11, 21), QTime(9, 0), Qt::UTC);
}

inline void setClock(const QDateTime &at)
{
    Clock::setForTests(at);
    qputenv("TOFFEE_TEST_CLOCK", at.toUTC().toString(Qt::ISODateWithMs).toLatin1());
}

} // namespace Toffee::Test
