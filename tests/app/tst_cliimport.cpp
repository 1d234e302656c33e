// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli import, run as a user or a script runs it: CAM libraries into a table, the preview, and a
// malformed library that leaves the table byte for byte as it was.
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "model/formats/tablefile.h"
#include "tests/support/camfiles.h"
#include "tests/support/processes.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::cli;
using Toffee::Test::Run;

namespace {

// The table an operator already has: T1 measured on the machine, T5 typed in by hand.
ToolTable measuredTable()
{
    Tool t1;
    t1.number = 1;
    t1.description = u"6 mm flat"_s;
    t1.radiusGeometry = 3.0;
    t1.lengthWear = -0.02;
    t1.measuredTlo = -33.388;
    t1.measuredAt = QDateTime(QDate(2026, 11, 22), QTime(10, 15), Qt::UTC);
    t1.referenceMz = -101.5;
    t1.notes = u"reground"_s;
    Tool t5;
    t5.number = 5;
    t5.pocket = 5;
    t5.description = u"Flat 5"_s;
    t5.radiusGeometry = 1.0;
    return ToolTable::fromTools({ t1, t5 }, Units::Millimetre).value();
}

} // namespace

class TestCliImport : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void importsAToolsArchiveIntoANewTable()
    {
        QTemporaryDir dir;
        const QString source = dir.filePath(u"library.tools"_s);
        const QString table = dir.filePath(u"new.json"_s);
        QVERIFY(Test::writeFile(source,
            Test::zipArchive(
                { { "tools.json", Test::fusionLibrary({ Test::fusionTool(1), Test::fusionTool(2) }) } })));
        const Run run = cli({ u"import"_s, source, u"--into"_s, table });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(run.out.contains("new        T1"), run.out.constData());
        QVERIFY2(run.out.contains("2 new, 0 changed, 0 unchanged; written"), run.out.constData());
        const auto written = loadTableFile(table);
        QVERIFY2(written.ok(), qPrintable(written.error().text()));
        QCOMPARE(written.value().units(), Units::Millimetre);
        QCOMPARE(written.value().size(), 2);
        QCOMPARE(written.value().find(2)->radiusGeometry, 3.0);
        QCOMPARE(written.value().find(2)->lengthGeometry, 0.0);
    }

    void showsWhatChangesAndKeepsTheMeasuredTlo()
    {
        QTemporaryDir dir;
        const QString source = dir.filePath(u"library.hsmlib"_s);
        const QString table = dir.filePath(u"tools.json"_s);
        QVERIFY(saveTableFile(table, measuredTable(), TableFormat::Json).ok());
        QVERIFY(Test::writeFile(source,
            Test::hsmLibrary(Test::hsmTool(1, u"diameter=\"6\""_s, u"millimeters"_s, u"6 mm flat, 3 flutes"_s)
                + Test::hsmTool(5, u"diameter=\"2\""_s, u"millimeters"_s, u"Flat 5"_s) + Test::hsmTool(9))));

        const QByteArray before = Test::readFile(table);
        Run run = cli({ u"--json"_s, u"import"_s, source, u"--into"_s, table, u"--dry-run"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(Test::readFile(table), before);
        const QJsonObject preview = QJsonDocument::fromJson(run.out).object();
        QCOMPARE(preview.value(u"new"_s).toArray(), QJsonArray { 9 });
        QCOMPARE(preview.value(u"unchanged"_s).toArray(), QJsonArray { 5 });
        const QJsonArray changed = preview.value(u"changed"_s).toArray();
        QCOMPARE(changed.size(), 1);
        QCOMPARE(changed.at(0)[u"number"_s].toInt(), 1);
        QCOMPARE(changed.at(0)[u"fields"_s].toArray(),
            QJsonArray { u"description “6 mm flat” → “6 mm flat, 3 flutes”"_s });
        QCOMPARE(preview.value(u"new_cutters"_s).toArray(), QJsonArray()); // the same 6 mm cutter
        QCOMPARE(preview.value(u"written"_s).toBool(), false);

        run = cli({ u"import"_s, source, u"--into"_s, table });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(run.out.contains("description “6 mm flat” → “6 mm flat, 3 flutes”"), run.out.constData());
        const auto after = loadTableFile(table);
        QVERIFY(after.ok());
        const Tool &t1 = *after.value().find(1);
        QCOMPARE(t1.radiusGeometry, 3.0);
        QCOMPARE(t1.description, u"6 mm flat, 3 flutes"_s);
        QCOMPARE(t1.measuredTlo, -33.388);
        QCOMPARE(t1.measuredAt, measuredTable().find(1)->measuredAt);
        QCOMPARE(t1.referenceMz, -101.5);
        QCOMPARE(t1.lengthWear, -0.02);
        QCOMPARE(t1.notes, u"reground"_s);
        QCOMPARE(after.value().size(), 3);
    }

    void importsTheMakeraHeaderOfAProgramIntoAnInchTable()
    {
        QTemporaryDir dir;
        const QString source = dir.filePath(u"part.nc"_s);
        const QString table = dir.filePath(u"inch.tbl"_s);
        QVERIFY(Test::writeFile(source, Test::makeraProgram({ Test::makeraTool(3, "diameter=6.35") })));
        const Run run = cli({ u"import"_s, source, u"--into"_s, table, u"--units"_s, u"in"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        const auto written = loadTableFile(table, {}, Units::Inch);
        QVERIFY2(written.ok(), qPrintable(written.error().text()));
        QCOMPARE(written.value().find(3)->radiusGeometry, 0.125);
    }

    void refusesAMalformedLibraryAndLeavesTheTableAsItWas_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("contents");
        QTest::addColumn<QByteArray>("message");
        const QByteArray json = Test::fusionLibrary({ Test::fusionTool(1), Test::fusionTool(2) });
        QTest::newRow("truncated JSON")
            << u"lib.json"_s << json.first(json.indexOf("\"geometry\"")) << "lib.json: line 5: column"_ba;
        QTest::newRow("DC is text") << u"lib.json"_s
                                    << Test::fusionLibrary(
                                           { Test::fusionTool(1, "x", "millimeters", R"("DC": "abc")") })
                                    << "lib.json: tool 1 in \"data\": \"DC\" is \"abc\", not a number."_ba;
        QTest::newRow("not a zip") << u"lib.tools"_s << json << "lib.tools: this is not a .tools archive"_ba;
        QTest::newRow("no tools.json") << u"lib.tools"_s << Test::zipArchive({ { "readme.txt", "hello" } })
                                       << "lib.tools: the archive holds no tools.json"_ba;
        QTest::newRow("garbled tools.json")
            << u"lib.tools"_s << Test::zipArchive({ { "tools.json", "{\n\"data\": 5}" } })
            << "lib.tools: tools.json: line 1: this is not a Fusion tool library"_ba;
        QTest::newRow("wrong namespace")
            << u"lib.hsmlib"_s << Test::hsmLibrary(Test::hsmTool(1), u"tool-library"_s, u"urn:x"_s)
            << "lib.hsmlib: line 2: column"_ba;
        QTest::newRow("a key twice")
            << u"lib.json"_s
            << Test::fusionLibrary({ Test::fusionTool(1).replace(R"("turret": 0)", R"("number": 4)") })
            << "lib.json: line 7: column 37: the key \"number\" appears twice in \"post-process\"; "
               "Toffee will not guess which one is meant."_ba;
        QString attributes;
        for (int i = 0; i < 300; ++i)
            attributes += u" a"_s + QString::number(i) + u"=\"1\""_s;
        QTest::newRow("an element of 300 attributes")
            << u"lib.hsmlib"_s
            << Test::hsmLibrary(
                   QString(Test::hsmTool(1)).replace(u"<tool "_s, u"<tool"_s + attributes + u" "_s))
            << "lib.hsmlib: line 3: this is not an HSM tool library Toffee reads: <tool> has more than 256 attributes"_ba;
        QTest::newRow("number=abc") << u"part.nc"_s
                                    << Test::makeraProgram({ ";@MKR|TOOL|number=abc|diameter=3" })
                                    << "part.nc: line 3: number=abc is not a tool number."_ba;
        QTest::newRow("no header") << u"part.nc"_s << "G21\nG0 X0\n"_ba
                                   << "part.nc: this program has no Makera"_ba;
    }
    void refusesAMalformedLibraryAndLeavesTheTableAsItWas()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, contents);
        QFETCH(QByteArray, message);
        QTemporaryDir dir;
        QVERIFY(QDir::setCurrent(dir.path()));
        QVERIFY(Test::writeFile(name, contents));
        QVERIFY(saveTableFile(u"tools.json"_s, measuredTable(), TableFormat::Json).ok());
        const QByteArray before = Test::readFile(u"tools.json"_s);
        const Run run = cli({ u"import"_s, name, u"--into"_s, u"tools.json"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QByteArray("toffee-cli: " + message)), run.err.constData());
        QCOMPARE(Test::readFile(u"tools.json"_s), before);
        const Run json = cli({ u"--json"_s, u"import"_s, name, u"--into"_s, u"tools.json"_s });
        QCOMPARE(json.exitCode, 2);
        QVERIFY(QJsonDocument::fromJson(json.out)
                    .object()
                    .value(u"error"_s)
                    .toString()
                    .toUtf8()
                    .startsWith(message));
        QCOMPARE(Test::readFile(u"tools.json"_s), before);
    }

    void refusesALibraryOrAnyOtherFileGivenAsTheTable_data()
    {
        QTest::addColumn<QString>("into");
        QTest::addColumn<QByteArray>("contents");
        QTest::addColumn<QByteArray>("message");
        const QByteArray json = Test::fusionLibrary({ Test::fusionTool(1) });
        QTest::newRow("the library itself") << u"lib.json"_s << json
                                            << "lib.json is a Fusion tool library, not a tool table: give a "
                                               ".json, .tbl or .csv tool table as "
                                               "--into."_ba;
        QTest::newRow("a broken library")
            << u"other.json"_s << Test::fusionLibrary({ Test::fusionTool(1, "x", "furlongs") })
            << "other.json is a Fusion tool library, not a tool table"_ba;
        QTest::newRow("other JSON")
            << u"other.json"_s << R"({"version": 17, "rows": []})"_ba
            << "other.json is JSON but not a tool table (it has no \"format\": "
               "\"toffee-tool-table\"): give a .json, .tbl or .csv tool table as --into."_ba;
        QTest::newRow("a .tools archive")
            << u"lib.tools"_s << Test::zipArchive({ { "tools.json", json } })
            << "lib.tools is a Fusion tool library (.tools), not a tool table"_ba;
        QTest::newRow("a program") << u"part.nc"_s << Test::makeraProgram({ Test::makeraTool(3) })
                                   << "part.nc is a G-code program, not a tool table"_ba;
    }
    void refusesALibraryOrAnyOtherFileGivenAsTheTable()
    {
        QFETCH(QString, into);
        QFETCH(QByteArray, contents);
        QFETCH(QByteArray, message);
        QTemporaryDir dir;
        QVERIFY(QDir::setCurrent(dir.path()));
        QVERIFY(Test::writeFile(u"lib.json"_s, Test::fusionLibrary({ Test::fusionTool(1) })));
        if (into != u"lib.json"_s)
            QVERIFY(Test::writeFile(into, contents));
        const QByteArray before = Test::readFile(into);
        for (const QStringList &extra : { QStringList(), QStringList { u"--dry-run"_s } }) {
            const Run run = cli(QStringList { u"import"_s, u"lib.json"_s, u"--into"_s, into } + extra);
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(run.err.contains(QByteArray("toffee-cli: " + message)), run.err.constData());
            QVERIFY2(!run.err.contains("newer Toffee"), run.err.constData());
            QCOMPARE(Test::readFile(into), before);
        }
    }

    void newToolsIntoATblGetAPocketOfTheirOwnAndSayTheyHaveNoLength()
    {
        QTemporaryDir dir;
        const QString source = dir.filePath(u"probe.json"_s);
        const QString table = dir.filePath(u"tool.tbl"_s);
        QVERIFY(Test::writeFile(table, "T1 P1 Z12.5 D3 ;my drill\n"));
        // T0, the probe, and a tool numbered past the pockets: the table's rule gives both pocket 1.
        QVERIFY(Test::writeFile(source,
            Test::fusionLibrary({ Test::fusionTool(0, "probe"), Test::fusionTool(2, ""),
                Test::fusionTool(123456, "big")
                    .replace(R"("length-offset": 123456)", R"("length-offset": 7)") })));
        const Run run = cli({ u"import"_s, source, u"--into"_s, table });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(
            run.out.contains("note: pocket 3; no tool length yet (0 in the table): measure it before use"),
            run.out.constData());
        QVERIFY2(
            run.out.contains("note: the library gives length offset H7; Toffee always uses H = T (H123456)"),
            run.out.constData());
        QCOMPARE(Test::readFile(table),
            "T0 P3 Z0 D6 ;probe\nT1 P1 Z12.5 D3 ;my drill\nT2 P2 Z0 D6 ;flat end mill, 6 mm\n"
            "T123456 P4 Z0 D6 ;big\n"_ba);

        QVERIFY(Test::writeFile(table, "T1 P1 Z12.5 D3 ;my drill\n"));
        const Run json = cli({ u"--json"_s, u"import"_s, source, u"--into"_s, table, u"--dry-run"_s });
        QVERIFY2(json.exitCode == 0, json.err.constData());
        const QJsonArray notes = QJsonDocument::fromJson(json.out).object().value(u"notes"_s).toArray();
        QCOMPARE(notes.size(), 3);
        QCOMPARE(notes.at(0)[u"number"_s].toInt(), 0);
        QCOMPARE(notes.at(0)[u"notes"_s].toArray(),
            QJsonArray { u"pocket 3; no tool length yet (0 in the table): measure it before use"_s });
    }

    void refusesAToffeeTableAndAMissingInto()
    {
        const QString example = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");
        QTemporaryDir dir;
        Run run = cli({ u"import"_s, example, u"--into"_s, dir.filePath(u"t.json"_s) });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("is a Toffee tool table, not a CAM library"), run.err.constData());
        QVERIFY(!QFile::exists(dir.filePath(u"t.json"_s)));
        run = cli({ u"import"_s, example });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("usage: toffee-cli import SOURCE --into TABLE"), run.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestCliImport)
#include "tst_cliimport.moc"
