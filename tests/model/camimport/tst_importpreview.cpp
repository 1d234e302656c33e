// SPDX-License-Identifier: GPL-3.0-or-later
// A CAM library merged into a table (model/camimport/importpreview.cpp): what is new, what changes and how,
// and that nothing the machine measured is ever touched.
#include <QTest>

#include "model/camimport/camreaders.h"
#include "model/camimport/importpreview.h"
#include "model/job/jobchecker.h"
#include "tests/support/camfiles.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

CamTool camTool(int number, double diameter, Units units = Units::Millimetre, const QString &description = {})
{
    CamTool tool;
    tool.number = number;
    tool.diameter = diameter;
    tool.units = units;
    tool.description = description.isEmpty() ? u"Flat %1"_s.arg(number) : description;
    tool.place = u"tool %1"_s.arg(number);
    return tool;
}

CamLibrary library(const QList<CamTool> &tools)
{
    return CamLibrary { u"lib.json"_s, CamFormat::FusionJson, tools };
}

// A tool the machine has measured, with everything an operator and the machine gave it.
Tool measuredTool(int number)
{
    Tool tool;
    tool.number = number;
    tool.pocket = 7;
    tool.description = u"Flat %1"_s.arg(number);
    tool.lengthGeometry = 41.25;
    tool.lengthWear = -0.012;
    tool.radiusGeometry = 1.0;
    tool.radiusWear = 0.004;
    tool.measuredTlo = -33.388;
    tool.measuredAt = QDateTime(QDate(2026, 11, 22), QTime(10, 15, 0, 125), Qt::UTC);
    tool.tloSource = TloSource::Manual;
    tool.referenceMz = -101.5;
    tool.breakTestFailed = true;
    tool.notes = u"reground twice\nkeep for aluminium"_s;
    return tool;
}

ImportPreview preview(const ToolTable &table, const QList<CamTool> &tools)
{
    auto built = ImportPreview::build(table, library(tools));
    if (!built)
        qFatal("%s", qPrintable(built.error().text()));
    return built.takeValue();
}

} // namespace

class TestImportPreview : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void marksEachToolNewChangedOrUnchanged()
    {
        Tool same;
        same.number = 1;
        same.description = u"Flat 1"_s;
        same.radiusGeometry = 1.5;
        auto table = ToolTable::fromTools({ same, measuredTool(2) }, Units::Millimetre);
        QVERIFY(table.ok());
        const ImportPreview p
            = preview(table.value(), { camTool(1, 3.0), camTool(2, 6.0), camTool(30, 4.0) });
        QCOMPARE(p.tools().size(), 3);
        QCOMPARE(p.tools().at(0).change, ImportChange::Unchanged);
        QCOMPARE(p.tools().at(1).change, ImportChange::Changed);
        QCOMPARE(p.tools().at(1).fields, QStringList { u"radius 1.000 → 3.000 mm"_s });
        // T2 was a 2 mm cutter and the library's is 6 mm: another cutter, whose TLO is not the old one's.
        QVERIFY(p.tools().at(1).newCutter);
        QCOMPARE(p.tools().at(1).endedTlo, std::optional(-33.388));
        QVERIFY(
            p.tools().at(1).notes.contains(u"a new cutter (diameter 2.000 → 6.000 mm): the old cutter's TLO "
                                           "-33.388 mm, its length, wear and break mark end; measure it "
                                           "before it cuts"_s));
        QCOMPARE(p.merged().find(2)->measuredTlo, std::nullopt);
        // Its length (41.250, the old cutter's) ends too: G43 on LinuxCNC or FANUC would apply it to the new
        // cutter, and the job check in those dialects says the tool has no length.
        QCOMPARE(p.merged().find(2)->lengthGeometry, 0.0);
        for (const Dialect dialect : { Dialect::LinuxCnc, Dialect::Fanuc }) {
            JobCheckSetup setup;
            setup.dialect = dialect;
            setup.useTable(p.merged());
            JobChecker checker(setup);
            int line = 0;
            for (const QByteArray text : { "T2 M6", "G43 H2", "G1 Z-1 F100", "M30" })
                checker.feed(text, ++line);
            const JobReport report = checker.finish(u"job.nc"_s, false);
            QVERIFY(std::any_of(report.findings.cbegin(), report.findings.cend(), [](const Finding &f) {
                return f.kind == FindingKind::NotMeasured && f.tool == 2
                    && f.message == u"T2 has no length in the table: G43 would apply 0."_s;
            }));
        }
        QVERIFY(!p.merged().find(2)->breakTestFailed);
        QVERIFY(!p.tools().at(0).newCutter);
        QCOMPARE(p.tools().at(2).change, ImportChange::New);
        QCOMPARE(p.summary(), u"1 new, 1 changed, 1 unchanged; a new cutter in 1 (measure before use)"_s);
        QVERIFY(p.changesAnything());
        QCOMPARE(p.merged().size(), 3);
        const Tool *added = p.merged().find(30);
        QVERIFY(added);
        QCOMPARE(added->pocket, 30);
        QCOMPARE(added->radiusGeometry, 2.0);
        QCOMPARE(added->description, u"Flat 30"_s);
        QCOMPARE(added->lengthGeometry, 0.0);
        QCOMPARE(added->measuredTlo, std::nullopt);
    }

    void keepsEverythingTheMachineAndTheOperatorGaveATool()
    {
        Tool before = measuredTool(2);
        before.radiusGeometry = 3.0; // the library's cutter: 6 mm across
        auto table = ToolTable::fromTools({ before }, Units::Millimetre);
        CamTool cam = camTool(2, 6.0, Units::Millimetre, u"6 mm flat, 3 flutes"_s);
        cam.fluteLength = 20;
        cam.overallLength = 50;
        const ImportPreview p = preview(table.value(), { cam });
        const Tool &after = *p.merged().find(2);
        QCOMPARE(after.radiusGeometry, 3.0);
        QCOMPARE(after.description, u"6 mm flat, 3 flutes"_s);
        QCOMPARE(after.measuredTlo, before.measuredTlo);
        QCOMPARE(*after.measuredTlo, -33.388);
        QCOMPARE(after.measuredAt, before.measuredAt);
        QCOMPARE(after.tloSource, TloSource::Manual);
        QCOMPARE(after.referenceMz, before.referenceMz);
        QCOMPARE(after.breakTestFailed, true);
        QCOMPARE(after.lengthGeometry, before.lengthGeometry);
        QCOMPARE(after.lengthWear, before.lengthWear);
        QCOMPARE(after.radiusWear, before.radiusWear);
        QCOMPARE(after.pocket, before.pocket);
        QCOMPARE(after.notes,
            u"reground twice\nkeep for aluminium\nFrom CAM: flute length 20 mm, overall length 50 mm"_s);
        QCOMPARE(p.tools().front().fields,
            (QStringList { u"description “Flat 2” → “6 mm flat, 3 flutes”"_s,
                u"CAM lengths added to the notes (flute length 20 mm, overall length 50 mm)"_s }));
        QCOMPARE(after.overallLength, std::optional(50.0)); // for the next import to compare
        QVERIFY(!p.tools().front().newCutter);

        // Imported again with other lengths: the CAM's line is replaced, the operator's lines stay.
        cam.fluteLength = 22;
        const ImportPreview again = preview(p.merged(), { cam });
        QCOMPARE(again.merged().find(2)->notes,
            u"reground twice\nkeep for aluminium\nFrom CAM: flute length 22 mm, overall length 50 mm"_s);
        QCOMPARE(again.tools().front().fields,
            QStringList {
                u"CAM lengths in the notes: flute length 20 mm, overall length 50 mm → flute length 22 "
                u"mm, overall length 50 mm"_s });
        QCOMPARE(preview(again.merged(), { cam }).tools().front().change, ImportChange::Unchanged);
    }

    void convertsInchesIntoAMillimetreTable()
    {
        CamTool cam = camTool(4, 0.25, Units::Inch);
        cam.fluteLength = 0.75;
        const ImportPreview p = preview(ToolTable(Units::Millimetre), { cam });
        QCOMPARE(p.merged().find(4)->radiusGeometry, 3.175);
        QCOMPARE(p.merged().find(4)->notes, u"From CAM: flute length 19.05 mm"_s);
        QCOMPARE(preview(p.merged(), { cam }).tools().front().change, ImportChange::Unchanged);
    }

    void convertsMillimetresIntoAnInchTable()
    {
        const ImportPreview p = preview(ToolTable(Units::Inch), { camTool(6, 6.0) });
        // 3 mm = 0.1181102… in, kept to 0.00001 in.
        QCOMPARE(p.merged().find(6)->radiusGeometry, 0.11811);
        QCOMPARE(p.merged().units(), Units::Inch);
        QCOMPARE(preview(p.merged(), { camTool(6, 6.0) }).tools().front().change, ImportChange::Unchanged);
    }

    void neverTakesTheGaugeLengthAsAnOffset()
    {
        const auto tools = readFusionJson(Test::fusionLibrary({ Test::fusionTool(8) }));
        QVERIFY(tools.ok());
        const ImportPreview p = preview(ToolTable(), tools.value());
        const Tool &tool = *p.merged().find(8);
        QCOMPARE(tool.lengthGeometry, 0.0);
        QCOMPARE(tool.measuredTlo, std::nullopt);
        QVERIFY(!tool.measuredAt.isValid());
        QCOMPARE(tool.referenceMz, std::nullopt);
        QVERIFY2(!tool.notes.contains(u"123.4"_s), qPrintable(tool.notes));
        QCOMPARE(tool.notes, u"From CAM: flute length 20 mm, below the holder 30 mm, overall length 50 mm"_s);
    }

    void givesANewToolThePocketOfItsNumberOrOneNoOtherToolHas()
    {
        // T1 is in pocket 1, T7 was moved to pocket 2: T2's own pocket is taken, and so is pocket 1, which
        // the table gives T0 and any number beyond the pockets.
        Tool t1;
        t1.number = 1;
        Tool t7;
        t7.number = 7;
        t7.pocket = 2;
        auto table = ToolTable::fromTools({ t1, t7 }, Units::Millimetre);
        const ImportPreview p = preview(
            table.value(), { camTool(0, 2.0), camTool(2, 3.0), camTool(123456, 4.0), camTool(3, 5.0) });
        const auto pocket = [&p](int number) {
            return p.merged().find(number)->pocket;
        };
        QCOMPARE(pocket(3), 3); // its own
        QCOMPARE(pocket(0), 4); // then the lowest free ones, in the library's order
        QCOMPARE(pocket(2), 5);
        QCOMPARE(pocket(123456), 6);
        QCOMPARE(pocket(1), 1);
        QCOMPARE(pocket(7), 2);

        // A free pocket of the table's rule is kept: T0 into an empty table is in pocket 1.
        QCOMPARE(preview(ToolTable(), { camTool(0, 2.0) }).merged().find(0)->pocket, 1);
        // T1 claims its own pocket before T0, wherever the library lists it.
        const ImportPreview both = preview(ToolTable(), { camTool(0, 2.0), camTool(1, 2.0) });
        QCOMPARE(both.merged().find(1)->pocket, 1);
        QCOMPARE(both.merged().find(0)->pocket, 2);
    }

    void saysANewToolHasNoLengthYet()
    {
        Tool t1;
        t1.number = 1;
        auto table = ToolTable::fromTools({ t1 }, Units::Millimetre);
        const ImportPreview p = preview(table.value(), { camTool(1, 2.0), camTool(0, 2.0) });
        QCOMPARE(p.tools().at(0).notes, QStringList());
        QCOMPARE(p.tools().at(1).notes,
            QStringList { u"pocket 2; no tool length yet (0 in the table): measure it before use"_s });
        QCOMPARE(p.merged().find(0)->lengthGeometry, 0.0);
        QCOMPARE(p.merged().find(0)->measuredTlo, std::nullopt);
    }

    void keepsTheTablesDescriptionWhenTheLibraryHasNone()
    {
        Tool mine = measuredTool(2);
        mine.description = u"the good drill"_s;
        auto table = ToolTable::fromTools({ mine }, Units::Millimetre);
        CamTool drill = camTool(2, 3.0);
        drill.description.clear();
        drill.type = u"drill"_s;
        CamTool added = drill;
        added.number = 4;
        const ImportPreview p = preview(table.value(), { drill, added });
        QCOMPARE(p.merged().find(2)->description, u"the good drill"_s);
        QCOMPARE(p.tools().at(0).description, u"the good drill"_s);
        QCOMPARE(p.tools().at(0).fields, QStringList { u"radius 1.000 → 1.500 mm"_s });
        QCOMPARE(p.merged().find(2)->cutterType, u"drill"_s);
        // Only a new tool is named by the library's type and size.
        QCOMPARE(p.merged().find(4)->description, u"drill, 3 mm"_s);
    }

    void notesALengthOffsetOtherThanTheToolNumber()
    {
        Tool t2 = measuredTool(2);
        auto table = ToolTable::fromTools({ t2 }, Units::Millimetre);
        CamTool same = camTool(2, 2.0, Units::Millimetre, t2.description);
        same.lengthOffset = 12;
        CamTool own = camTool(3, 2.0);
        own.lengthOffset = 3;
        const ImportPreview p = preview(table.value(), { same, own });
        QCOMPARE(p.tools().at(0).change, ImportChange::Unchanged);
        QCOMPARE(p.tools().at(0).notes,
            QStringList {
                u"the library gives length offset H12; Toffee always uses H = T (H2), so it is not imported"_s });
        QCOMPARE(*p.merged().find(2), t2);
        QVERIFY2(!p.tools().at(1).notes.join(u' ').contains(u"H3"_s),
            qPrintable(p.tools().at(1).notes.join(u' ')));
    }

    void refusesAToolTheTableCannotHoldAndNamesIt()
    {
        CamTool huge = camTool(9, 3000.0);
        huge.line = 12;
        const auto built = ImportPreview::build(ToolTable(), library({ camTool(1, 3.0), huge }));
        QVERIFY(!built.ok());
        QCOMPARE(built.error().file, u"lib.json"_s);
        QCOMPARE(built.error().line, 12);
        QVERIFY2(built.error().message.startsWith(u"tool 9: T9: radius geometry 1500 mm is out of range"_s),
            qPrintable(built.error().message));
    }
};

QTEST_GUILESS_MAIN(TestImportPreview)
#include "tst_importpreview.moc"
