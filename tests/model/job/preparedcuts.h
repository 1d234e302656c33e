// SPDX-License-Identifier: GPL-3.0-or-later
// What tst_jobpreparer.cpp and tst_jobpreparerrefusals.cpp share: a table, a program prepared, and its cuts
// run again.
#pragma once

#include "model/gcode/gcodeinterpreter.h"
#include "model/job/jobprepare.h"
#include "model/tooltable.h"
#include <QTemporaryDir>
#include <QTest>

namespace Toffee::Test {

using namespace Qt::StringLiterals;

inline const QDateTime kNow(QDate(2026, 11, 24), QTime(12, 0), Qt::UTC);

// T1 the reference, T2 and T7 measured yesterday, T8 measured 30 days ago, T9 never; lengths for G43.
inline ToolTable table()
{
    QList<Tool> tools;
    const struct
    {
        int number;
        std::optional<double> tlo;
        int daysAgo;
        double length;
    } rows[] = { { 1, 0.0, 1, 38.1 }, { 2, -33.388, 1, 71.488 }, { 7, -5.25, 1, 43.35 },
        { 8, -8.0, 30, 46.1 }, { 9, std::nullopt, 0, 52.5 } };
    for (const auto &r : rows) {
        Tool t;
        t.number = r.number;
        t.pocket = r.number;
        t.lengthGeometry = r.length;
        t.measuredTlo = r.tlo;
        if (r.tlo)
            t.measuredAt = kNow.addDays(-r.daysAgo);
        t.referenceMz = -72.3;
        tools << t;
    }
    return ToolTable::fromTools(tools, Units::Millimetre).value();
}

struct Cut
{
    int tool = -1;
    Position work {};
    Position machine {};
};

// Every feed move of `program` as `dialect` runs it with the table's offsets.
inline QList<Cut> cuts(const QByteArray &program, Dialect dialect)
{
    GCodeInterpreter interpreter(dialect, offsetTableFor(table(), dialect));
    interpreter.setRecordMoves(false);
    QList<Cut> out;
    int line = 0;
    for (const QByteArray &text : program.split('\n')) {
        const auto ran = interpreter.runLine(text, ++line);
        if (!ran) {
            qWarning("%s", qPrintable(ran.error().text()));
            return {};
        }
        if (interpreter.lastBlock().motion == BlockEffect::Motion::Feed)
            out.append({ interpreter.loadedTool(), interpreter.workPosition(), interpreter.position() });
    }
    return out;
}

inline QByteArray prepare(const QByteArray &program, PrepareOptions options,
    PrepareSummary *summary = nullptr, QString *error = nullptr)
{
    QTemporaryDir dir;
    const QString in = dir.filePath(u"job.nc"_s);
    const QString out = dir.filePath(u"prepared.nc"_s);
    QFile file(in);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write(program);
    file.close();
    options.now = kNow;
    const auto result = prepareJobFile(in, table(), options, out);
    if (!result) {
        if (error)
            *error = result.error().text();
        return {};
    }
    if (summary)
        *summary = result.value();
    QFile written(out);
    return written.open(QIODevice::ReadOnly) ? written.readAll() : QByteArray();
}

// The prepared program cuts where the original does, each cut with the tool's own offset from the table.
inline void verifyCutsWithEachToolsOffset(
    const QByteArray &original, const QByteArray &prepared, Dialect dialect)
{
    const QList<Cut> before = cuts(original, dialect);
    const QList<Cut> after = cuts(prepared, dialect);
    QVERIFY(!before.isEmpty());
    QCOMPARE(after.size(), before.size());
    const OffsetTable offsets = offsetTableFor(table(), dialect);
    for (qsizetype i = 0; i < after.size(); ++i) {
        QCOMPARE(after.at(i).tool, before.at(i).tool);
        for (size_t axis = 0; axis < 3; ++axis)
            QCOMPARE(after.at(i).work[axis], before.at(i).work[axis]);
        const double expected = offsets.at(after.at(i).tool).length();
        QVERIFY2(std::fabs(after.at(i).machine[2] - after.at(i).work[2] - expected) < 1e-9,
            qPrintable(u"cut %1 of T%2: machine Z %3, work Z %4, offset %5"_s.arg(i)
                           .arg(after.at(i).tool)
                           .arg(after.at(i).machine[2])
                           .arg(after.at(i).work[2])
                           .arg(expected)));
    }
}

// Every line the preparation added or changed says why.
inline void verifyEveryNewLineSaysWhy(const QByteArray &original, const QByteArray &prepared)
{
    const QList<QByteArray> old = original.split('\n');
    for (const QByteArray &line : prepared.split('\n')) {
        if (!old.contains(line))
            QVERIFY2(line.contains("(Toffee: "), line.constData());
    }
}

inline const QByteArray kCarveraJob = "G21 G90\n"
                                      "M6 T2\n" // 2: rack tool
                                      "M3 S12000\n"
                                      "G0 X0 Y0 Z5\n"
                                      "G1 Z-1 F300\n"
                                      "G1 X20\n" // 6: T2's last cut
                                      "G0 Z5\n"
                                      "M6 T7 (the chamfer)\n" // 8: manual, fresh
                                      "M3 S10000\n"
                                      "G1 Z-0.5 F200\n" // 10: T7's last cut
                                      "M5\n"
                                      "M6 T8\n" // 12: manual, stale
                                      "G1 Z-2 F100\n"
                                      "G1 X0\n" // 14: T8's last cut
                                      "M30\n";

} // namespace Toffee::Test
