// SPDX-License-Identifier: GPL-3.0-or-later
// Tables for the format tests and the benchmark.
#pragma once

#include <QRandomGenerator>
#include <QTest>

#include "model/formats/tablefile.h"
#include "model/tooltable.h"

namespace Toffee::Test {

// A table through a format and back: the same table, and a second save writes the same bytes.
inline void verifyRoundTrip(const ToolTable &table, TableFormat format)
{
    const QByteArray written = writeTable(table, format);
    const auto read = readTable(written, format, table.units());
    QVERIFY2(read.ok(), qPrintable(read.error().text()));
    QCOMPARE(read.value(), table);
    QCOMPARE(writeTable(read.value(), format), written);
}

// A plain tool for tests that care about the number and the length.
inline Tool tool(int number, double length = 10.0, const QString &description = {})
{
    Tool t;
    t.number = number;
    t.pocket = 1;
    t.lengthGeometry = length;
    t.description = description;
    return t;
}

// A reader's refusal: it failed, on `line`, with a message that contains `message`.
inline void verifyRefused(const Result<ToolTable> &read, int line, const QString &message)
{
    QVERIFY(!read.ok());
    QVERIFY2(read.error().message.contains(message), qPrintable(read.error().message));
    QCOMPARE(read.error().line, line);
}

// Every awkward value a file must carry: quotes, commas, semicolons, non-ASCII text, multi-line notes,
// negative numbers, the limits, a measured TLO with milliseconds, LinuxCNC extras.
inline ToolTable awkwardTable(Units units = Units::Millimetre)
{
    using namespace Qt::StringLiterals;
    QList<Tool> tools;
    Tool t1;
    t1.number = 1;
    t1.pocket = 1;
    t1.description = u"3.175 mm flat, \"2F\"; Ø1/8"_s;
    t1.lengthGeometry = 38.1;
    t1.radiusGeometry = 1.5875;
    t1.measuredTlo = 0.0;
    t1.measuredAt = QDateTime(QDate(2026, 11, 20), QTime(8, 12, 40, 125), Qt::UTC);
    t1.notes = u"Reference tool.\nProbed first, at MCS Z -72.300."_s;
    tools << t1;
    Tool t2;
    t2.number = 2;
    t2.pocket = 7;
    t2.description = u"6 mm end mill"_s;
    t2.lengthGeometry = 71.488;
    t2.measuredTlo = -33.388;
    t2.measuredAt = QDateTime(QDate(2026, 11, 20), QTime(8, 15, 2), Qt::UTC);
    t2.tloSource = TloSource::Manual; // set by hand on the machine
    t2.breakTestFailed = true; // and found broken since
    t2.referenceMz = -72.3; // against the reference tool T1
    t2.cutterType = u"flat end mill, \"2F\""_s; // as the CAM library said
    t2.overallLength = 50.8;
    t2.lifeLimitMinutes = 90.5;
    t2.lifeLimitUses = 40;
    tools << t2;
    Tool t3;
    t3.number = 99999;
    t3.pocket = 99999;
    t3.description = u"big tool number"_s;
    t3.lengthGeometry = units == Units::Inch ? -99.9999 : -999.999;
    t3.radiusGeometry = 0.0625;
    t3.linuxCncExtra = u"X0.25 I95 J155 Q2"_s;
    tools << t3;
    Tool t0;
    t0.number = 0;
    t0.pocket = 0;
    t0.lengthGeometry = 0.1;
    t0.notes = u"  leading and trailing spaces  "_s;
    tools << t0;
    return ToolTable::fromTools(tools, units).takeValue();
}

// What a LinuxCNC table can hold: no wear, TLO or notes.
inline ToolTable linuxCncTable()
{
    ToolTable table = awkwardTable();
    QList<Tool> tools = table.tools();
    for (Tool &tool : tools) {
        tool.measuredTlo.reset();
        tool.measuredAt = {};
        tool.tloSource = TloSource::Probe;
        tool.breakTestFailed = false;
        tool.referenceMz.reset();
        tool.notes.clear();
        tool.cutterType.clear();
        tool.overallLength.reset();
        tool.lifeLimitMinutes.reset();
        tool.lifeLimitUses.reset();
    }
    return ToolTable::fromTools(tools, Units::Millimetre).takeValue();
}

// `count` realistic tools, reproducible from `seed`.
inline ToolTable generatedTable(int count, quint32 seed = 42)
{
    QRandomGenerator random(seed);
    QList<Tool> tools;
    tools.reserve(count);
    auto value = [&random](double limit) {
        return std::round((random.generateDouble() * 2 - 1) * limit * 1000) / 1000;
    };
    for (int i = 0; i < count; ++i) {
        Tool tool;
        tool.number = i + 1;
        tool.pocket = i % 99999 + 1;
        tool.description = QStringLiteral("Tool %1, %2 mm end mill").arg(i + 1).arg(1 + i % 20);
        tool.lengthGeometry = value(200);
        tool.lengthWear = value(0.5);
        tool.radiusGeometry = std::fabs(value(10));
        tool.radiusWear = value(0.05);
        if (i % 3 == 0) {
            tool.measuredTlo = value(100);
            tool.measuredAt = QDateTime(QDate(2026, 11, 1), QTime(8, 0), Qt::UTC).addSecs(i);
        }
        tools.append(std::move(tool));
    }
    return ToolTable::fromTools(std::move(tools), Units::Millimetre).takeValue();
}

} // namespace Toffee::Test
