// SPDX-License-Identifier: GPL-3.0-or-later
// CAM libraries from files (model/camimport/camlibrary.cpp): which reader, and refusals that name the file.
#include <sys/stat.h>

#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

#include "model/camimport/camlibrary.h"
#include "model/camimport/camreaders.h"
#include "tests/support/camfiles.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestCamLibrary : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void readsEachFormatFromItsFile_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("contents");
        QTest::addColumn<int>("format");
        const QByteArray json = Test::fusionLibrary({ Test::fusionTool(5) });
        QTest::newRow("json") << u"library.json"_s << json << int(CamFormat::FusionJson);
        QTest::newRow("tools") << u"library.tools"_s << Test::zipArchive({ { "tools.json", json } })
                               << int(CamFormat::FusionArchive);
        QTest::newRow("hsmlib") << u"library.hsmlib"_s << Test::hsmLibrary(Test::hsmTool(5))
                                << int(CamFormat::HsmLibrary);
        QTest::newRow("nc") << u"part.nc"_s << Test::makeraProgram({ Test::makeraTool(5) })
                            << int(CamFormat::MakeraProgram);
        QTest::newRow("gcode") << u"part.GCODE"_s << Test::makeraProgram({ Test::makeraTool(5) })
                               << int(CamFormat::MakeraProgram);
    }
    void readsEachFormatFromItsFile()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, contents);
        QFETCH(int, format);
        QTemporaryDir dir;
        const QString path = dir.filePath(name);
        QVERIFY(Test::writeFile(path, contents));
        QVERIFY(isCamLibraryFile(path));
        const auto library = loadCamLibrary(path);
        QVERIFY2(library.ok(), qPrintable(library.error().text()));
        QCOMPARE(library.value().path, path);
        QCOMPARE(int(library.value().format), format);
        QCOMPARE(library.value().tools.size(), 1);
        QCOMPARE(library.value().tools.front().number, 5);
    }

    void aRefusalNamesTheFileTheEntryAndTheLine()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"broken.tools"_s);
        QVERIFY(Test::writeFile(path, Test::zipArchive({ { "tools.json", "{\n\"data\": [1,]}" } })));
        const auto library = loadCamLibrary(path);
        QVERIFY(!library.ok());
        QCOMPARE(library.error().file, path + u": tools.json"_s);
        QCOMPARE(library.error().line, 2);
        // The library is read a tool at a time: the first tool, not an object, is refused before the comma
        // after it.
        QCOMPARE(library.error().text(),
            path + u": tools.json: line 2: tool 1 in \"data\": it is 1, not an object."_s);

        const QString program = dir.filePath(u"part.nc"_s);
        QVERIFY(Test::writeFile(program, Test::makeraProgram({ ";@MKR|TOOL|number=abc" })));
        QCOMPARE(loadCamLibrary(program).error().text(),
            program + u": line 3: number=abc is not a tool number."_s);
    }

    void tellsAToffeeTableFromAFusionLibrary()
    {
        QVERIFY(isToffeeTable(R"({"format": "toffee-tool-table", "version": 1, "tools": []})"));
        QVERIFY(isToffeeTable("{\n  \"version\": 1,\n  \"format\"\n :\t\"toffee-tool-table\"}"));
        QVERIFY(!isToffeeTable(Test::fusionLibrary({ Test::fusionTool(1) })));
        QVERIFY(!isToffeeTable(
            Test::fusionLibrary({ Test::fusionTool(1, R"(see \"format\": \"toffee-tool-table\")") })));
        QVERIFY(!isCamLibraryFile(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json")));
        QVERIFY(!isCamLibraryFile(u"table.tbl"_s));
    }

    void readsOnlyTheBeginningOfALargeProgram()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"large.nc"_s);
        QByteArray program = Test::makeraProgram({ Test::makeraTool(2) });
        program += QByteArray(kMaxProgramHeaderBytes * 2, '\n');
        QVERIFY(Test::writeFile(path, program));
        const auto library = loadCamLibrary(path);
        QVERIFY2(library.ok(), qPrintable(library.error().text()));
        QCOMPARE(library.value().tools.front().number, 2);
    }

    void survivesGarbledFilesOfEachKind()
    {
        // Bytes flipped, cut and repeated, 600 times per format: each reader returns the tools or a reason,
        // never a crash and never an empty refusal.
        const QByteArray json = Test::fusionLibrary({ Test::fusionTool(1), Test::fusionTool(2) });
        const std::pair<QByteArray, Result<QList<CamTool>> (*)(QByteArrayView)> kinds[] = {
            { json, readFusionJson },
            { Test::zipArchive({ { "tools.json", json } }), readFusionArchive },
            { Test::hsmLibrary(Test::hsmTool(1) + Test::hsmTool(2)), readHsmLibrary },
            { Test::makeraProgram({ Test::makeraTool(1), Test::makeraTool(2) }),
                [](QByteArrayView data) {
                    return readMakeraHeader(data);
                } },
        };
        QRandomGenerator random(13);
        for (const auto &[good, read] : kinds) {
            for (int i = 0; i < 600; ++i) {
                QByteArray garbled = good;
                for (int edits = random.bounded(1, 6); edits > 0; --edits) {
                    const qsizetype at = random.bounded(qsizetype(garbled.size()));
                    switch (random.bounded(3)) {
                    case 0:
                        garbled[at] = char(random.bounded(256));
                        break;
                    case 1:
                        garbled.truncate(at);
                        break;
                    default:
                        garbled.insert(at, garbled.mid(at, random.bounded(1, 64)));
                    }
                    if (garbled.isEmpty())
                        break;
                }
                const auto result = read(garbled);
                QVERIFY(result.ok() ? !result.value().isEmpty() : !result.error().message.isEmpty());
            }
        }
    }

    void refusesWhatIsNotAFile()
    {
        QTemporaryDir dir;
        const QString fifo = dir.filePath(u"pipe.nc"_s);
        QCOMPARE(mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        const auto library = loadCamLibrary(fifo); // would block forever if it were opened
        QVERIFY(!library.ok());
        QVERIFY2(library.error().text().contains(u"named pipe"_s), qPrintable(library.error().text()));
        QVERIFY(!loadCamLibrary(dir.filePath(u"missing.hsmlib"_s)).ok());
        QVERIFY(loadCamLibrary(dir.filePath(u"table.csv"_s))
                    .error()
                    .message.contains(u"not a CAM tool library"_s));
    }
};

QTEST_GUILESS_MAIN(TestCamLibrary)
#include "tst_camlibrary.moc"
