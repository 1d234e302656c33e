// SPDX-License-Identifier: GPL-3.0-or-later
// A CAM library merged into a table (model/camimport/importpreview.cpp): what is new, what changes and how,
// and that nothing the machine measured is ever touched.
#include <QTest>

#include "model/camimport/camreaders.h"
#include "model/camimport/importpreview.h"
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
        QCOMPARE(p.tools().at(2).change, ImportChange::New);
        QCOMPARE(p.summary(), u"1 new, 1 changed, 1 unchanged"_s);
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
        const Tool before = measuredTool(2);
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
            (QStringList { u"description “Flat 2” → “6 mm flat, 3 flutes”"_s, u"radius 1.000 → 3.000 mm"_s,
                u"CAM lengths added to the notes (flute length 20 mm, overall length 50 mm)"_s }));

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
