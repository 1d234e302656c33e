// SPDX-License-Identifier: GPL-3.0-or-later
// The job check: every finding, each on its line, against a table. With the history library and at scale:
// tst_jobcheckerlibrary.
#include <cmath>

#include <QTemporaryDir>
#include <QTest>

#include "tests/model/job/jobcheckcases.h"

using namespace Qt::StringLiterals;
using namespace Toffee;
using namespace Toffee::Test;

class TestJobChecker : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void findsEveryToolProblemOnTheLineThatLoadsIt()
    {
        const QByteArray program = "G21 G90\n"
                                   "M6 T2\n" // 2: fine
                                   "G1 Z-1 F300\n"
                                   "M6 T3\n" // 4: never measured
                                   "G1 Z-1\n"
                                   "M6 T4\n" // 6: broken
                                   "G1 Z-1\n"
                                   "M6 T5\n" // 8: stale
                                   "G1 Z-1\n"
                                   "M6 T9\n" // 10: not in the table, and not in the rack
                                   "G1 Z-1\n"
                                   "M6 T7\n" // 12: outside the rack
                                   "G1 Z-1\nM30\n";
        const JobReport r = check(program, Dialect::Carvera, shopTable(), {}, carveraRack());
        QCOMPARE(r.tools.size(), 6);
        QCOMPARE(r.tools.at(0).number, 2);
        QCOMPARE(r.tools.at(4).number, 9);
        QVERIFY(!r.tools.at(4).inTable);
        QCOMPARE(r.tools.at(0).tlo, std::optional(-33.388));
        QCOMPARE(r.tools.at(0).measuredAt, kNow.addDays(-2));
        const Finding *notMeasured = find(r, FindingKind::NotMeasured, 3);
        QVERIFY(notMeasured);
        QCOMPARE(notMeasured->line, 4);
        QCOMPARE(notMeasured->severity(), Severity::Warning);
        const Finding *broken = find(r, FindingKind::BrokenTool, 4);
        QVERIFY(broken);
        QCOMPARE(broken->line, 6);
        QCOMPARE(broken->severity(), Severity::Error);
        const Finding *stale = find(r, FindingKind::StaleTlo, 5);
        QVERIFY(stale);
        QCOMPARE(stale->line, 8);
        QVERIFY2(stale->message.contains(u"30 days ago"_s), qPrintable(stale->message));
        const Finding *missing = find(r, FindingKind::MissingTool, 9);
        QVERIFY(missing);
        QCOMPARE(missing->line, 10);
        QCOMPARE(missing->severity(), Severity::Error);
        QCOMPARE(find(r, FindingKind::ManualChange, 9)->line, 10);
        QCOMPARE(find(r, FindingKind::ManualChange, 7)->line, 12);
        QVERIFY(!find(r, FindingKind::ManualChange, 2));
        QVERIFY(!find(r, FindingKind::StaleTlo, 2));
        QCOMPARE(r.errors(), 2);
        QCOMPARE(r.warnings(), 4);
        QCOMPARE(r.exitCode(), 4);
        // With no rack, every change is manual; with none known, nothing is said of it.
        QCOMPARE(find(check(program, Dialect::Carvera, shopTable(), {}, QList<int> {}),
                     FindingKind::ManualChange, 2)
                     ->line,
            2);
        QVERIFY(!find(check(program, Dialect::Carvera, shopTable()), FindingKind::ManualChange));
        // In line order.
        for (qsizetype i = 1; i < r.findings.size(); ++i)
            QVERIFY(r.findings.at(i - 1).line <= r.findings.at(i).line);
    }

    void aTloSetByHandIsNotShownAsMeasured()
    {
        QList<Tool> tools { cutter(2, -30.488, 0) };
        tools[0].tloSource = TloSource::Manual;
        const JobReport r = check("M6 T2\nG1 Z-1 F100\nM30\n", Dialect::Carvera,
            ToolTable::fromTools(tools, Units::Millimetre).value());
        QVERIFY(r.tools.front().setByHand);
        const Finding *f = find(r, FindingKind::NotMeasured, 2);
        QVERIFY(f);
        QCOMPARE(f->line, 1);
        QVERIFY2(f->message.contains(u"set by hand"_s), qPrintable(f->message));
    }

    void aToolLoadedTwiceIsOneToolWithBothLines()
    {
        const JobReport r
            = check("M6 T2\nG1 X10 F600\nM6 T1\nG1 X0\nM6 T2\nG1 X10\nM30\n", Dialect::Carvera, shopTable());
        QCOMPARE(r.tools.size(), 2);
        QCOMPARE(r.tools.at(0).loadLines, (QList<int> { 1, 5 }));
        QCOMPARE(r.tools.at(0).loads, 2);
        // 10 mm at 600 mm/min is one second, twice.
        QCOMPARE(r.tools.at(0).cuttingSeconds, 2.0);
        QCOMPARE(r.tools.at(0).feedPathMm, 20.0);
        QCOMPARE(r.tools.at(1).cuttingSeconds, 1.0);
        QCOMPARE(r.cuttingSeconds, 3.0);
        QCOMPARE(r.exitCode(), 0);
    }

    void findsFeedsBelowTheFloorWithTheirFirstLines()
    {
        QByteArray program = "M6 T2\nG0 Z5\nG0 Z-30\n"; // a rapid below the floor is not a feed
        for (int i = 0; i < 25; ++i)
            program += "G1 Z-21 F100\nG1 Z-10\n";
        const JobReport r = check(program, Dialect::Carvera, shopTable(), -20.0);
        const Finding *below = find(r, FindingKind::BelowFloor, 2);
        QVERIFY(below);
        QCOMPARE(below->line, 4);
        QCOMPARE(below->lines.size(), JobChecker::kMaxLinesPerFinding);
        QCOMPARE(below->lines.at(1), 6);
        QCOMPARE(below->count, 25); // the plunges; not the moves up from them
        QCOMPARE(r.tools.at(0).lowestZ, std::optional(-21.0));
        QCOMPARE(r.exitCode(), 4);
        const JobReport arc
            = check("M6 T2\nG0 X0 Z-10\nG18 G2 X10 Z-10 R5 F100\n", Dialect::Carvera, shopTable(), -14.0);
        QVERIFY(find(arc, FindingKind::BelowFloor));
        QCOMPARE(arc.tools.at(0).lowestZ, std::optional(-15.0));
        // A drilling cycle's holes go to its Z.
        const JobReport drill = check("T2 M6\nG43 H2 G0 Z10\nG99 G81 X5 Y5 Z-25 R2 F100\nX10\nG80\nM30\n",
            Dialect::Fanuc, shopTable(), -20.0);
        const Finding *hole = find(drill, FindingKind::BelowFloor, 2);
        QVERIFY(hole);
        QCOMPARE(hole->lines, (QList<int> { 3, 4 }));
        QCOMPARE(drill.tools.at(0).lowestZ, std::optional(-25.0));
    }

    // A TLO dated in the future is neither fresh nor "older than the stale limit": it is said as what it is,
    // and never restored in place of a probe.
    void aTloDatedInTheFutureIsNeitherFreshNorStale()
    {
        const QDateTime now(QDate(2026, 11, 21), QTime(9, 0), Qt::UTC);
        ToolFacts facts;
        facts.inTable = true;
        facts.measuredTlo = 12.5;
        facts.referenceMz = -115.34;
        facts.measuredAt = QDateTime(QDate(2100, 1, 1), QTime(0, 0), Qt::UTC);
        QVERIFY(!facts.isFresh(now, 7));
        const auto restorable = restorableTlo(2, facts, now, 7, -115.34);
        QVERIFY(!restorable);
        QVERIFY2(
            restorable.error().message.contains(u"in the future"_s), qPrintable(restorable.error().message));
        QVERIFY(!restorable.error().message.contains(u"older than"_s));
        facts.measuredAt = now.addSecs(-3600);
        QCOMPARE(restorableTlo(2, facts, now, 7, -115.34).value(), 12.5);
    }

    void findsInchesOnTheCarveraAndUnitsThatAreNotTheTables()
    {
        const JobReport carvera = check("G20\nM6 T2\nM30\n", Dialect::Carvera, shopTable());
        QCOMPARE(find(carvera, FindingKind::InchOnCarvera)->line, 1);
        QVERIFY(!find(carvera, FindingKind::UnitsMismatch));
        // An inch table's TLOs on the Carvera are the machine's millimetres all the same: no mismatch.
        Toffee::ToolTable inches(Units::Inch);
        QVERIFY(inches.recordMeasurement(2, 30.0, QDateTime(QDate(2026, 11, 21), QTime(8, 0), Qt::UTC)).ok());
        QVERIFY(!find(check("G21\nM6 T2\nM30\n", Dialect::Carvera, inches), FindingKind::UnitsMismatch));
        const JobReport fanuc = check("G21\nT2 M6\nG20\nM30\n", Dialect::Fanuc, shopTable());
        QCOMPARE(find(fanuc, FindingKind::UnitsMismatch)->line, 3);
        QCOMPARE(find(fanuc, FindingKind::UnitsMismatch)->severity(), Severity::Error);
    }

    void findsLengthCompensationThatIsMissingOrAnotherTools()
    {
        const QByteArray program = "T1 M6\n"
                                   "G43 H1 G0 Z50\n"
                                   "G1 Z-1 F100\n" // 3: fine
                                   "T2 M6\n"
                                   "G0 X5\n"
                                   "G1 Z-2\n" // 6: H1 still in force
                                   "T3 M6\n"
                                   "G49\n"
                                   "G1 Z-3\n" // 9: none
                                   "T5 M6\n"
                                   "G43 H2 Z10\n"
                                   "G1 Z-1\n" // 12: H2, deliberately
                                   "M30\n";
        const JobReport r = check(program, Dialect::Fanuc, shopTable());
        QVERIFY(!find(r, FindingKind::LengthOffsetMismatch, 1));
        const Finding *stale = find(r, FindingKind::LengthOffsetMismatch, 2);
        QCOMPARE(stale->line, 6);
        QVERIFY2(stale->message.contains(u"still in force"_s), qPrintable(stale->message));
        QCOMPARE(find(r, FindingKind::NoLengthCompensation, 3)->line, 9);
        const Finding *other = find(r, FindingKind::LengthOffsetMismatch, 5);
        QCOMPARE(other->line, 11); // G1 is in force: the G43 block feeds
        QVERIFY2(other->message.contains(u"H2"_s), qPrintable(other->message));
        QCOMPARE(r.exitCode(), 1);
        // LinuxCNC: G43 without H takes the loaded tool; FAGOR: D names the offset.
        QCOMPARE(check("T2 M6\nG43\nG1 Z-1 F100\nM30\n", Dialect::LinuxCnc, shopTable()).findings.size(), 0);
        const JobReport fagor = check("T2 D3 M6\nG43\nG1 Z-1 F100\nM30\n", Dialect::Fagor8055M, shopTable());
        QVERIFY(find(fagor, FindingKind::LengthOffsetMismatch, 2)->message.contains(u"D3"_s));
        // The Carvera and Automation1 have no G43 to check.
        QVERIFY(!find(
            check("M6 T2\nG1 Z-1 F100\n", Dialect::Carvera, shopTable()), FindingKind::NoLengthCompensation));
    }

    void findsEveryLineTheControllerRefusesAndCountsBeyondAHundred()
    {
        QByteArray program = "M6 T2\n";
        for (int i = 0; i < 250; ++i)
            program += "G1 X1 Y1 G7\n";
        const JobReport r = check(program, Dialect::Fanuc, shopTable());
        QCOMPARE(r.errors(), JobChecker::kMaxProgramErrors + 1);
        QCOMPARE(r.findings.at(0).line, 2);
        QVERIFY2(r.findings.at(0).message.contains(u"G7"_s), qPrintable(r.findings.at(0).message));
        const Finding &rest = r.findings.constLast();
        QCOMPARE(rest.kind, FindingKind::ProgramError);
        QCOMPARE(rest.line, 102);
        QCOMPARE(rest.count, 150);
    }

    void aFeedBeforeAnyToolChangeIsPointedOut()
    {
        const JobReport r = check("G1 X10 F100\nG1 X20\nM6 T2\nM30\n", Dialect::Carvera, shopTable());
        const Finding *f = find(r, FindingKind::NoToolLoaded);
        QCOMPARE(f->line, 1);
        QCOMPARE(f->count, 2);
        QCOMPARE(r.exitCode(), 1);
    }

    void grblHalProgramsAreCheckedAgainstTheMeasuredTlosAndTheControllersTable()
    {
        // LinuxCNC's words (M6 T, then G43 H): a change without its own G43 H is a finding (the H before
        // stays in force), as on any G43 controller.
        const QByteArray program = "G21 G90\nM6 T2\nG43 H2\nG1 Z-1 F100\nM6 T7\nG1 Z-1\nM6 T3\nG43 H3\n"
                                   "G1 Z-1\nM30\n";
        const JobReport plain = check(program, Dialect::GrblHal, shopTable());
        const Finding *stale = find(plain, FindingKind::LengthOffsetMismatch, 7);
        QVERIFY(stale);
        QCOMPARE(stale->line, 6);
        // The TLO is Toffee's measured one, as on the Carvera: T3 has a length but no measured TLO.
        QVERIFY(find(plain, FindingKind::NotMeasured, 3));
        QCOMPARE(plain.tools.at(0).tlo, std::optional(-33.388));
        QVERIFY(!find(plain, FindingKind::ControllerTableDiffers));

        // Read from the controller: T2's entry differs, T7's agrees; T3 has no TLO to compare.
        const JobReport read = check(program, Dialect::GrblHal, shopTable(), {}, {},
            QHash<int, double> { { 2, -30.0 }, { 7, -5.0 }, { 3, 0.0 } });
        const Finding *differs = find(read, FindingKind::ControllerTableDiffers, 2);
        QVERIFY(differs);
        QCOMPARE(differs->severity(), Severity::Warning);
        QCOMPARE(differs->line, 2);
        QVERIFY2(differs->message.contains(u"-30.000"_s) && differs->message.contains(u"-33.388"_s),
            qPrintable(differs->message));
        QVERIFY(!find(read, FindingKind::ControllerTableDiffers, 7));
        QVERIFY(!find(read, FindingKind::ControllerTableDiffers, 3));
        // A tool beyond the controller's table is said too.
        const JobReport beyond = check("M6 T2\nG43 H2\nG1 Z-1 F100\nM30\n", Dialect::GrblHal, shopTable(), {},
            {}, QHash<int, double> {});
        const Finding *missing = find(beyond, FindingKind::ControllerTableDiffers, 2);
        QVERIFY(missing);
        QVERIFY(missing->message.contains(u"has no T2"_s));
    }

    void aTloTheProgramSetsAZeroToolAndAFutureDateAreToldApart()
    {
        // The program sets T2's TLO by hand to another value than the table's; T0 is the probe, not looked
        // up.
        const JobReport carvera
            = check("M6 T2 H-30\nG1 Z-1 F100\nM493.3 Z-33.388\nM6 T0\nM30\n", Dialect::Carvera, shopTable());
        const Finding *set = find(carvera, FindingKind::ProgramSetsTlo, 2);
        QVERIFY(set);
        QCOMPARE(set->line, 1);
        QCOMPARE(set->count, 1); // line 3 sets the table's own value
        QVERIFY2(set->message.contains(u"-30.000"_s) && set->message.contains(u"-33.388"_s),
            qPrintable(set->message));
        QVERIFY(!find(carvera, FindingKind::MissingTool, 0));
        // LinuxCNC's T0 is the empty spindle: no finding for it.
        QCOMPARE(check("T0 M6\nM2\n", Dialect::LinuxCnc, shopTable()).findings.size(), 0);
        // A TLO dated in the future is not fresh: the clock was wrong.
        QList<Tool> tools { cutter(2, -33.388, 0) };
        tools[0].measuredAt = kNow.addDays(400);
        const JobReport future = check(
            "M6 T2\nG1 Z-1 F100\n", Dialect::Carvera, ToolTable::fromTools(tools, Units::Millimetre).value());
        QVERIFY(find(future, FindingKind::StaleTlo, 2)->message.contains(u"in the future"_s));
        QVERIFY(find(check("G21\nT2 M6\nG20\n", Dialect::Fanuc, shopTable()), FindingKind::UnitsMismatch)
                    ->message.startsWith(u"The program is in inches (G20)"_s));
    }

    void nothingAfterTheEndRuns()
    {
        const JobReport r = check("M6 T2\nM30\nM6 T99\nG7\n", Dialect::Carvera, shopTable());
        QCOMPARE(r.tools.size(), 1);
        QCOMPARE(r.lines, 2);
        QCOMPARE(r.exitCode(), 0);
    }
};

QTEST_GUILESS_MAIN(TestJobChecker)
#include "tst_jobchecker.moc"
