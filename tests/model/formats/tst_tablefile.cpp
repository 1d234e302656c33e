// SPDX-License-Identifier: GPL-3.0-or-later
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "model/formats/tablefile.h"
#include "tests/support/testtables.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestTableFile : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void tellsTheFormatFromTheName()
    {
        QCOMPARE(formatForPath(u"/a/b/tools.json"_s), TableFormat::Json);
        QCOMPARE(formatForPath(u"tool.TBL"_s), TableFormat::LinuxCnc);
        QCOMPARE(formatForPath(u"x.csv"_s), TableFormat::Csv);
        QVERIFY(!formatForPath(u"x.txt"_s));
        QVERIFY(!formatForPath(u"noext"_s));
        QCOMPARE(formatFromName(u"tbl"), TableFormat::LinuxCnc);
        QVERIFY(!formatFromName(u"xml"));
    }

    void convertsBetweenEveryFormat_data()
    {
        QTest::addColumn<int>("from");
        QTest::addColumn<int>("to");
        for (int from = 0; from < 3; ++from) {
            for (int to = 0; to < 3; ++to)
                QTest::addRow("%s to %s", qPrintable(formatSuffix(TableFormat(from))),
                    qPrintable(formatSuffix(TableFormat(to))))
                    << from << to;
        }
    }
    void convertsBetweenEveryFormat()
    {
        QFETCH(int, from);
        QFETCH(int, to);
        QTemporaryDir dir;
        const ToolTable table = Test::linuxCncTable(); // what every format holds
        const QString a = dir.filePath(u"a."_s + formatSuffix(TableFormat(from)));
        const QString b = dir.filePath(u"b."_s + formatSuffix(TableFormat(to)));
        QVERIFY(saveTableFile(a, table, TableFormat(from)).ok());
        auto first = loadTableFile(a);
        QVERIFY2(first.ok(), qPrintable(first.error().text()));
        QVERIFY(saveTableFile(b, first.value(), TableFormat(to)).ok());
        auto second = loadTableFile(b);
        QVERIFY2(second.ok(), qPrintable(second.error().text()));
        QCOMPARE(second.value(), table);
    }

    void namesTheFileInItsErrors()
    {
        QTemporaryDir dir;
        const auto missing = loadTableFile(dir.filePath(u"missing.json"_s));
        QVERIFY(!missing.ok());
        QVERIFY(missing.error().message.contains(u"missing.json: cannot open"_s));

        const auto unknown = loadTableFile(dir.filePath(u"tools.txt"_s));
        QVERIFY(!unknown.ok());
        QVERIFY(unknown.error().message.contains(u"unknown file type"_s));

        QFile bad(dir.filePath(u"bad.tbl"_s));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("T1 P1\nT2 P2 Zx\n");
        bad.close();
        const auto malformed = loadTableFile(bad.fileName());
        QVERIFY(!malformed.ok());
        QCOMPARE(malformed.error().line, 2);
        QVERIFY2(malformed.error().text().endsWith(u"bad.tbl: line 2: \"Zx\": Z needs a number."_s),
            qPrintable(malformed.error().text()));
        QCOMPARE(malformed.error().text().count(u"line 2"_s), 1); // said once
    }

    void aFailedSaveLeavesTheOldFileWhole()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"tools.json"_s);
        QVERIFY(saveTableFile(path, Test::awkwardTable(), TableFormat::Json).ok());
        const QByteArray before = [&] {
            QFile f(path);
            f.open(QIODevice::ReadOnly);
            return f.readAll();
        }();
        // A directory that cannot be written: QSaveFile cannot make its temporary file, the old file stays.
        QVERIFY(QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner));
        const auto r = saveTableFile(path, Test::generatedTable(10), TableFormat::Json);
        QFile::setPermissions(
            dir.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        if (r.ok())
            QSKIP("running as root: the directory could be written anyway");
        QVERIFY(r.error().message.contains(u"tools.json"_s));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), before);
    }

    void saysWhatALinuxCncTableLoses()
    {
        QVERIFY(formatLosses(Test::awkwardTable(), TableFormat::Json).isEmpty());
        QVERIFY(formatLosses(Test::awkwardTable(), TableFormat::Csv).isEmpty());
        QVERIFY(formatLosses(Test::linuxCncTable(), TableFormat::LinuxCnc).isEmpty());
        const QStringList losses = formatLosses(Test::awkwardTable(), TableFormat::LinuxCnc);
        // The broken tool's mark, measured TLOs, notes, life limits and the cutter's type and length.
        QCOMPARE(losses.size(), 5);
        QVERIFY(losses.join(u' ').contains(u"TLO"_s));
        QVERIFY(losses.join(u' ').contains(u"tool life limits"_s));
        QVERIFY(losses.join(u' ').contains(u"tell a new cutter only by its diameter"_s));
        QVERIFY(losses.first().contains(u"break test: T2 would no longer be marked"_s));
    }

    void marksSurviveJsonAndCsvAndOnlyMarkedTablesAreVersion2()
    {
        // A TLO set by hand and a failed break test are written, read back, and kept by both rich formats.
        const ToolTable marked = Test::awkwardTable();
        for (TableFormat format : { TableFormat::Json, TableFormat::Csv }) {
            const auto back = readTable(writeTable(marked, format), format);
            QVERIFY2(back.ok(), qPrintable(back.ok() ? QString() : back.error().text()));
            QCOMPARE(back.value().find(2)->tloSource, TloSource::Manual);
            QVERIFY(back.value().find(2)->breakTestFailed);
            QCOMPARE(*back.value().find(2)->referenceMz, -72.3);
            QCOMPARE(back.value().find(1)->tloSource, TloSource::Probe);
            QVERIFY(!back.value().find(1)->breakTestFailed);
        }
        // A cutter or a life limit is version 3; marks alone, version 2.
        const QByteArray json = writeTable(marked, TableFormat::Json);
        QVERIFY(json.contains("\"version\": 3"));
        QVERIFY(json.contains("\"cutter_type\": \"flat end mill, \\\"2F\\\"\", \"overall_length\": 50.8, "
                              "\"life_limit_minutes\": 90.5, \"life_limit_uses\": 40"));
        ToolTable marksOnly = marked;
        Tool t2 = *marksOnly.find(2);
        t2.cutterType.clear();
        t2.overallLength.reset();
        t2.lifeLimitMinutes.reset();
        t2.lifeLimitUses.reset();
        QVERIFY(marksOnly.replace(2, t2).ok());
        QVERIFY(writeTable(marksOnly, TableFormat::Json).contains("\"version\": 2"));
        QVERIFY(json.contains("\"tlo_source\": \"manual\", \"break_test_failed\": true"));
        // Without marks the file stays version 1, which an older Toffee still reads.
        const QByteArray plain = writeTable(Test::linuxCncTable(), TableFormat::Json);
        QVERIFY(plain.contains("\"version\": 1"));
        QVERIFY(!plain.contains("tlo_source"));
        const QByteArray csv = writeTable(marked, TableFormat::Csv);
        QVERIFY(
            csv.startsWith("number,pocket,description,length_geometry,length_wear,radius_geometry,"
                           "radius_wear,measured_tlo,measured_at,notes,tlo_source,break_test,reference_mz,"
                           "units,"));
        QVERIFY(csv.contains(",manual,failed,-72.3,mm,"));
    }

    // A TLO read from the controller's table (Pull Offsets) stays that in both rich formats: not measured, not
    // set by hand. JSON says it in version 4, which an older Toffee calls newer instead of misreading it.
    void aPulledTloStaysPulled()
    {
        ToolTable table = Test::awkwardTable();
        QVERIFY(table.recordMeasurement(1, 2.5, QDateTime(QDate(2026, 11, 20), QTime(8, 0), Qt::UTC),
                         TloSource::Pulled)
                    .ok());
        for (TableFormat format : { TableFormat::Json, TableFormat::Csv }) {
            const QByteArray written = writeTable(table, format);
            QVERIFY(written.contains(format == TableFormat::Json ? "\"tlo_source\": \"pulled\"" : ",pulled,"));
            const auto back = readTable(written, format);
            QVERIFY2(back.ok(), qPrintable(back.ok() ? QString() : back.error().text()));
            QCOMPARE(back.value().find(1)->tloSource, TloSource::Pulled);
            QCOMPARE(*back.value().find(1)->measuredTlo, 2.5);
            QCOMPARE(back.value().find(2)->tloSource, TloSource::Manual);
        }
        QVERIFY(writeTable(table, TableFormat::Json).contains("\"version\": 4"));
        QVERIFY(writeTable(Test::awkwardTable(), TableFormat::Json).contains("\"version\": 3"));
    }

    void badMarksAreRefusedWithTheirLine()
    {
        const auto json = readTable(
            "{\"format\": \"toffee-tool-table\", \"version\": 2, \"units\": \"mm\", \"tools\": [\n"
            "{\"number\": 1, \"measured_tlo\": 1, \"tlo_source\": \"guess\"}]}",
            TableFormat::Json);
        QVERIFY(!json.ok());
        QCOMPARE(json.error().line, 2);
        QVERIFY(json.error().message.contains(u"\"tlo_source\" must be"_s));
        const auto flag = readTable(
            "{\"format\": \"toffee-tool-table\", \"version\": 2, \"units\": \"mm\", \"tools\": [\n"
            "{\"number\": 1, \"break_test_failed\": \"yes\"}]}",
            TableFormat::Json);
        QVERIFY(!flag.ok());
        QVERIFY(flag.error().message.contains(u"true or false"_s));
        // "Set by hand" with no TLO to have been set is not a tool.
        const auto empty = readTable(
            "{\"format\": \"toffee-tool-table\", \"version\": 2, \"units\": \"mm\", \"tools\": [\n"
            "{\"number\": 1, \"tlo_source\": \"manual\"}]}",
            TableFormat::Json);
        QVERIFY(!empty.ok());
        QVERIFY(empty.error().message.contains(u"set by hand needs its value"_s));
        const auto csv = readTable("number,break_test\n1,maybe\n", TableFormat::Csv);
        QVERIFY(!csv.ok());
        QCOMPARE(csv.error().line, 2);
        QVERIFY(csv.error().message.contains(u"break_test \"maybe\""_s));
    }
};

QTEST_GUILESS_MAIN(TestTableFile)
#include "tst_tablefile.moc"
