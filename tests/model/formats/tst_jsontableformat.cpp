// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "model/formats/tablefile.h"
#include "tests/support/testtables.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

// Five header lines, then one tool per line from line 6.
QByteArray table(const QList<QByteArray> &tools, const QByteArray &header = {})
{
    QByteArray out = header.isEmpty() ? QByteArray("{\n  \"format\": \"toffee-tool-table\",\n  \"version\": "
                                                   "1,\n  \"units\": \"mm\",\n  \"tools\": [\n")
                                      : header;
    for (qsizetype i = 0; i < tools.size(); ++i)
        out += "    " + tools.at(i) + (i + 1 < tools.size() ? ",\n" : "\n");
    return out + "  ]\n}\n";
}

const QByteArray kGood = R"({"number": 1, "pocket": 1, "length_geometry": 10})";

} // namespace

class TestJsonTableFormat : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTrips_data()
    {
        QTest::addColumn<ToolTable>("table");
        QTest::newRow("awkward values, mm") << Test::awkwardTable();
        QTest::newRow("awkward values, inch") << Test::awkwardTable(Units::Inch);
        QTest::newRow("empty") << ToolTable();
        QTest::newRow("empty, inch") << ToolTable(Units::Inch);
        QTest::newRow("500 generated tools") << Test::generatedTable(500);
    }
    void roundTrips()
    {
        QFETCH(ToolTable, table);
        Test::verifyRoundTrip(table, TableFormat::Json);
    }

    void readsTheExampleTable()
    {
        const auto table
            = loadTableFile(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"));
        QVERIFY2(table.ok(), qPrintable(table.error().text()));
        QCOMPARE(table.value().size(), 6);
        QCOMPARE(table.value().find(2)->measuredTlo.value_or(0), 9.652);
    }

    void decodesEscapes()
    {
        const auto read
            = readJsonTable(table({ R"({"number": 1, "notes": "\"a\"\\b\/\n\u00e9\ud83d\udd27"})" }));
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().at(0).notes, u"\"a\"\\b/\n\u00e9\U0001F527"_s);
    }

    void readsOptionalFieldsAsDefaults()
    {
        const auto read = readJsonTable(table({ R"({"number": 12})" }));
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        const Tool &tool = read.value().at(0);
        QCOMPARE(tool.number, 12);
        QCOMPARE(tool.pocket, 12);
        QCOMPARE(tool.lengthGeometry, 0.0);
        QVERIFY(!tool.measuredTlo.has_value());
    }

    void reportsAMalformedFileWithItsLine_data()
    {
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("message");
        const QByteArray head
            = "{\n  \"format\": \"toffee-tool-table\",\n  \"version\": 1,\n  \"units\": \"mm\",\n";

        QTest::newRow("empty file") << QByteArray() << 1 << u"not valid JSON"_s;
        QTest::newRow("truncated") << head.left(40) << 3 << u"not valid JSON"_s;
        QTest::newRow("missing comma")
            << table({ kGood, R"({"number": 2} {"number": 3})" }) << 7 << u"not valid JSON"_s;
        QTest::newRow("trailing garbage") << table({ kGood }) + "x" << 9 << u"not valid JSON"_s;
        QTest::newRow("a list at the top") << QByteArray("[]") << 1 << u"one JSON object"_s;
        QTest::newRow("another program's JSON")
            << QByteArray(R"({"tools": []})") << 1 << u"\"format\" must be"_s;
        QTest::newRow("no version") << QByteArray(
            R"({"format": "toffee-tool-table", "units": "mm", "tools": []})")
                                    << 1 << u"\"version\""_s;
        QTest::newRow("version as text")
            << QByteArray(R"({"format": "toffee-tool-table", "version": "1", "units": "mm", "tools": []})")
            << 1 << u"\"version\""_s;
        QTest::newRow("fractional version")
            << QByteArray(R"({"format": "toffee-tool-table", "version": 1.5, "units": "mm", "tools": []})")
            << 1 << u"\"version\""_s;
        QTest::newRow("newer version")
            << QByteArray(R"({"format": "toffee-tool-table", "version": 6, "units": "mm", "tools": []})") << 1
            << u"newer Toffee"_s;
        QTest::newRow("unknown units")
            << QByteArray(R"({"format": "toffee-tool-table", "version": 1, "units": "cm", "tools": []})") << 1
            << u"\"units\""_s;
        QTest::newRow("tools not a list")
            << QByteArray(R"({"format": "toffee-tool-table", "version": 1, "units": "mm", "tools": {}})") << 1
            << u"\"tools\" must be a list"_s;
        QTest::newRow("unknown table field") << QByteArray(
            R"({"format": "toffee-tool-table", "version": 1, "units": "mm", "tools": [], "x": 1})")
                                             << 1 << u"unknown field \"x\""_s;
        QTest::newRow("a tool that is not an object")
            << table({ kGood, "42" }) << 7 << u"must be a JSON object"_s;
        QTest::newRow("a tool without a number")
            << table({ kGood, R"({"pocket": 2})" }) << 7 << u"no \"number\""_s;
        QTest::newRow("fractional tool number") << table({ R"({"number": 1.5})" }) << 6 << u"whole number"_s;
        QTest::newRow("huge tool number") << table({ R"({"number": 1e12})" }) << 6 << u"out of range"_s;
        QTest::newRow("tool number out of range")
            << table({ R"({"number": 1000000})" }) << 6 << u"out of range"_s;
        QTest::newRow("pocket as text")
            << table({ R"({"number": 1, "pocket": "one"})" }) << 6 << u"\"pocket\" must be"_s;
        QTest::newRow("length as text")
            << table({ kGood, R"({"number": 2})", R"({"number": 3, "length_geometry": "10"})" }) << 8
            << u"must be a number"_s;
        QTest::newRow("wear out of range")
            << table({ kGood, R"({"number": 2, "length_wear": 120})" }) << 7 << u"length wear 120 mm"_s;
        QTest::newRow("duplicate tool") << table({ kGood, R"({"number": 2})", R"({"number": 1})" }) << 8
                                        << u"tool 1 is already on line 6"_s;
        QTest::newRow("unknown tool field")
            << table({ R"({"number": 1, "lenght": 3})" }) << 6 << u"\"lenght\""_s;
        QTest::newRow("bad date") << table({ R"({"number": 1, "measured_at": "yesterday"})" }) << 6
                                  << u"not a date"_s;
        QTest::newRow("description not text")
            << table({ R"({"number": 1, "description": 5})" }) << 6 << u"must be text"_s;
        QTest::newRow("description over two lines")
            << table({ R"({"number": 1, "description": "a\nb"})" }) << 6 << u"one line"_s;
        QTest::newRow("bad LinuxCNC extra")
            << table({ R"({"number": 1, "linuxcnc": "K3"})" }) << 6 << u"LinuxCNC tool field"_s;
        QTest::newRow("string not UTF-8")
            << table({ "{\"number\": 1, \"notes\": \"caf\xe9\"}" }) << 6 << u"not valid UTF-8"_s;
        QTest::newRow("unknown escape")
            << table({ R"({"number": 1, "notes": "a\qb"})" }) << 6 << u"unknown escape"_s;
        QTest::newRow("raw line break in a string")
            << table({ "{\"number\": 1, \"notes\": \"a\nb\"}" }) << 6 << u"line break or control character"_s;
        QTest::newRow("lone surrogate")
            << table({ R"({"number": 1, "notes": "\ud800"})" }) << 6 << u"surrogate"_s;
        QTest::newRow("leading zero") << table({ R"({"number": 01})" }) << 6 << u"expected a number"_s;
        QTest::newRow("field twice") << table({ R"({"number": 1, "number": 2})" }) << 6 << u"appears twice"_s;
        QTest::newRow("number too large")
            << table({ R"({"number": 1, "length_wear": 1e999})" }) << 6 << u"too large"_s;
        QTest::newRow("deeply nested garbage") << QByteArray(R"({"format": "toffee-tool-table", "x": )")
                + QByteArray(200, '[') << 1 << u"nested too deeply"_s;
        // A key given twice is refused at every level, named with its line.
        const QByteArray top
            = "{\n  \"format\": \"toffee-tool-table\",\n  \"version\": 1,\n  \"units\": \"mm\",\n";
        QTest::newRow("format twice")
            << table({ kGood }, top + "  \"format\": \"toffee-tool-table\",\n  \"tools\": [\n") << 5
            << u"the key \"format\" appears twice at the top level"_s;
        QTest::newRow("units twice") << table({ kGood }, top + "  \"units\": \"in\",\n  \"tools\": [\n") << 5
                                     << u"the key \"units\" appears twice at the top level"_s;
        QTest::newRow("tools twice") << top + "  \"tools\": [],\n  \"tools\": []\n}\n"
                                     << 6 << u"the key \"tools\" appears twice at the top level"_s;
        QTest::newRow("a key twice in a tool's value")
            << table({ kGood, R"({"number": 2, "notes": {"a": 1, "a": 2}})" }) << 7
            << u"the key \"a\" appears twice in \"notes\"; Toffee will not guess which one is meant."_s;
        QTest::newRow("a key twice deep in a field of the table")
            << table({ kGood },
                   top + "  \"x\": [[{\"k\": [{\"a\": 1}, {\"b\": 1,\n \"b\": 2}]}]],\n  \"tools\": [\n")
            << 6 << u"the key \"b\" appears twice in \"k\""_s;
        QTest::newRow("a key twice in an object of a list")
            << table({ kGood }, top + "  \"x\": [[{\"a\": 1,\n \"a\": 2}]],\n  \"tools\": [\n") << 6
            << u"the key \"a\" appears twice in \"x\""_s;
        QTest::newRow("tools on one line, the third bad")
            << table({ R"({"number": 1}, {"number": 2}, {"number": 3, "pocket": -1})" }) << 6
            << u"pocket -1"_s;
    }
    void reportsAMalformedFileWithItsLine()
    {
        QFETCH(QByteArray, data);
        QFETCH(int, line);
        QFETCH(QString, message);
        Test::verifyRefused(readJsonTable(data), line, message);
    }
};

QTEST_GUILESS_MAIN(TestJsonTableFormat)
#include "tst_jsontableformat.moc"
