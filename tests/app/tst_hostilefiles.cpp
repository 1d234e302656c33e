// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli against files a hostile environment hands it, each run under a memory limit (ulimit -v): a
// reader that sized its memory by the file instead of the table fails the suite here, not the machine. And
// a full disk: the old file stays byte for byte, and the exit code and the message say why.
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include "tests/support/fulldisk.h"
#include "tests/support/specialfiles.h"

using namespace Qt::StringLiterals;

namespace {

// AddressSanitizer reserves terabytes of address space, so the limit is left out under it.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kLimitMemory = false;
#else
constexpr bool kLimitMemory = true;
#endif
constexpr int kMemoryLimitKb = 1024 * 1024; // 1 GB: a reader that collects every row of 250 MB needs many

struct Run
{
    int exitCode = -1;
    QString err;
    qint64 ms = 0;
};

// toffee-cli ARGS under the memory limit, killed (and failed) after `timeoutMs`.
Run cli(const QStringList &arguments, int timeoutMs = 60000)
{
    QStringList quoted;
    for (const QString &a : arguments)
        quoted << u"'"_s + QString(a).replace(u"'"_s, u"'\\''"_s) + u"'"_s;
    const QString limit = kLimitMemory ? u"ulimit -v %1; "_s.arg(kMemoryLimitKb) : QString();
    QProcess process;
    QElapsedTimer clock;
    clock.start();
    process.start(
        u"/bin/sh"_s, { u"-c"_s, limit + u"exec '" TOFFEE_BIN_DIR "/toffee-cli' "_s + quoted.join(u' ') });
    Run run;
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished();
        run.err = u"TEST: toffee-cli did not finish in time"_s;
        return run;
    }
    run.ms = clock.elapsed();
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

// A file of `line` repeated to `bytes`, after `head`, written in large pieces.
bool giant(const QString &path, const QByteArray &head, const QByteArray &line, qint64 bytes)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return false;
    file.write(head);
    QByteArray block;
    while (block.size() < 1024 * 1024)
        block += line;
    for (qint64 written = head.size(); written < bytes; written += block.size()) {
        if (file.write(block) != block.size())
            return false;
    }
    return true;
}

QByteArray contents(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("(cannot read)");
}

} // namespace

class TestHostileFiles : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private Q_SLOTS:
    void specialFilesAreRefusedByName_data() { Toffee::Test::addSpecialFileRows(); }
    void specialFilesAreRefusedByName()
    {
        QFETCH(QString, kind);
        QFETCH(QString, expected);
        const QString path = m_dir.filePath(kind + u".json"_s);
        QVERIFY(Toffee::Test::makeSpecialFile(kind, path));
        for (const QString &command : { u"show"_s, u"simulate"_s }) {
            const Run run = command == u"show"_s ? cli({ command, path }, 10000)
                                                 : cli({ command, u"--dialect"_s, u"fanuc"_s, path }, 10000);
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(run.err.contains(expected) && run.err.contains(path), qPrintable(run.err));
        }
    }

    void tinyRowGiantsStopAtTheFirstError_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("head");
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<qint64>("bytes");
        QTest::addColumn<QString>("expected");
        // Each once peaked at gigabytes (4.7 GB, 6.5 GB, bad_alloc) before naming its line.
        QTest::newRow("63 MB CSV of one-column rows")
            << u"rows.csv"_s << QByteArray("number\n") << QByteArray("1\n") << qint64(63) * 1024 * 1024
            << u"line 3: tool 1 is already on line 2"_s;
        QTest::newRow("240 MB tbl of T1 P1")
            << u"rows.tbl"_s << QByteArray() << QByteArray("T1 P1\n") << qint64(240) * 1024 * 1024
            << u"line 2: tool 1 is already on line 1"_s;
        QTest::newRow("125 M-row CSV")
            << u"many.csv"_s << QByteArray("number\n") << QByteArray("1\n") << qint64(250) * 1024 * 1024
            << u"line 3: tool 1 is already on line 2"_s;
        QTest::newRow("250 MB of blank lines in a JSON tool list")
            << u"blank.json"_s
            << QByteArray(R"({"format": "toffee-tool-table", "version": 1, "units": "mm", "tools": [)")
            << QByteArray("\n") << qint64(250) * 1024 * 1024 << u"must be a JSON object"_s;
    }
    void tinyRowGiantsStopAtTheFirstError()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, head);
        QFETCH(QByteArray, line);
        QFETCH(qint64, bytes);
        QFETCH(QString, expected);
        const QString path = m_dir.filePath(name);
        QVERIFY(giant(path, head, line, bytes));
        const Run run = cli({ u"show"_s, path });
        QFile::remove(path);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(expected), qPrintable(run.err));
    }

    void giantTokensStopAsTheyAreRead_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("head");
        QTest::addColumn<QByteArray>("unit");
        QTest::addColumn<QByteArray>("tail");
        QTest::addColumn<QString>("expected");
        // Each a single 250 MB token or row that was once copied whole (bad_alloc under this limit).
        QTest::newRow("JSON description")
            << u"text.json"_s
            << QByteArray("{\"format\": \"toffee-tool-table\", \"version\": 1, \"units\": \"mm\", \"tools\": "
                          "[{\"number\": 1, \"description\": \"")
            << QByteArray("d") << QByteArray("\"}]}") << u"longer than 64 KB"_s;
        QTest::newRow("CSV quoted field") << u"quoted.csv"_s << QByteArray("number,notes\n1,\"")
                                          << QByteArray("n") << QByteArray("\"\n") << u"longer than 64 KB"_s;
        QTest::newRow("CSV header of many columns")
            << u"columns.csv"_s << QByteArray("number") << QByteArray(",x") << QByteArray("\n1\n")
            << u"more than 26 columns"_s;
        QTest::newRow("CSV row of many fields")
            << u"fields.csv"_s << QByteArray("number\n1") << QByteArray(",") << QByteArray("\n")
            << u"more fields than the header's 1"_s;
        QTest::newRow("tbl comment") << u"comment.tbl"_s << QByteArray("T1 P1 ;") << QByteArray("c")
                                     << QByteArray("\n") << u"longer than a description may be"_s;
    }
    void giantTokensStopAsTheyAreRead()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, head);
        QFETCH(QByteArray, unit);
        QFETCH(QByteArray, tail);
        QFETCH(QString, expected);
        const QString path = m_dir.filePath(name);
        QVERIFY(giant(path, head, unit, qint64(250) * 1024 * 1024));
        QFile file(path);
        QVERIFY(file.open(QIODevice::Append));
        file.write(tail);
        file.close();
        const Run run = cli({ u"show"_s, path });
        QFile::remove(path);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(expected) && run.err.size() < 1000, qPrintable(run.err.left(1000)));
    }

    void aTableAtEveryLimitIsReadOrRefusedNeverACrash()
    {
        // 25,000 tools with notes of 10,000 characters: within every limit, 245 MB of file and twice that
        // in memory. Under the limit it either loads or is refused for want of memory; it never aborts.
        const QString path = m_dir.filePath(u"full.json"_s);
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{\"format\": \"toffee-tool-table\", \"version\": 1, \"units\": \"mm\", \"tools\": [");
        const QByteArray notes(10000, 'n');
        for (int i = 1; i <= 25000; ++i)
            file.write((i > 1 ? ",\n" : "\n") + QByteArray("{\"number\": ") + QByteArray::number(i)
                + ", \"notes\": \"" + notes + "\"}");
        file.write("]}\n");
        file.close();
        const Run run = cli({ u"show"_s, path });
        QFile::remove(path);
        QVERIFY2(run.exitCode == 0 || (run.exitCode == 2 && run.err.contains(u"not enough memory"_s)),
            qPrintable(u"exit %1: %2"_s.arg(run.exitCode).arg(run.err.left(500))));
    }

    void hugeTokensAreQuotedShort_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("head");
        QTest::addColumn<QByteArray>("tail");
        QTest::newRow("10 MB CSV column name")
            << u"header.csv"_s << QByteArray("number,") << QByteArray("\n1\n");
        QTest::newRow("10 MB tbl field") << u"field.tbl"_s << QByteArray("T1 P1 X") << QByteArray("\n");
        QTest::newRow("10 MB JSON key")
            << u"key.json"_s << QByteArray(R"({"format": "toffee-tool-table", "version": 1, ")")
            << QByteArray(R"(": 1})");
    }
    void hugeTokensAreQuotedShort()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, head);
        QFETCH(QByteArray, tail);
        const QString path = m_dir.filePath(name);
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(head + QByteArray(10 * 1024 * 1024, 'z') + tail);
        file.close();
        const Run run = cli({ u"show"_s, path });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.size() < 1000, qPrintable(run.err.left(1000)));
        QVERIFY2(run.err.contains(u"zzzz"_s), qPrintable(run.err));
    }

    void aFullDiskFailsTheConvertAndKeepsTheOldFile()
    {
        Toffee::Test::FullDisk disk;
        const QString target = disk.path(u"tools.json"_s);
        const QString example = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");
        QVERIFY(QFile::copy(example, target));
        const QByteArray before = contents(target);
        disk.fill();
        // A CSV of the same tools is different bytes: the convert must write, and cannot.
        const QString csv = m_dir.filePath(u"source.csv"_s);
        QCOMPARE(cli({ u"convert"_s, example, csv }).exitCode, 0);
        const Run run = cli({ u"convert"_s, csv, target });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(disk.reason()) && run.err.contains(u"old file is unchanged"_s),
            qPrintable(run.err));
        QVERIFY(!run.err.contains(u"wrote"_s));
        QCOMPARE(contents(target), before);
    }

    void aProbeOnAFullDiskIsNotRecordedAsSaved()
    {
        Toffee::Test::FullDisk disk;
        const QString table = disk.path(u"tools.json"_s);
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), table));
        QFile::setPermissions(table, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        const QByteArray before = contents(table);
        disk.fill();
        const Run run = cli({ u"--emulator"_s, u"--table"_s, table, u"probe"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(u"could not record it"_s) && run.err.contains(disk.reason()),
            qPrintable(run.err));
        QCOMPARE(contents(table), before);
    }
};

QTEST_GUILESS_MAIN(TestHostileFiles)
#include "tst_hostilefiles.moc"
