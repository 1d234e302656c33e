// SPDX-License-Identifier: GPL-3.0-or-later
// LineReader: a file a line at a time, whatever its size, its line ends or what stands in its place.
#include <QTemporaryDir>
#include <QTest>

#include "tests/support/specialfiles.h"

#include "model/formats/linereader.h"

using namespace Qt::StringLiterals;
using namespace Toffee;

namespace {

QString write(const QTemporaryDir &dir, const QByteArray &content)
{
    const QString path = dir.filePath(u"program.nc"_s);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return {};
    file.write(content);
    return path;
}

QList<QByteArray> readAll(const QString &path, std::optional<Error> *error = nullptr)
{
    LineReader reader;
    QList<QByteArray> lines;
    if (auto opened = reader.open(path); !opened) {
        if (error)
            *error = opened.error();
        return lines;
    }
    QByteArrayView line;
    while (reader.next(line)) {
        lines.append(line.toByteArray());
        if (reader.lineNumber() != lines.size())
            return {};
    }
    if (error)
        *error = reader.error();
    return lines;
}

} // namespace

class TestLineReader : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void readsLinesWithAnyEnd_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QList<QByteArray>>("lines");
        QTest::newRow("empty") << QByteArray() << QList<QByteArray> {};
        QTest::newRow("one, no end") << QByteArray("G0 X1") << QList<QByteArray> { "G0 X1" };
        QTest::newRow("LF") << QByteArray("G0\nG1\n") << QList<QByteArray> { "G0", "G1" };
        QTest::newRow("CRLF") << QByteArray("G0\r\nG1\r\n") << QList<QByteArray> { "G0", "G1" };
        QTest::newRow("CRLF, last without") << QByteArray("G0\r\nG1\r") << QList<QByteArray> { "G0", "G1" };
        QTest::newRow("empty lines") << QByteArray("\n\nM30\n") << QList<QByteArray> { "", "", "M30" };
        QTest::newRow("UTF-8 byte-order mark")
            << QByteArray("\xEF\xBB\xBFG21\nM30") << QList<QByteArray> { "G21", "M30" };
    }

    void readsLinesWithAnyEnd()
    {
        QFETCH(QByteArray, content);
        QFETCH(QList<QByteArray>, lines);
        QTemporaryDir dir;
        std::optional<Error> error;
        QCOMPARE(readAll(write(dir, content), &error), lines);
        QVERIFY(!error);
    }

    void readsLinesAcrossItsBuffer()
    {
        // Lines of every length from 1 to 3000 bytes, so that many straddle the megabyte the reader holds.
        QByteArray content;
        QList<QByteArray> expected;
        for (int i = 0; content.size() < 3 * 1024 * 1024; ++i) {
            const QByteArray line = QByteArray::number(i) + ' ' + QByteArray(i % 3000, 'x');
            content += line + '\n';
            expected.append(line);
        }
        QTemporaryDir dir;
        QCOMPARE(readAll(write(dir, content)), expected);
    }

    void refusesALineLongerThanAnyProgramHas()
    {
        QTemporaryDir dir;
        std::optional<Error> error;
        const QList<QByteArray> lines = readAll(
            write(dir, "G0\nG1\n" + QByteArray(LineReader::kMaxLineBytes + 1, 'X') + "\nM30\n"), &error);
        QCOMPARE(lines.size(), 2);
        QVERIFY(error);
        QCOMPARE(error->line, 3);
        QVERIFY2(error->text().contains(u"line 3 is longer than 64 KB"_s), qPrintable(error->text()));
        // A line of exactly the limit is read.
        QCOMPARE(readAll(write(dir, QByteArray(LineReader::kMaxLineBytes, 'Y'))).size(), 1);
        // And a file of one endless line is refused without reading it all.
        QFile huge(dir.filePath(u"huge.nc"_s));
        QVERIFY(huge.open(QIODevice::WriteOnly));
        QVERIFY(huge.resize(200LL * 1024 * 1024)); // sparse: nothing but zero bytes, no line end
        huge.close();
        QVERIFY(readAll(huge.fileName(), &error).isEmpty());
        QVERIFY(error && error->line == 1);
    }

    void refusesWhatIsNotText()
    {
        QTemporaryDir dir;
        std::optional<Error> error;
        // UTF-16: every other byte is NUL.
        const QList<QByteArray> lines = readAll(write(dir, QByteArray("G\0002\0001\000\n\000", 9)), &error);
        QVERIFY(lines.isEmpty());
        QVERIFY(error);
        QCOMPARE(error->line, 1);
        QVERIFY2(error->message.contains(u"not a text program"_s), qPrintable(error->message));
    }

    void refusesWhatIsNotAFileByName_data() { Test::addSpecialFileRows(); }

    void refusesWhatIsNotAFileByName()
    {
        QFETCH(QString, kind);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = dir.filePath(u"special"_s);
        QVERIFY(Test::makeSpecialFile(kind, path));
        std::optional<Error> error;
        QVERIFY(readAll(path, &error).isEmpty());
        QVERIFY(error);
        QVERIFY2(
            error->message.startsWith(path) && error->message.contains(expected), qPrintable(error->message));
    }
};

QTEST_GUILESS_MAIN(TestLineReader)
#include "tst_linereader.moc"
