// SPDX-License-Identifier: GPL-3.0-or-later
// What tst_jobchecker.cpp and tst_jobcheckerlibrary.cpp share: the shop's table and a check of a program
// against it.
#pragma once

#include "model/job/jobcheck.h"
#include "model/library/library.h"
#include "model/tooltable.h"
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

namespace Toffee::Test {

using namespace Qt::StringLiterals;

inline const QDateTime kNow(QDate(2026, 11, 24), QTime(12, 0), Qt::UTC);

inline Tool cutter(int number, std::optional<double> tlo, int daysAgo, double length = 40.0)
{
    Tool t;
    t.number = number;
    t.pocket = number;
    t.lengthGeometry = length;
    t.measuredTlo = tlo;
    if (tlo)
        t.measuredAt = kNow.addDays(-daysAgo);
    return t;
}

// T1 (reference), T2 (measured 2 days ago), T3 (never measured), T4 (failed its break test), T5 (measured
// 30 days ago), T7 (measured, outside the rack), in mm.
inline ToolTable shopTable()
{
    QList<Tool> tools { cutter(1, 0.0, 1), cutter(2, -33.388, 2), cutter(3, std::nullopt, 0),
        cutter(4, -12.5, 1), cutter(5, -20.0, 30), cutter(7, -5.0, 1) };
    tools[3].breakTestFailed = true;
    return ToolTable::fromTools(tools, Units::Millimetre).value();
}

inline JobReport check(const QByteArray &program, Dialect dialect, const ToolTable &table,
    std::optional<double> zFloor = {}, std::optional<QList<int>> rack = {},
    std::optional<QHash<int, double>> controllerTlos = {})
{
    JobCheckSetup setup;
    setup.dialect = dialect;
    setup.useTable(table);
    setup.zFloor = zFloor;
    setup.rack = rack;
    setup.now = kNow;
    setup.controllerTlos = controllerTlos;
    JobChecker checker(setup);
    int line = 0;
    for (const QByteArray &text : program.split('\n'))
        checker.feed(text, ++line);
    return checker.finish(u"test.nc"_s, false);
}

inline const Finding *find(const JobReport &report, FindingKind kind, int tool = -2)
{
    for (const Finding &f : report.findings) {
        if (f.kind == kind && (tool == -2 || f.tool == tool))
            return &f;
    }
    return nullptr;
}

} // namespace Toffee::Test
