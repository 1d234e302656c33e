// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "model/formats/tablefile.h"
#include "tests/support/testtables.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestLinuxCncTableFormat : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTrips_data()
    {
        QTest::addColumn<ToolTable>("table");
        QTest::newRow("what LinuxCNC can hold") << Test::linuxCncTable();
        QTest::newRow("empty") << ToolTable();
    }
    void roundTrips()
    {
        QFETCH(ToolTable, table);
        Test::verifyRoundTrip(table, TableFormat::LinuxCnc);
    }

    void writesTheGrammarLinuxCncReads()
    {
        const QByteArray written = writeLinuxCncTable(Test::linuxCncTable());
        QCOMPARE(written,
            QByteArray("T0 P0 Z0.1\n"
                       "T1 P1 Z38.1 D3.175 ;3.175 mm flat, \"2F\"; \xc3\x98"
                       "1/8\n"
                       "T2 P7 Z71.488 ;6 mm end mill\n"
                       "T99999 P99999 Z-999.999 D0.125 X0.25 I95 J155 Q2 ;big tool number\n"));
    }

    void foldsWearIntoLengthAndDiameter()
    {
        Tool tool;
        tool.number = 1;
        tool.lengthGeometry = 100.0;
        tool.lengthWear = -0.1;
        tool.radiusGeometry = 3.0;
        tool.radiusWear = -0.01;
        const auto table = ToolTable::fromTools({ tool }, Units::Millimetre).takeValue();
        QCOMPARE(writeLinuxCncTable(table), QByteArray("T1 P1 Z99.9 D5.98\n"));
        QCOMPARE(formatLosses(table, TableFormat::LinuxCnc).size(), 1);
    }

    void loadsLinuxCncsOwnFiles_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("count");
        QTest::addColumn<int>("number");
        QTest::addColumn<double>("length");
        QTest::addColumn<double>("radius");
        QTest::addColumn<QString>("description");
        QTest::addColumn<QString>("extra");
        QTest::newRow("mill") << u"linuxcnc-mill.tbl"_s << 5 << 3 << 1.273 << 0.1005 << u"#7 tap drill"_s
                              << QString();
        QTest::newRow("mill, lower case") << u"linuxcnc-mill.tbl"_s << 5 << 4 << -0.25 << 0.0
                                          << u"lower-case letters load too"_s << QString();
        QTest::newRow("mill, big number")
            << u"linuxcnc-mill.tbl"_s << 5 << 99999 << 0.1 << 0.0 << u"big tool number"_s << QString();
        QTest::newRow("lathe, CRLF") << u"linuxcnc-lathe.tbl"_s << 2 << 1 << 1.5 << 0.015625
                                     << u"lathe tool in the spindle"_s << u"X0 I95 J155 Q2"_s;
        QTest::newRow("lathe, no comment")
            << u"linuxcnc-lathe.tbl"_s << 2 << 2 << 0.25 << 0.0 << QString() << u"X-0.1 Q7"_s;
    }
    void loadsLinuxCncsOwnFiles()
    {
        QFETCH(QString, file);
        QFETCH(int, count);
        QFETCH(int, number);
        QFETCH(double, length);
        QFETCH(double, radius);
        QFETCH(QString, description);
        QFETCH(QString, extra);
        const auto table = loadTableFile(QStringLiteral(TOFFEE_TEST_DATA "/") + file);
        QVERIFY2(table.ok(), qPrintable(table.error().text()));
        QCOMPARE(table.value().size(), count);
        const Tool *tool = table.value().find(number);
        QVERIFY(tool);
        QCOMPARE(tool->lengthGeometry, length);
        QCOMPARE(tool->radiusGeometry, radius);
        QCOMPARE(tool->description, description);
        QCOMPARE(tool->linuxCncExtra, extra);
    }

    void readsInches()
    {
        const auto table = readLinuxCncTable("T1 P1 Z0.511\n", Units::Inch);
        QVERIFY(table.ok());
        QCOMPARE(table.value().units(), Units::Inch);
        QVERIFY(!readLinuxCncTable("T1 P1 Z150\n", Units::Inch).ok()); // 150 in is beyond any inch controller
    }

    void reportsAMalformedLineWithItsNumber_data()
    {
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("message");
        const QByteArray ok = "; header comment\nT1 P1 Z1\n\n"; // lines 1-3, so a bad line 4 is counted right
        QTest::newRow("no pocket") << ok + "T2 Z1" << 4 << u"no pocket (P)"_s;
        QTest::newRow("no tool number") << ok + "P2 Z1" << 4 << u"no tool number (T)"_s;
        QTest::newRow("letter without value") << ok + "T2 P2 Z" << 4 << u"\"Z\": Z needs a number"_s;
        QTest::newRow("value not a number") << ok + "T2 P2 Zabc" << 4 << u"Z needs a number"_s;
        QTest::newRow("unknown letter") << ok + "T2 P2 K5" << 4 << u"\"K5\" is not a tool table field"_s;
        QTest::newRow("field twice") << ok + "T2 P2 Z1 Z2" << 4 << u"appears twice"_s;
        QTest::newRow("fractional tool") << ok + "T2.5 P2" << 4 << u"T needs a whole number"_s;
        QTest::newRow("fractional pocket") << ok + "T2 P2.5" << 4 << u"P needs a whole number"_s;
        QTest::newRow("orientation out of range") << ok + "T2 P2 Q12" << 4 << u"Q must be 0 to 9"_s;
        QTest::newRow("fractional orientation") << ok + "T2 P2 Q1.5" << 4 << u"Q needs a whole number"_s;
        QTest::newRow("negative tool") << ok + "T-3 P2" << 4 << u"tool number -3"_s;
        QTest::newRow("pocket out of range") << ok + "T2 P100000" << 4 << u"pocket 100000"_s;
        QTest::newRow("duplicate tool") << ok + "T1 P2 Z3" << 4 << u"tool 1 is already on line 2"_s;
        QTest::newRow("length out of range") << ok + "T2 P2 Z5000" << 4 << u"out of range"_s;
        QTest::newRow("binary data") << ok + QByteArray("T2 P2\0Z1", 8) << 4 << u"binary data"_s;
        QTest::newRow("comment not UTF-8") << ok + "T2 P2 ;caf\xe9" << 4 << u"not valid UTF-8"_s;
        QTest::newRow("overflowing number") << ok + "T2 P2 D1e400" << 4 << u"D needs a number"_s;
        QTest::newRow("nan") << ok + "T2 P2 Znan" << 4 << u"Z needs a number"_s;
        QTest::newRow("two signs") << ok + "T2 P2 Z+-1" << 4 << u"Z needs a number"_s;
        QTest::newRow("a word") << ok + "garbage" << 4 << u"not a tool table field"_s;
        QTest::newRow("fields run together") << ok + "T2P2" << 4 << u"T needs a whole number"_s;
        QTest::newRow("axis without value") << ok + "T2 P2 X" << 4 << u"X needs a number"_s;
        QTest::newRow("bare T") << ok + "T" << 4 << u"T needs a whole number"_s;
        QTest::newRow("bad line first") << QByteArray("Z1 T1\n") << 1 << u"no pocket"_s;
    }
    void reportsAMalformedLineWithItsNumber()
    {
        QFETCH(QByteArray, data);
        QFETCH(int, line);
        QFETCH(QString, message);
        Test::verifyRefused(readLinuxCncTable(data, Units::Millimetre), line, message);
    }
};

QTEST_GUILESS_MAIN(TestLinuxCncTableFormat)
#include "tst_linuxcnctableformat.moc"
