// SPDX-License-Identifier: GPL-3.0-or-later
// Fusion / HSM JSON tool libraries and .tools archives (model/camimport/fusionjson.cpp, fusionarchive.cpp).
#include <csignal>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <QFile>
#include <QTest>

#include "model/camimport/camreaders.h"
#include "model/camimport/importpreview.h"
#include "tests/support/camfiles.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

// AddressSanitizer reserves terabytes of address space and keeps what is freed a while: the limit is left out
// under it.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kLimitMemory = false;
#else
constexpr bool kLimitMemory = true;
#endif

const QByteArray kTwoTools = Test::fusionLibrary({ Test::fusionTool(3),
    Test::fusionTool(7, "1/4 ball", "inches",
        R"("DC": 0.25, "LCF": 0.75, "OAL": 2.5, "tip-diameter": 0, "shoulder-length": 1)") });

void verifyRefused(const Result<QList<CamTool>> &read, int line, const QString &message)
{
    QVERIFY2(!read.ok(), "the library was read");
    QVERIFY2(read.error().message.contains(message), qPrintable(read.error().message));
    QCOMPARE(read.error().line, line);
}

// The address space this process has now (VmSize), in bytes.
qint64 addressSpace()
{
    QFile status(u"/proc/self/status"_s);
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith("VmSize:"))
            return line.mid(7).trimmed().split(' ').value(0).toLongLong() * 1024;
    }
    return -1;
}

// A library of Fusion's own tools, each about 800 bytes, as near to the 32 MB a library may have as they go.
QByteArray largestLibrary(int *tools)
{
    QByteArray json = "{\n  \"version\": 14,\n  \"data\": [\n";
    const qsizetype room = kMaxCamLibraryBytes - 2048;
    for (*tools = 0; json.size() < room;) {
        const QByteArray tool = Test::fusionTool(*tools + 1);
        if (json.size() + tool.size() + 8 > room)
            break;
        json += (*tools > 0 ? ",\n    " : "    ") + tool;
        ++*tools;
    }
    return json + "\n  ]\n}\n";
}

} // namespace

class TestFusionLibrary : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void readsTheCutterAndNothingElse()
    {
        const auto read = readFusionJson(kTwoTools);
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().size(), 2);
        const CamTool &t3 = read.value().at(0);
        QCOMPARE(t3.number, 3);
        QCOMPARE(t3.description, u"6 mm flat"_s);
        QCOMPARE(t3.type, u"flat end mill"_s);
        QCOMPARE(t3.units, Units::Millimetre);
        QCOMPARE(t3.diameter, 6.0);
        QCOMPARE(t3.fluteLength, 20.0);
        QCOMPARE(t3.stickOut, 30.0);
        QCOMPARE(t3.overallLength, 50.0);
        QCOMPARE(t3.place, u"tool 1 in \"data\""_s);
        const CamTool &t7 = read.value().at(1);
        QCOMPARE(t7.number, 7);
        QCOMPARE(t7.units, Units::Inch);
        QCOMPARE(t7.diameter, 0.25);
        QCOMPARE(t7.stickOut, std::nullopt);
    }

    void aToolWithoutUnitIsReadAndItsUnitAskedForNeverGuessed()
    {
        const QByteArray noUnit
            = QByteArray(Test::fusionTool(3, "6 mm flat")).replace(R"("unit": "millimeters",)", "");
        const auto read = readFusionJson(Test::fusionLibrary({ Test::fusionTool(1), noUnit }));
        QVERIFY2(read, qPrintable(read ? QString() : read.error().text()));
        QVERIFY(read.value().at(0).unitGiven);
        QVERIFY(!read.value().at(1).unitGiven);
        CamLibrary library { u"lib.json"_s, CamFormat::FusionJson, read.value() };
        QCOMPARE(ImportPreview::toolsWithoutUnit(library), QList<int> { 3 });
        // Without an answer: refused by name, saying what the file needs and how to go on.
        const auto refused = ImportPreview::build(ToolTable(), library);
        QVERIFY(!refused);
        QVERIFY2(refused.error().message.startsWith(
                     u"Tools in this library without \"unit\" (millimeters or inches): T3."_s),
            qPrintable(refused.error().message));
        QVERIFY(refused.error().message.contains(u"add \"unit\": \"millimeters\" (or \"inches\") to each"_s));
        QVERIFY(refused.error().message.contains(u"--cam-units mm|in"_s));
        // In inches, as the operator said: 6 in across, a 3 in radius in an inch table, with a note.
        const auto inches = ImportPreview::build(ToolTable(Units::Inch), library, Units::Inch);
        QVERIFY(inches);
        QCOMPARE(inches.value().merged().find(3)->radiusGeometry, 3.0);
        QCOMPARE(inches.value().merged().find(1)->radiusGeometry, 0.11811); // T1 gives millimetres: converted
        QVERIFY(inches.value().tools().at(1).notes.contains(
            u"the library gives no unit: its lengths are read in inches, as you said"_s));
    }

    void aToolWithoutDescriptionHasNone()
    {
        // The import names a new tool by its type and size, and keeps an existing tool's description.
        const auto read = readFusionJson(Test::fusionLibrary({ Test::fusionTool(1, "  ") }));
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().front().description, QString());
        QCOMPARE(read.value().front().type, u"flat end mill"_s);
    }

    void readsTheLengthOffsetForANote()
    {
        const auto read = readFusionJson(Test::fusionLibrary({ Test::fusionTool(3),
            Test::fusionTool(4).replace(R"("length-offset": 4)", R"("length-offset": 14)"),
            Test::fusionTool(5).replace(R"("length-offset": 5,)", "") }));
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().at(0).lengthOffset, 3);
        QCOMPARE(read.value().at(1).lengthOffset, 14);
        QCOMPARE(read.value().at(2).lengthOffset, std::nullopt);
    }

    void quotesAHugeNumberShortly_data()
    {
        QTest::addColumn<QByteArray>("tool");
        QTest::addColumn<QString>("message");
        QTest::newRow("DC") << Test::fusionTool(2, "x", "millimeters", R"("DC": 1e308)")
                            << u"the diameter 1e+308 mm is out of range"_s;
        QTest::newRow("negative LCF") << Test::fusionTool(2, "x", "millimeters", R"("DC": 3, "LCF": -1e308)")
                                      << u"the flute length is -1e+308 mm; it cannot be negative."_s;
        QTest::newRow("number") << Test::fusionTool(2).replace(R"("number": 2,)", R"("number": 1.5e300,)")
                                << u"its \"number\" 1.5e+300 is out of range"_s;
    }
    void quotesAHugeNumberShortly()
    {
        QFETCH(QByteArray, tool);
        QFETCH(QString, message);
        const auto read = readFusionJson(Test::fusionLibrary({ tool }));
        QVERIFY(!read.ok());
        QVERIFY2(read.error().message.contains(message), qPrintable(read.error().message));
        QVERIFY2(read.error().message.size() < 160, qPrintable(read.error().message));
    }

    void refusesAMalformedLibraryWhole_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("message");
        const QByteArray good = Test::fusionTool(1);
        QTest::newRow("truncated") << kTwoTools.first(kTwoTools.size() / 2) << 0 << u"not valid JSON"_s;
        QTest::newRow("empty file") << QByteArray() << 1 << u"not valid JSON"_s;
        QTest::newRow("DC is text") << Test::fusionLibrary(
            { good, Test::fusionTool(2, "x", "millimeters", R"("DC": "abc")") })
                                    << 0 << u"tool 2 in \"data\": \"DC\" is \"abc\", not a number."_s;
        QTest::newRow("negative DC")
            << Test::fusionLibrary({ Test::fusionTool(2, "x", "millimeters", R"("DC": -6)") }) << 0
            << u"tool 1 in \"data\" (T2): the diameter is -6 mm; it cannot be negative."_s;
        QTest::newRow("OAL is a list")
            << Test::fusionLibrary({ Test::fusionTool(2, "x", "millimeters", R"("DC": 6, "OAL": [50])") })
            << 0 << u"\"OAL\" is a list, not a number."_s;
        QTest::newRow("number is text")
            << Test::fusionLibrary({ QByteArray(good).replace(R"("number": 1,)", R"("number": "abc",)") })
            << 0 << u"its \"number\" is \"abc\", not a whole number."_s;
        QTest::newRow("number has a fraction")
            << Test::fusionLibrary({ QByteArray(good).replace(R"("number": 1,)", R"("number": 2.5,)") }) << 0
            << u"its \"number\" is 2.5, not a whole number."_s;
        QTest::newRow("number out of range")
            << Test::fusionLibrary({ QByteArray(good).replace(R"("number": 1,)", R"("number": 1000000,)") })
            << 0 << u"tool number 1000000 is out of range"_s;
        QTest::newRow("no number") << Test::fusionLibrary({ QByteArray(good).replace(R"("number": 1,)", "") })
                                   << 0 << u"no \"post-process\" \"number\""_s;
        QTest::newRow("repeated number") << Test::fusionLibrary({ good, Test::fusionTool(2), good }) << 0
                                         << u"tool 3 in \"data\" (T1): number 1 is taken already (tool 1 in "
                                            u"\"data\")"_s;
        QTest::newRow("unknown unit") << Test::fusionLibrary({ Test::fusionTool(1, "x", "furlongs") }) << 0
                                      << u"\"unit\" is \"furlongs\""_s;
        QTest::newRow("geometry is a number") << Test::fusionLibrary(
            { Test::fusionTool(1, "x", "millimeters", "").replace(R"("geometry": {})", R"("geometry": 5)") })
                                              << 0 << u"\"geometry\" is 5, not an object."_s;
        QTest::newRow("a tool that is a number")
            << Test::fusionLibrary({ good, "42" }) << 0 << u"tool 2 in \"data\": it is 42, not an object."_s;
        QTest::newRow("no data") << QByteArray(R"({"version": 14, "tools": []})") << 1
                                 << u"not a Fusion tool library"_s;
        QTest::newRow("a list, not an object") << QByteArray("[1, 2]") << 1 << u"not a Fusion tool library"_s;
        QTest::newRow("no tools") << Test::fusionLibrary({}) << 0 << u"holds no tools"_s;
        // A key given twice is refused at every level, named with its line: Fusion would take one of them.
        QTest::newRow("number twice in post-process")
            << Test::fusionLibrary({ QByteArray(good).replace(R"("turret": 0)", R"("number": 4)") }) << 7
            << u"the key \"number\" appears twice in \"post-process\"; Toffee will not guess which one is meant."_s;
        QTest::newRow("number twice, once written with an escape")
            << Test::fusionLibrary({ QByteArray(good).replace(R"("turret": 0)", R"("numb\u0065r": 4)") }) << 7
            << u"the key \"number\" appears twice in \"post-process\""_s;
        QTest::newRow("DC twice in geometry") << Test::fusionLibrary(
            { Test::fusionTool(1, "x", "millimeters", R"("DC": 6, "LB": 3, "DC": 8)") })
                                              << 5 << u"the key \"DC\" appears twice in \"geometry\""_s;
        QTest::newRow("type twice in a tool")
            << Test::fusionLibrary({ Test::fusionTool(2),
                   QByteArray(good).replace(R"("unit":)", R"("type": "drill", "unit":)") })
            << 10
            << u"tool 2 in \"data\": the key \"type\" appears twice; Toffee will not guess which one is meant."_s;
        QTest::newRow("a key twice in a holder's segment")
            << Test::fusionLibrary({ QByteArray(good).replace(R"("lower-diameter": 16)", R"("height": 16)") })
            << 8 << u"the key \"height\" appears twice in \"segments\""_s;
        QTest::newRow("a key twice in a preset")
            << Test::fusionLibrary({ QByteArray(good).replace(R"("v_f": 800)", R"("n": 800)") }) << 9
            << u"the key \"n\" appears twice in \"presets\""_s;
        QTest::newRow("data twice") << "{\n  \"data\": [" + good + "],\n  \"data\": []\n}\n"
                                    << 8 << u"the key \"data\" appears twice at the top level"_s;
        QTest::newRow("length-offset is text")
            << Test::fusionLibrary(
                   { QByteArray(good).replace(R"("length-offset": 1,)", R"("length-offset": "H1",)") })
            << 0 << u"tool 1 in \"data\": its \"length-offset\" is \"H1\", not a whole number."_s;
    }
    void refusesAMalformedLibraryWhole()
    {
        QFETCH(QByteArray, json);
        QFETCH(int, line);
        QFETCH(QString, message);
        const auto read = readFusionJson(json);
        QVERIFY2(!read.ok(), "the library was read");
        QVERIFY2(read.error().message.contains(message), qPrintable(read.error().message));
        if (line > 0)
            QCOMPARE(read.error().line, line);
    }

    // A library is read a tool at a time, keeping only what Toffee takes: the largest one Toffee reads is
    // read in a child process whose address space may grow by 150 MB (a whole QJsonDocument of it took 500
    // MB).
    void readsTheLargestLibraryInBoundedMemory()
    {
        int tools = 0;
        const QByteArray json = largestLibrary(&tools);
        QVERIFY(json.size() > kMaxCamLibraryBytes - 4096 && json.size() <= kMaxCamLibraryBytes);
        constexpr qint64 kAllowance = 150LL * 1024 * 1024;
        const qint64 limit = addressSpace() + kAllowance;
        QVERIFY(limit > kAllowance);
        const pid_t child = fork();
        QVERIFY(child >= 0);
        if (child == 0) {
            std::signal(SIGABRT, SIG_DFL); // an abort ends the child quietly, not through QTest's handler
            const rlimit rl { rlim_t(limit), rlim_t(limit) };
            if (kLimitMemory && setrlimit(RLIMIT_AS, &rl) != 0)
                _exit(3);
            try {
                const auto read = readFusionJson(json);
                _exit(!read.ok() ? 1 : read.value().size() != tools ? 2 : 0);
            } catch (...) { // std::bad_alloc: QTest would catch it, and the child would run on as a test
                _exit(4);
            }
        }
        int status = 0;
        QCOMPARE(waitpid(child, &status, 0), child);
        QVERIFY2(WIFEXITED(status), "the reader crashed");
        QVERIFY2(WEXITSTATUS(status) != 4, "the reader ran out of memory");
        QCOMPARE(WEXITSTATUS(status), 0);
    }

    void aSyntaxErrorNamesItsLineAndColumn()
    {
        // Line 3 is the first tool; the comma after "unit" is missing: the parser stops at the next quote.
        const QByteArray json
            = "{\n  \"data\": [\n    {\"type\": \"drill\", \"unit\": \"mm\" \"number\": 1}\n  ]\n}\n";
        const auto read = readFusionJson(json);
        verifyRefused(read, 3, u"column 36: this is not valid JSON"_s);
    }

    void readsTheLibraryInsideAToolsArchive()
    {
        const QByteArray zip = Test::zipArchive({ { "tools.json", kTwoTools } });
        QVERIFY(zip.startsWith("PK"));
        const auto read = readFusionArchive(zip);
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value(), readFusionJson(kTwoTools).value());
        const auto inAFolder = readFusionArchive(Test::zipArchive({ { "Library/tools.json", kTwoTools } }));
        QVERIFY2(inAFolder.ok(), qPrintable(inAFolder.error().text()));
        QCOMPARE(inAFolder.value().size(), 2);
    }

    void refusesABrokenArchive_data()
    {
        QTest::addColumn<QByteArray>("zip");
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("message");
        const QByteArray good = Test::zipArchive({ { "tools.json", kTwoTools } });
        QTest::newRow("not a zip") << QByteArray("this is plain text, not an archive\n") << QString() << 0
                                   << u"this is not a .tools archive"_s;
        QTest::newRow("empty") << QByteArray() << QString() << 0 << u"this is not a .tools archive"_s;
        QTest::newRow("truncated") << good.first(good.size() / 2) << QString() << 0
                                   << u"this is not a .tools archive"_s;
        QTest::newRow("no tools.json") << Test::zipArchive({ { "library.json", kTwoTools } }) << QString()
                                       << 0 << u"the archive holds no tools.json"_s;
        QTest::newRow("garbled tools.json")
            << Test::zipArchive({ { "tools.json", "{\n  \"data\": [\n    {,\n" } }) << u"tools.json"_s << 3
            << u"column 6: this is not valid JSON"_s;
        QByteArray corrupted = good;
        // The compressed data follows the 30-byte local header, the name and the extra field: flip some of
        // it.
        const auto u16 = [&good](int at) {
            return uchar(good.at(at)) | uchar(good.at(at + 1)) << 8;
        };
        const int data = 30 + u16(26) + u16(28);
        for (int i = data + 2; i < data + 12; ++i)
            corrupted[i] = char(corrupted.at(i) ^ 0x5a);
        QTest::newRow("corrupted data") << corrupted << u"tools.json"_s << 0 << u"cannot be unpacked"_s;

        // libzip refuses a second entry of one name with "File already exists": a zip with tools.json and
        // tools.jsoX, renamed in its local header and its directory, is such an archive.
        QByteArray twoOfOneName
            = Test::zipArchive({ { "tools.json", kTwoTools }, { "tools.jsoX", kTwoTools } });
        QVERIFY(twoOfOneName.count("tools.jsoX") == 2);
        twoOfOneName.replace("tools.jsoX", "tools.json");
        QTest::newRow("two entries of one name")
            << twoOfOneName << QString() << 0
            << u"this is not a .tools archive Toffee can read: two of its entries have the same name"_s;
        QTest::newRow("tools.json twice")
            << Test::zipArchive({ { "a/tools.json", kTwoTools }, { "B/TOOLS.JSON", kTwoTools } }) << QString()
            << 0 << u"the archive holds tools.json twice (a/tools.json and B/TOOLS.JSON)"_s;
        // A checksum that matches neither the data: set alike in the local header (at 14) and the directory
        // entry (at 16), so that only unpacking finds it.
        QByteArray badChecksum = good;
        const qsizetype directory = badChecksum.indexOf("PK\x01\x02");
        QVERIFY(directory > 0);
        for (const qsizetype at : { qsizetype(14), directory + 16 })
            badChecksum[at] = char(badChecksum.at(at) ^ 0x01);
        QTest::newRow("wrong checksum")
            << badChecksum << u"tools.json"_s << 0
            << u"it cannot be unpacked: the archive is damaged (what it unpacks to fails its checksum)."_s;
        QTest::newRow("cut short") << good.first(good.size() - 30) << QString() << 0
                                   << u"it is not a zip archive, or one cut short"_s;
    }
    void refusesABrokenArchive()
    {
        QFETCH(QByteArray, zip);
        QFETCH(QString, file);
        QFETCH(int, line);
        QFETCH(QString, message);
        const auto read = readFusionArchive(zip);
        verifyRefused(read, line, message);
        QCOMPARE(read.error().file, file);
        // libzip's own words describe libzip, not the archive.
        QVERIFY2(!read.error().message.contains(u"File already exists"_s), qPrintable(read.error().message));
        QVERIFY2(!read.error().message.contains(u"inconsistent"_s), qPrintable(read.error().message));
    }

    void refusesAnArchiveThatUnpacksPastTheLimit()
    {
        // 33 MB of blanks compress to a few kilobytes: the reader stops at 32 MB, not at the memory's end.
        QByteArray bomb(kMaxCamLibraryBytes + 1024 * 1024, ' ');
        bomb.prepend("{\"data\": [");
        const QByteArray zip = Test::zipArchive({ { "tools.json", bomb } });
        bomb.clear();
        QVERIFY(!zip.isEmpty() && zip.size() < 1024 * 1024);
        verifyRefused(readFusionArchive(zip), 0, u"unpacks to more than 32 MB"_s);
    }
};

QTEST_GUILESS_MAIN(TestFusionLibrary)
#include "tst_fusionlibrary.moc"
