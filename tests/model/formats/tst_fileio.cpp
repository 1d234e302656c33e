// SPDX-License-Identifier: GPL-3.0-or-later
// Files as a hostile environment makes them: special files in a table's place, a disk that fills, a table too
// large to read back, tokens of megabytes. Nothing blocks, nothing is lost, no message quotes megabytes.
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTest>

#include "model/formats/fileio.h"
#include "model/formats/tablefile.h"
#include "model/textparsing.h"
#include "tests/support/fulldisk.h"
#include "tests/support/specialfiles.h"
#include "tests/support/testtables.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

QByteArray contents(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("(cannot read)");
}

ToolTable tableOf(int count)
{
    QList<Tool> tools;
    for (int i = 1; i <= count; ++i)
        tools << Test::tool(i, 10.0 + i / 1000.0, u"tool %1 with a description"_s.arg(i));
    return ToolTable::fromTools(tools, Units::Millimetre).takeValue();
}

} // namespace

class TestFileIo : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private Q_SLOTS:
    void refusesWhatIsNotARegularFile_data() { Toffee::Test::addSpecialFileRows(); }
    void refusesWhatIsNotARegularFile()
    {
        QFETCH(QString, kind);
        QFETCH(QString, expected);
        const QString path = m_dir.filePath(kind + u".json"_s);
        QVERIFY(Toffee::Test::makeSpecialFile(kind, path));
        QElapsedTimer clock;
        clock.start();
        const auto read = loadTableFile(path);
        QVERIFY(clock.elapsed() < 5000); // a FIFO with no writer would block for ever
        QVERIFY(!read.ok());
        QVERIFY2(read.error().message.contains(expected), qPrintable(read.error().message));
        QVERIFY2(read.error().message.startsWith(path), qPrintable(read.error().message));
    }

    void refusesAFileOverItsLimit()
    {
        const QString path = m_dir.filePath(u"big.json"_s);
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray(3000, ' '));
        file.close();
        const auto read = readRegularFile(path, 2048);
        QVERIFY(!read.ok());
        QVERIFY2(read.error().message.contains(u"at most"_s), qPrintable(read.error().message));
        QCOMPARE(readRegularFile(path, 3000).value().size(), 3000);
    }

    void aFullDiskLeavesTheOldFileWhole_data()
    {
        QTest::addColumn<int>("formatIndex");
        QTest::addColumn<qint64>("spare");
        QTest::newRow("JSON, disk full") << int(TableFormat::Json) << qint64(0);
        QTest::newRow("tbl, disk full") << int(TableFormat::LinuxCnc) << qint64(0);
        QTest::newRow("CSV, disk full") << int(TableFormat::Csv) << qint64(0);
        QTest::newRow("JSON, a little space left") << int(TableFormat::Json) << qint64(8192);
        QTest::newRow("CSV, a little space left") << int(TableFormat::Csv) << qint64(8192);
    }
    void aFullDiskLeavesTheOldFileWhole()
    {
        QFETCH(int, formatIndex);
        const auto format = TableFormat(formatIndex);
        QFETCH(qint64, spare);
        Test::FullDisk disk;
        const QString path = disk.path(u"tools."_s + formatSuffix(format));
        QVERIFY(saveTableFile(path, tableOf(6), format).ok());
        const QByteArray before = contents(path);
        disk.fill(spare);
        // Larger than what is left: 3,000 tools are about 150 KB in any format.
        const auto saved = saveTableFile(path, tableOf(3000), format);
        QVERIFY(!saved.ok());
        QVERIFY2(saved.error().message.contains(disk.reason()), qPrintable(saved.error().message));
        QVERIFY2(
            saved.error().message.contains(u"old file is unchanged"_s), qPrintable(saved.error().message));
        QCOMPARE(contents(path), before);
        // Nothing half-written is left beside it.
        QCOMPARE(QDir(QFileInfo(path).path()).entryList({ u"tools*"_s }, QDir::Files),
            QStringList { u"tools."_s + formatSuffix(format) });
    }

    void aNewFileOnAFullDiskIsNotWritten()
    {
        Test::FullDisk disk;
        disk.fill();
        const QString path = disk.path(u"new.json"_s);
        const auto saved = saveTableFile(path, tableOf(3000), TableFormat::Json);
        QVERIFY(!saved.ok());
        QVERIFY2(saved.error().message.contains(u"Nothing was written"_s), qPrintable(saved.error().message));
        QVERIFY2(!saved.error().message.contains(u"old file"_s), qPrintable(saved.error().message));
        QVERIFY(!QFileInfo::exists(path));
    }

    void aSaveSaysWhyItCannotStart_data()
    {
        QTest::addColumn<QString>("target");
        QTest::addColumn<QString>("expected");
        QTest::addColumn<bool>("mentionsOldFile");
        QTest::newRow("missing folder") << u"no-such-folder/tools.json"_s << u"does not exist"_s << false;
        QTest::newRow("FIFO") << u"fifo.json"_s << u"named pipe (FIFO)"_s << false;
        QTest::newRow("folder") << u"folder.json"_s << u"it is a folder"_s << false;
    }
    void aSaveSaysWhyItCannotStart()
    {
        QFETCH(QString, target);
        QFETCH(QString, expected);
        QFETCH(bool, mentionsOldFile);
        QTemporaryDir dir;
        const QString path = dir.filePath(target);
        if (target == u"fifo.json")
            QVERIFY(Test::makeSpecialFile(u"fifo"_s, path));
        else if (target == u"folder.json")
            QVERIFY(Test::makeSpecialFile(u"folder"_s, path));
        const auto saved = saveTableFile(path, tableOf(2), TableFormat::Json);
        QVERIFY(!saved.ok());
        QVERIFY2(saved.error().message.contains(expected), qPrintable(saved.error().message));
        QCOMPARE(saved.error().message.contains(u"old file"_s), mentionsOldFile);
    }

    void refusesToWriteWhatItCouldNotReadBack()
    {
        // 4,500 tools, each with notes at the limit that JSON writes six bytes a character: within every
        // limit of a tool, but a file of about 270 MB, more than a reader takes.
        QList<Tool> tools;
        const QString notes(10000, QChar(0x01));
        for (int i = 1; i <= 4500; ++i) {
            Tool t = Test::tool(i);
            t.notes = notes;
            tools << t;
        }
        const ToolTable big = ToolTable::fromTools(tools, Units::Millimetre).takeValue();
        const QString path = m_dir.filePath(u"big-notes.json"_s);
        QVERIFY(saveTableFile(path, tableOf(2), TableFormat::Json).ok());
        const QByteArray before = contents(path);
        const auto saved = saveTableFile(path, big, TableFormat::Json);
        QVERIFY(!saved.ok());
        QVERIFY2(saved.error().message.contains(u"more than Toffee reads back"_s),
            qPrintable(saved.error().message));
        QCOMPARE(contents(path), before);
        // What it does write, it reads back: the same table in CSV, which writes notes as they are, fits.
        const QString csv = m_dir.filePath(u"big-notes.csv"_s);
        QVERIFY(saveTableFile(csv, big, TableFormat::Csv).ok());
        const auto read = loadTableFile(csv);
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().size(), 4500);
    }

    void messagesQuoteAnExcerpt_data()
    {
        QTest::addColumn<int>("formatIndex");
        QTest::addColumn<QByteArray>("data");
        const QByteArray huge(10 * 1024 * 1024, 'q');
        QTest::newRow("CSV column name") << int(TableFormat::Csv) << QByteArray("number," + huge + "\n1,2\n");
        QTest::newRow("CSV number") << int(TableFormat::Csv)
                                    << QByteArray("number,length_geometry\n1," + huge + "\n");
        QTest::newRow("tbl token") << int(TableFormat::LinuxCnc) << QByteArray("T1 P1 " + huge + "\n");
        QTest::newRow("JSON key") << int(TableFormat::Json)
                                  << QByteArray(R"({"format": "toffee-tool-table", "version": 1, ")" + huge
                                         + R"(": 1})");
    }
    void messagesQuoteAnExcerpt()
    {
        QFETCH(int, formatIndex);
        const auto format = TableFormat(formatIndex);
        QFETCH(QByteArray, data);
        const auto read = readTable(data, format);
        QVERIFY(!read.ok());
        QVERIFY2(read.error().message.size() < 400, qPrintable(read.error().message.left(400)));
        QVERIFY2(read.error().message.contains(u"qqqq"_s), qPrintable(read.error().message));
    }

    void aGiantFileOfOneRowStopsAtItsSecond()
    {
        // 63 MB of one-column rows once peaked at 4.7 GB before naming line 3; now the reader stops there.
        QByteArray csv = "number\n";
        csv.reserve(8 * 1024 * 1024);
        while (csv.size() < 8 * 1024 * 1024)
            csv += "1\n";
        const auto read = readTable(csv, TableFormat::Csv);
        Test::verifyRefused(read, 3, u"tool 1 is already on line 2"_s);
    }

    void numbersAreNamedForWhatIsWrong_data()
    {
        QTest::addColumn<int>("formatIndex");
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("message");
        QTest::newRow("CSV tool 2147483648") << int(TableFormat::Csv) << QByteArray("number\n2147483648\n")
                                             << 2 << u"out of range; use 0 to 999999"_s;
        QTest::newRow("tbl T99999999999999999999")
            << int(TableFormat::LinuxCnc) << QByteArray("T99999999999999999999 P1\n") << 1
            << u"out of range"_s;
        QTest::newRow("JSON number 2147483648")
            << int(TableFormat::Json)
            << QByteArray(
                   "{\"format\": \"toffee-tool-table\", \"version\": 1, \"units\": \"mm\", \"tools\": [\n"
                   "{\"number\": 2147483648}]}")
            << 2 << u"out of range"_s;
        QTest::newRow("NUL on line 2")
            << int(TableFormat::Csv) << QByteArray("number\n1\0\n", 10) << 2 << u"binary data"_s;
    }
    void numbersAreNamedForWhatIsWrong()
    {
        QFETCH(int, formatIndex);
        const auto format = TableFormat(formatIndex);
        QFETCH(QByteArray, data);
        QFETCH(int, line);
        QFETCH(QString, message);
        Test::verifyRefused(readTable(data, format), line, message);
    }

    void aNumberTooCloseToZeroIsZero()
    {
        QCOMPARE(parseDecimal("1e-400"), 0.0);
        QCOMPARE(parseDecimal("-0.0001e-400"), -0.0);
        QVERIFY(!parseDecimal("1e400"));
        QCOMPARE(parseDecimal("100000e-5000000000000000000000000"), 0.0);
        QVERIFY(!parseDecimal(QByteArray("1" + QByteArray(400, '0') + "e-10")));
        const QByteArray json
            = "{\"format\": \"toffee-tool-table\", \"version\": 1, \"units\": \"mm\", \"tools\": [\n"
              "{\"number\": 1, \"length_wear\": 1e-400}]}";
        const auto read = readTable(json, TableFormat::Json);
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().tools().front().lengthWear, 0.0);
    }
};

QTEST_GUILESS_MAIN(TestFileIo)
#include "tst_fileio.moc"
