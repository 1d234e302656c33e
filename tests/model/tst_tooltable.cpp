// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>

#include <QTest>

#include "tests/support/testtables.h"

#include "model/tooltable.h"

using namespace Toffee;
using Toffee::Test::tool;
using namespace Qt::StringLiterals;

class TestToolTable : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void storesAMeasurementAtTheMachinesResolution()
    {
        // The machine reports MCS Z to 0.001 mm; their difference in doubles is -33.388000000000005, which
        // the table, its file and toffee-cli show once printed.
        const double noisy = -105.688 - -72.3;
        QVERIFY(noisy != -33.388);
        ToolTable mm(Units::Millimetre);
        QVERIFY(mm.recordMeasurement(2, noisy, QDateTime::currentDateTimeUtc()).ok());
        QCOMPARE(*mm.find(2)->measuredTlo, -33.388);
        QVERIFY(writeTable(mm, TableFormat::Json).contains("\"measured_tlo\": -33.388,"));
        // The machine's millimetres become an inch table's inches, at 0.0001 in: 33.388 mm is 1.31449 in.
        ToolTable inch(Units::Inch);
        QVERIFY(inch.recordMeasurement(2, -33.388, QDateTime::currentDateTimeUtc(), TloSource::Probe, -115.34)
                    .ok());
        QCOMPARE(*inch.find(2)->measuredTlo, -1.3145);
        QCOMPARE(*inch.find(2)->referenceMz, -4.5409);
        // And back to a machine in millimetres at its 0.001 mm (-1.3145 in is -33.3883 mm), with how far a
        // machine's value may lie from it and still be it: half an inch table's step more than a mm table's.
        const auto stored = inch.storedTlo(2);
        QVERIFY(stored);
        QCOMPARE(stored->tlo, -33.388);
        QCOMPARE(*stored->referenceMz, -115.339); // -4.5409 in: -115.33886 mm
        QVERIFY(std::fabs(*stored->referenceMz - -115.34) <= stored->sameWithin);
        QCOMPARE(stored->sameWithin, 0.0005 + 0.00127);
        QCOMPARE(mm.storedTlo(2)->sameWithin, 0.0005);
        QVERIFY(!inch.storedTlo(9)); // not in the table
    }

    void aRecordingOfSeveralToolsIsAllOrNothing()
    {
        ToolTable table(Units::Millimetre);
        QVERIFY(table.recordMeasurement(1, 10.0, QDateTime::currentDateTimeUtc()).ok());
        const ToolTable before = table;
        const QDateTime at = QDateTime::currentDateTimeUtc();
        // T3's 5000 mm is beyond any table: T2 before it is not taken either, and the refusal names T3.
        const auto refused = table.recordAll(
            { { 2, 12.5, TloSource::Manual, std::nullopt, std::nullopt, at, RecordingKind::Pulled },
                { 3, 5000.0, TloSource::Manual, std::nullopt, std::nullopt, at, RecordingKind::Pulled } });
        QVERIFY(!refused);
        QVERIFY2(refused.error().text().startsWith(u"T3: "_s), qPrintable(refused.error().text()));
        QCOMPARE(table, before);
        QVERIFY(table
                    .recordAll({ { 2, 12.5, TloSource::Manual, std::nullopt, std::nullopt, at,
                        RecordingKind::Pulled } })
                    .ok());
        QCOMPARE(*table.find(2)->measuredTlo, 12.5);
    }

    void aTotalLengthHasNoBinaryNoise()
    {
        // 41.3 + -0.02 in doubles is 41.279999999999994, which toffee-cli's JSON and the table printed.
        QVERIFY(41.3 + -0.02 != 41.28);
        Tool t;
        t.lengthGeometry = 41.3;
        t.lengthWear = -0.02;
        QVERIFY(t.totalLength() == 41.28);
        t.lengthGeometry = 38.1;
        t.lengthWear = 0.0;
        QVERIFY(t.totalLength() == 38.1);
    }

    void keepsToolsSortedByNumber()
    {
        ToolTable table;
        QVERIFY(table.insert(tool(5)).ok());
        QVERIFY(table.insert(tool(1)).ok());
        QVERIFY(table.insert(tool(3)).ok());
        QCOMPARE(table.size(), 3);
        QCOMPARE(table.at(0).number, 1);
        QCOMPARE(table.at(1).number, 3);
        QCOMPARE(table.at(2).number, 5);
        QCOMPARE(table.indexOf(3), 1);
        QCOMPARE(table.indexOf(4), -1);
        QVERIFY(table.find(5));
        QVERIFY(!table.find(2));
    }

    void refusesDuplicateNumbersAndStaysUnchanged()
    {
        ToolTable table;
        QVERIFY(table.insert(tool(1, 10)).ok());
        const ToolTable before = table;
        const auto r = table.insert(tool(1, 20));
        QVERIFY(!r.ok());
        QVERIFY(r.error().message.contains(u"already in the table"_s));
        QCOMPARE(table, before);
    }

    void refusesAnInvalidValueAndStaysUnchanged()
    {
        ToolTable table;
        QVERIFY(table.insert(tool(1, 10)).ok());
        const ToolTable before = table;
        QVERIFY(!table.insert(tool(2, 5000)).ok());
        QVERIFY(!table.replace(1, tool(1, 5000)).ok());
        QCOMPARE(table, before);
    }

    void replaceCanRenumberButNotOntoAnotherTool()
    {
        ToolTable table;
        QVERIFY(table.insert(tool(1)).ok());
        QVERIFY(table.insert(tool(2)).ok());
        QVERIFY(table.replace(1, tool(7, 3)).ok());
        QCOMPARE(table.at(1).number, 7);
        QCOMPARE(table.at(1).lengthGeometry, 3.0);
        const ToolTable before = table;
        QVERIFY(!table.replace(7, tool(2)).ok());
        QVERIFY(!table.replace(42, tool(42)).ok());
        QCOMPARE(table, before);
    }

    void removesByNumber()
    {
        ToolTable table;
        QVERIFY(table.insert(tool(1)).ok());
        QVERIFY(table.remove(1));
        QVERIFY(!table.remove(1));
        QVERIFY(table.isEmpty());
    }

    void findsTheNextFreeNumber()
    {
        ToolTable table;
        QCOMPARE(table.nextFreeNumber(), 1);
        QVERIFY(table.insert(tool(1)).ok());
        QVERIFY(table.insert(tool(2)).ok());
        QVERIFY(table.insert(tool(4)).ok());
        QCOMPARE(table.nextFreeNumber(), 3);
        QCOMPARE(table.nextFreeNumber(4), 5);
        QVERIFY(table.insert(tool(999999)).ok());
        QCOMPARE(table.nextFreeNumber(999999), -1);
    }

    void fromToolsNamesTheBadTool()
    {
        ToolTable::Problem problem;
        auto r = ToolTable::fromTools({ tool(3), tool(1), tool(2, 1e6) }, Units::Millimetre, &problem);
        QVERIFY(!r.ok());
        QCOMPARE(problem.index, 2);
        QCOMPARE(problem.duplicateOf, -1);
        QCOMPARE(problem.number, 2);
        problem = {};
        r = ToolTable::fromTools({ tool(3), tool(1), tool(5), tool(1) }, Units::Millimetre, &problem);
        QVERIFY(!r.ok());
        QCOMPARE(problem.index, 3); // the second T1, where it stands in the input
        QCOMPARE(problem.duplicateOf, 1);
        QCOMPARE(problem.number, 1);
        r = ToolTable::fromTools({ tool(3), tool(1) }, Units::Inch);
        QVERIFY(r.ok());
        QCOMPARE(r.value().units(), Units::Inch);
        QCOMPARE(r.value().at(0).number, 1);
    }
};

QTEST_GUILESS_MAIN(TestToolTable)
#include "tst_tooltable.moc"
