// SPDX-License-Identifier: GPL-3.0-or-later
// A machinist's day with toffee-cli (issue 30): a new cutter is a new tool, by hand and by a CAM import that
// changes a tool's cutter; tool life with limits, counted from the history's program runs, reset by a new
// cutter. At each step: what the command says, what the file holds and what the history holds.
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "model/formats/tablefile.h"
#include "model/library/library.h"
#include "tests/support/camfiles.h"
#include "tests/support/processes.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::cli;
using Toffee::Test::Run;

namespace {

// The shop's table: T3 a 2 mm ball, measured, worn a little and marked broken; T1 the reference.
ToolTable shopTable()
{
    Tool t1;
    t1.number = 1;
    t1.description = u"6 mm flat"_s;
    t1.radiusGeometry = 3.0;
    t1.measuredTlo = 0.0;
    t1.measuredAt = QDateTime::currentDateTimeUtc().addSecs(-600);
    t1.referenceMz = -101.5;
    Tool t3;
    t3.number = 3;
    t3.description = u"2 mm ball"_s;
    t3.radiusGeometry = 1.0;
    t3.lengthGeometry = 71.488; // the old cutter's length, as a LinuxCNC table or FANUC's offset has it
    t3.lengthWear = 0.02;
    t3.measuredTlo = -30.2;
    t3.measuredAt = QDateTime::currentDateTimeUtc().addSecs(-600);
    t3.referenceMz = -101.5;
    t3.breakTestFailed = true;
    return ToolTable::fromTools({ t1, t3 }, Units::Millimetre).value();
}

QJsonObject json(const Run &run)
{
    return QJsonDocument::fromJson(run.out).object();
}

QList<HistoryEvent> events(const QString &library, int tool)
{
    auto opened = Library::open({ library });
    if (!opened)
        return {};
    return opened.value()->history({ u"Carvera"_s, tool, {}, 0 }).value();
}

} // namespace

class TestMachinistCli : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void aNewCutterByHandEndsTheOldOnesValues()
    {
        QTemporaryDir dir;
        const QString table = dir.filePath(u"shop.json"_s);
        const QString library = dir.filePath(u"library.sqlite"_s);
        const ToolTable shop = shopTable();
        QVERIFY(saveTableFile(table, shop, TableFormat::Json).ok());

        // A tool the table lacks: said, nothing written.
        const QByteArray before = Test::readFile(table);
        Run run = cli({ u"new-cutter"_s, u"7"_s, u"--table"_s, table, u"--library"_s, library });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("T7 is not in"), run.err.constData());
        QCOMPARE(Test::readFile(table), before);

        run = cli({ u"new-cutter"_s, u"3"_s, u"--table"_s, table, u"--library"_s, library });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(
            run.out.contains("the old cutter's TLO -30.200 mm is no longer stored"), run.out.constData());
        QVERIFY2(
            run.out.contains("its length 71.488 mm (the old cutter's, which G43 would apply to the new one) "
                             "is reset to 0"),
            run.out.constData());
        QVERIFY(run.out.contains("its wear (length 0.020, radius 0.000) is reset to 0"));
        QVERIFY(run.out.contains("its break-test mark is cleared"));
        QVERIFY(run.out.contains("measure T3 on the tool setter before it cuts"));
        // The file: T3 is a tool to measure, its number, pocket, description and radius kept; T1 untouched.
        const ToolTable after = loadTableFile(table).value();
        const Tool &t3 = *after.find(3);
        QVERIFY(!t3.measuredTlo);
        QVERIFY(!t3.measuredAt.isValid());
        QVERIFY(!t3.referenceMz);
        QVERIFY(!t3.breakTestFailed);
        QCOMPARE(t3.lengthWear, 0.0);
        QCOMPARE(t3.lengthGeometry, 0.0);
        QCOMPARE(t3.description, u"2 mm ball"_s);
        QCOMPARE(t3.radiusGeometry, 1.0);
        QCOMPARE(*after.find(1), *shop.find(1));
        // The history: the old cutter's TLO, ended.
        const QList<HistoryEvent> history = events(library, 3);
        QCOMPARE(history.size(), 1);
        QCOMPARE(history.front().kind, EventKind::NewCutter);
        QCOMPARE(history.front().oldTlo, std::optional(-30.2));
        QCOMPARE(history.front().referenceMz, std::optional(-101.5)); // what that TLO was measured against
        run = cli({ u"--json"_s, u"history"_s, u"--tool"_s, u"3"_s, u"--library"_s, library });
        QCOMPARE(json(run).value(u"events"_s).toArray().at(0).toObject().value(u"kind"_s).toString(),
            u"new_cutter"_s);
        run = cli({ u"history"_s, u"--tool"_s, u"3"_s, u"--library"_s, library });
        QVERIFY2(run.out.contains("new_cutter  old cutter's TLO -30.200 ended"), run.out.constData());

        // The job check then calls T3 unmeasured, not measured and fresh.
        const QString program = dir.filePath(u"job.nc"_s);
        QVERIFY(Test::writeFile(program, "G21 G90\nM6 T3\nG0 X0 Y0 Z5\nG1 Z-1 F300\nG1 X10 F600\nM30\n"));
        run = cli(
            { u"--json"_s, u"job"_s, u"check"_s, program, u"--table"_s, table, u"--library"_s, library });
        const QJsonArray findings = json(run).value(u"findings"_s).toArray();
        QVERIFY2(std::any_of(findings.begin(), findings.end(),
                     [](const QJsonValue &f) {
                         return f.toObject().value(u"kind"_s).toString() == u"not_measured"_s
                             && f.toObject().value(u"tool"_s).toInt() == 3;
                     }),
            run.out.constData());
        // On LinuxCNC and FANUC, G43 applies the table's length, the old cutter's until now: none is left.
        for (const QString &dialect : { u"linuxcnc"_s, u"fanuc"_s }) {
            run = cli({ u"--json"_s, u"job"_s, u"check"_s, program, u"--table"_s, table, u"--library"_s,
                library, u"--dialect"_s, dialect });
            const QJsonArray found = json(run).value(u"findings"_s).toArray();
            QVERIFY2(std::any_of(found.begin(), found.end(),
                         [](const QJsonValue &f) {
                             return f.toObject().value(u"message"_s).toString()
                                 == u"T3 has no length in the table: G43 would apply 0."_s;
                         }),
                run.out.constData());
        }
    }

    void anImportThatChangesACutterPutsInANewOneAndSaysSo()
    {
        QTemporaryDir dir;
        const QString table = dir.filePath(u"shop.json"_s);
        const QString library = dir.filePath(u"library.sqlite"_s);
        const QString source = dir.filePath(u"library.json"_s);
        QVERIFY(saveTableFile(table, shopTable(), TableFormat::Json).ok());
        // T3 is now a 6 mm flat; T1 the same 6 mm cutter as before.
        QVERIFY(Test::writeFile(source,
            Test::fusionLibrary({ Test::fusionTool(1, "6 mm flat"), Test::fusionTool(3, "6 mm flat") })));

        const QByteArray before = Test::readFile(table);
        Run run = cli({ u"--json"_s, u"import"_s, source, u"--into"_s, table, u"--dry-run"_s, u"--library"_s,
            library });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run).value(u"new_cutters"_s).toArray(), QJsonArray({ 3 }));
        QCOMPARE(Test::readFile(table), before); // a dry run writes nothing, in the file or the history
        QVERIFY(events(library, 3).isEmpty());

        run = cli({ u"import"_s, source, u"--into"_s, table, u"--library"_s, library });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        // The preview says it per tool, with the old cutter's TLO.
        QVERIFY2(
            run.out.contains("note: a new cutter (diameter 2.000 → 6.000 mm): the old cutter's TLO "
                             "-30.200 mm, its length, wear and break mark end; measure it before it cuts"),
            run.out.constData());
        QVERIFY(run.out.contains("a new cutter in 1 (measure before use)"));
        const ToolTable after = loadTableFile(table).value();
        QVERIFY(!after.find(3)->measuredTlo);
        QCOMPARE(after.find(3)->lengthWear, 0.0);
        QVERIFY(!after.find(3)->breakTestFailed);
        QCOMPARE(after.find(3)->radiusGeometry, 3.0);
        QCOMPARE(after.find(3)->cutterType, u"flat end mill"_s);
        QCOMPARE(after.find(3)->overallLength, std::optional(50.0));
        // T1 kept its measured TLO: the same cutter.
        QCOMPARE(after.find(1)->measuredTlo, std::optional(0.0));
        const QList<HistoryEvent> history = events(library, 3);
        QCOMPARE(history.size(), 1);
        QCOMPARE(history.front().kind, EventKind::NewCutter);
        QCOMPARE(history.front().oldTlo, std::optional(-30.2));
        QVERIFY(events(library, 1).isEmpty());

        // Imported again: the same cutters, nothing new.
        run = cli({ u"--json"_s, u"import"_s, source, u"--into"_s, table, u"--library"_s, library });
        QCOMPARE(json(run).value(u"new_cutters"_s).toArray(), QJsonArray());
        // Then the CAM says T3's overall length is 10 mm longer: another cutter of the same type and size.
        QVERIFY(Test::writeFile(source,
            Test::fusionLibrary({ Test::fusionTool(3, "6 mm flat", "millimeters",
                R"("DC": 6, "SFDM": 6, "OAL": 60, "LCF": 20, "LB": 30, "NOF": 3, "RE": 0)") })));
        run = cli({ u"--json"_s, u"import"_s, source, u"--into"_s, table, u"--library"_s, library });
        QCOMPARE(json(run).value(u"new_cutters"_s).toArray(), QJsonArray({ 3 }));
        QCOMPARE(events(library, 3).size(), 2);
    }

    void aFusionToolWithoutUnitIsPreviewedInTheUnitTheOperatorSays()
    {
        QTemporaryDir dir;
        const QString table = dir.filePath(u"shop.json"_s);
        const QString source = dir.filePath(u"library.json"_s);
        QVERIFY(saveTableFile(table, shopTable(), TableFormat::Json).ok());
        const QByteArray noUnit = QByteArray(
            Test::fusionTool(8, "1/4 in flat", "millimeters", R"("DC": 0.25, "OAL": 2.5, "LCF": 1)"))
                                      .replace(R"("unit": "millimeters",)", "");
        QVERIFY(Test::writeFile(source, Test::fusionLibrary({ noUnit })));
        const QByteArray before = Test::readFile(table);
        // Without an answer: what the file needs and how to go on, nothing written.
        Run run = cli({ u"import"_s, source, u"--into"_s, table });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("Tools in this library without \"unit\" (millimeters or inches): T8."),
            run.err.constData());
        QVERIFY(run.err.contains("--cam-units mm|in"));
        QCOMPARE(Test::readFile(table), before);
        // With one: the preview first (a dry run), the tool read in inches, and said so.
        run = cli({ u"import"_s, source, u"--into"_s, table, u"--cam-units"_s, u"in"_s, u"--dry-run"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(
            run.out.contains("note: the library gives no unit: its lengths are read in inches, as you said"),
            run.out.constData());
        QCOMPARE(Test::readFile(table), before);
        run = cli({ u"import"_s, source, u"--into"_s, table, u"--cam-units"_s, u"in"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(loadTableFile(table).value().find(8)->radiusGeometry, 3.175); // 1/4 in across, in a mm table
        QCOMPARE(cli({ u"import"_s, source, u"--into"_s, table, u"--cam-units"_s, u"cm"_s }).exitCode, 2);
    }

    void toolLifeCountsTheCuttersRunsAndANewCutterStartsItAgain()
    {
        QTemporaryDir dir;
        const QString table = dir.filePath(u"shop.json"_s);
        const QString library = dir.filePath(u"library.sqlite"_s);
        const QString program = dir.filePath(u"pocket.nc"_s);
        ToolTable tools = shopTable();
        Tool t1 = *tools.find(1);
        t1.lifeLimitMinutes = 1.5; // minutes of cutting
        t1.lifeLimitUses = 10;
        QVERIFY(tools.replace(1, t1).ok());
        QVERIFY(saveTableFile(table, tools, TableFormat::Json).ok());
        // The limits are in the file as the issue names them.
        QVERIFY(Test::readFile(table).contains("\"life_limit_minutes\": 1.5, \"life_limit_uses\": 10"));
        // 600 mm at 600 mm/min: a minute of cutting for T1.
        QVERIFY(Test::writeFile(program, "G21 G90\nM6 T1\nG0 X0 Y0 Z5\nG1 Z0 F600\nG1 X600 F600\nM30\n"));
        const QStringList check
            = { u"--json"_s, u"job"_s, u"check"_s, program, u"--table"_s, table, u"--library"_s, library };
        auto lifeFindings = [&check] {
            const Run run = cli(check);
            QJsonArray out;
            for (const QJsonValue &f : json(run).value(u"findings"_s).toArray()) {
                if (f.toObject().value(u"kind"_s).toString() == u"life_exceeded"_s)
                    out.append(f);
            }
            return out;
        };
        // A fresh cutter: a minute of a minute and a half is within its life.
        QCOMPARE(lifeFindings().size(), 0);
        Run run = cli({ u"history"_s, u"add-use"_s, u"--program"_s, program, u"--library"_s, library });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        // One minute cut, one more would be two: past its limit, said with the numbers and what to do.
        const QJsonArray found = lifeFindings();
        QCOMPARE(found.size(), 1);
        const QJsonObject finding = found.at(0).toObject();
        QCOMPARE(finding.value(u"tool"_s).toInt(), 1);
        QCOMPARE(finding.value(u"severity"_s).toString(), u"warning"_s);
        QVERIFY2(finding.value(u"message"_s).toString().contains(u"life limit of 1.5 min"_s),
            qPrintable(finding.value(u"message"_s).toString()));
        QVERIFY(finding.value(u"message"_s).toString().contains(u"toffee-cli new-cutter 1"_s));
        // A new cutter: the runs before it are the old cutter's.
        run = cli({ u"new-cutter"_s, u"1"_s, u"--table"_s, table, u"--library"_s, library });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(lifeFindings().size(), 0);
        QCOMPARE(
            loadTableFile(table).value().find(1)->lifeLimitMinutes, std::optional(1.5)); // the limit stays

        // Uses: a limit of one program, and one run of the new cutter recorded.
        tools = loadTableFile(table).value();
        t1 = *tools.find(1);
        t1.lifeLimitMinutes.reset();
        t1.lifeLimitUses = 1;
        QVERIFY(tools.replace(1, t1).ok());
        QVERIFY(saveTableFile(table, tools, TableFormat::Json).ok());
        QVERIFY(cli({ u"history"_s, u"add-use"_s, u"--program"_s, program, u"--library"_s, library }).exitCode
            == 0);
        const QJsonArray uses = lifeFindings();
        QCOMPARE(uses.size(), 1);
        QVERIFY2(uses.at(0).toObject().value(u"message"_s).toString().contains(u"life limit of 1 uses"_s),
            qPrintable(uses.at(0).toObject().value(u"message"_s).toString()));
    }

    void aCsvTableKeepsTheLimitsAndALinuxCncTableSaysItCannot()
    {
        QTemporaryDir dir;
        ToolTable tools = shopTable();
        Tool t3 = *tools.find(3);
        t3.lifeLimitMinutes = 90.0;
        t3.lifeLimitUses = 40;
        t3.cutterType = u"ball end mill"_s;
        QVERIFY(tools.replace(3, t3).ok());
        const QString csv = dir.filePath(u"shop.csv"_s);
        QVERIFY(saveTableFile(csv, tools, TableFormat::Csv).ok());
        QVERIFY(Test::readFile(csv).startsWith("number,"));
        QVERIFY(Test::readFile(csv).split('\n').front().endsWith(
            "cutter_type,overall_length,life_limit_minutes,life_limit_uses,flutes,probe_x,probe_y,probe_"
            "touches,"
            "probe_turn,probe_latch_feed,spread_limit"));
        QCOMPARE(loadTableFile(csv).value().find(3)->lifeLimitUses, std::optional(40));
        Run run = cli({ u"--json"_s, u"show"_s, csv });
        const QJsonObject shown = json(run).value(u"tools"_s).toArray().at(1).toObject();
        QCOMPARE(shown.value(u"life_limit_uses"_s).toInt(), 40);
        QCOMPARE(shown.value(u"cutter_type"_s).toString(), u"ball end mill"_s);
        run = cli({ u"show"_s, csv });
        QVERIFY2(run.out.contains("life limit: 90 min, 40 uses"), run.out.constData());
        const QString tbl = dir.filePath(u"shop.tbl"_s);
        run = cli({ u"convert"_s, csv, tbl });
        QVERIFY2(run.err.contains("no place for tool life limits"), run.err.constData());
        // Of an old cutter, a LinuxCNC table holds only its length (its wear folded in): that ends.
        run = cli(
            { u"new-cutter"_s, u"3"_s, u"--table"_s, tbl, u"--library"_s, dir.filePath(u"l.sqlite"_s) });
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains("its length 71.508 mm"), run.out.constData());
        QCOMPARE(loadTableFile(tbl).value().find(3)->lengthGeometry, 0.0);
        // Then it holds nothing of the next one: said, and the history still records it.
        run = cli(
            { u"new-cutter"_s, u"3"_s, u"--table"_s, tbl, u"--library"_s, dir.filePath(u"l.sqlite"_s) });
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.err.contains("holds nothing of T3's old cutter to end"), run.err.constData());
        QCOMPARE(events(dir.filePath(u"l.sqlite"_s), 3).size(), 2);
    }
};

QTEST_GUILESS_MAIN(TestMachinistCli)
#include "tst_machinistcli.moc"
