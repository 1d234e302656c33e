// SPDX-License-Identifier: GPL-3.0-or-later
// Garbled files: thousands of mutations of valid tables through every reader. Each must come back as a
// table or as an error naming a line inside the file; never a crash, never a half-read table.
#include <QRandomGenerator>
#include <QTest>

#include "model/formats/tablefile.h"
#include "tests/support/testtables.h"

using namespace Toffee;

class TestReaderRobustness : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void survivesMutatedFiles_data()
    {
        QTest::addColumn<int>("format");
        QTest::newRow("json") << int(TableFormat::Json);
        QTest::newRow("tbl") << int(TableFormat::LinuxCnc);
        QTest::newRow("csv") << int(TableFormat::Csv);
    }
    void survivesMutatedFiles()
    {
        QFETCH(int, format);
        const auto f = TableFormat(format);
        const QByteArray original
            = writeTable(f == TableFormat::LinuxCnc ? Test::linuxCncTable() : Test::awkwardTable(), f);
        QRandomGenerator random(20261122 + format);
        const char interesting[] = "{}[]\",;:\\\n\r\t -+.0123456789eETPZDQ\x00\xff\xc3";
        int refused = 0;
        for (int round = 0; round < 4000; ++round) {
            QByteArray data = original;
            const int edits = 1 + int(random.bounded(4));
            for (int e = 0; e < edits && !data.isEmpty(); ++e) {
                const qsizetype at = random.bounded(data.size());
                switch (random.bounded(4)) {
                case 0: // overwrite a byte
                    data[at] = interesting[random.bounded(int(sizeof interesting - 1))];
                    break;
                case 1: // delete a run
                    data.remove(at, 1 + random.bounded(8));
                    break;
                case 2: // insert a byte
                    data.insert(at, interesting[random.bounded(int(sizeof interesting - 1))]);
                    break;
                default: // truncate
                    data.truncate(at);
                }
            }
            const auto read = readTable(data, f);
            if (read.ok()) {
                // Whatever was read is a valid table: re-reading what it writes gives it back.
                const auto again = readTable(writeTable(read.value(), f), f);
                QVERIFY(again.ok());
                QCOMPARE(again.value(), read.value());
                continue;
            }
            ++refused;
            const int lines = int(data.count('\n')) + 1;
            QVERIFY2(read.error().line >= 0 && read.error().line <= lines, qPrintable(read.error().text()));
            QVERIFY(!read.error().message.isEmpty());
        }
        QVERIFY(refused > 500); // the mutations do produce bad files
    }
};

QTEST_GUILESS_MAIN(TestReaderRobustness)
#include "tst_readerrobustness.moc"
