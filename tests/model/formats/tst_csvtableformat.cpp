// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "model/formats/tablefile.h"
#include "tests/support/testtables.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestCsvTableFormat : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTrips_data()
    {
        QTest::addColumn<ToolTable>("table");
        QTest::newRow("awkward values, mm") << Test::awkwardTable();
        QTest::newRow("awkward values, inch") << Test::awkwardTable(Units::Inch);
        QTest::newRow("empty") << ToolTable();
        QTest::newRow("500 generated tools") << Test::generatedTable(500);
    }
    void roundTrips()
    {
        QFETCH(ToolTable, table);
        Test::verifyRoundTrip(table, TableFormat::Csv);
    }

    void readsWhatSpreadsheetsWrite_data()
    {
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<int>("number");
        QTest::addColumn<double>("length");
        QTest::addColumn<QString>("description");
        QTest::newRow("only the number column") << QByteArray("number\n7\n") << 7 << 0.0 << QString();
        QTest::newRow("columns in another order")
            << QByteArray("description,length_geometry,number\nroughing,12.5,3\n") << 3 << 12.5
            << u"roughing"_s;
        QTest::newRow("upper-case header")
            << QByteArray("NUMBER,Length_Geometry\n3,1\n") << 3 << 1.0 << QString();
        QTest::newRow("byte-order mark and CRLF")
            << QByteArray("\xEF\xBB\xBFnumber,length_geometry\r\n4,2.25\r\n") << 4 << 2.25 << QString();
        QTest::newRow("semicolons and decimal commas (German Excel)")
            << QByteArray("number;length_geometry;description\n5;71,488;\"Fräser; 6 mm\"\n") << 5 << 71.488
            << u"Fräser; 6 mm"_s;
        QTest::newRow("blank lines") << QByteArray("\nnumber,length_geometry\n\n6,3\n\n") << 6 << 3.0
                                     << QString();
        QTest::newRow("spaces around fields")
            << QByteArray("number , length_geometry\n 8 , 4.5 \n") << 8 << 4.5 << QString();
    }
    void readsWhatSpreadsheetsWrite()
    {
        QFETCH(QByteArray, data);
        QFETCH(int, number);
        QFETCH(double, length);
        QFETCH(QString, description);
        const auto read = readCsvTable(data);
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().size(), 1);
        QCOMPARE(read.value().at(0).number, number);
        QCOMPARE(read.value().at(0).lengthGeometry, length);
        QCOMPARE(read.value().at(0).description, description);
    }

    void reportsAMalformedFileWithItsLine_data()
    {
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("message");
        const QByteArray head = "number,pocket,description,length_geometry,length_wear,measured_tlo,measured_"
                                "at,units,linuxcnc\n"
                                "1,1,first,10,0,,,mm,\n"; // lines 1-2
        QTest::newRow("empty file") << QByteArray() << 1 << u"empty"_s;
        QTest::newRow("unknown column")
            << QByteArray("number,lenght\n1,2\n") << 1 << u"unknown column \"lenght\""_s;
        QTest::newRow("column twice") << QByteArray("number,pocket,number\n") << 1 << u"appears twice"_s;
        QTest::newRow("no number column")
            << QByteArray("pocket,description\n1,x\n") << 1 << u"no \"number\" column"_s;
        QTest::newRow("too few fields") << head + "2,2,second\n" << 3 << u"3 fields but the header has 9"_s;
        QTest::newRow("too many fields") << head + "2,2,x,1,0,,,mm,,extra\n"
                                         << 3 << u"more fields than the header's 9"_s;
        QTest::newRow("no tool number") << head + ",2,x,1,0,,,mm,\n" << 3 << u"no tool number"_s;
        QTest::newRow("tool number not whole") << head + "2.5,2,x,1,0,,,mm,\n"
                                               << 3 << u"not a whole number"_s;
        QTest::newRow("pocket not whole") << head + "2,two,x,1,0,,,mm,\n" << 3 << u"pocket \"two\""_s;
        QTest::newRow("length not a number") << head + "2,2,x,ten,0,,,mm,\n"
                                             << 3 << u"length_geometry \"ten\""_s;
        QTest::newRow("decimal comma with comma separator") << head + "2,2,x,\"1,5\",0,,,mm,\n"
                                                            << 3 << u"not a number"_s;
        QTest::newRow("wear out of range") << head + "2,2,x,1,-150,,,mm,\n" << 3 << u"length wear -150 mm"_s;
        QTest::newRow("duplicate tool") << head + "2,2,x,1,0,,,mm,\n1,3,y,1,0,,,mm,\n"
                                        << 4 << u"already on line 2"_s;
        QTest::newRow("unknown units") << head + "2,2,x,1,0,,,cm,\n" << 3 << u"units \"cm\""_s;
        QTest::newRow("mixed units") << head + "2,2,x,1,0,,,in,\n" << 3 << u"one unit"_s;
        QTest::newRow("quote never closed") << head + "2,2,\"open,1,0,,,mm,\n3,3,x,1,0,,,mm,\n"
                                            << 3 << u"never closed"_s;
        QTest::newRow("quote inside a field") << head + "2,2,ab\"c,1,0,,,mm,\n"
                                              << 3 << u"inside an unquoted field"_s;
        QTest::newRow("text after a quote") << head + "2,2,\"ab\"c,1,0,,,mm,\n"
                                            << 3 << u"after a closing quote"_s;
        QTest::newRow("bad date") << head + "2,2,x,1,0,-3,last week,mm,\n" << 3 << u"not a date"_s;
        QTest::newRow("TLO not a number") << head + "2,2,x,1,0,abc,,mm,\n" << 3 << u"measured_tlo \"abc\""_s;
        QTest::newRow("binary data") << head + QByteArray("2,2,\0,1", 7) << 3 << u"binary data"_s;
        QTest::newRow("not UTF-8") << head + "2,2,caf\xe9,1,0,,,mm,\n" << 3 << u"not UTF-8"_s;
        QTest::newRow("description over two lines") << head + "2,2,\"two\nlines\",1,0,,,mm,\n"
                                                    << 3 << u"one line"_s;
        QTest::newRow("line counted after a multi-line field")
            << QByteArray("number,notes\n1,\"a\nb\nc\"\n2,ok\nx,bad\n") << 6 << u"not a whole number"_s;
        QTest::newRow("bad LinuxCNC extra") << head + "2,2,x,1,0,,,mm,K9\n"
                                            << 3 << u"\"K9\" is not a LinuxCNC"_s;
    }
    void reportsAMalformedFileWithItsLine()
    {
        QFETCH(QByteArray, data);
        QFETCH(int, line);
        QFETCH(QString, message);
        Test::verifyRefused(readCsvTable(data), line, message);
    }
};

QTEST_GUILESS_MAIN(TestCsvTableFormat)
#include "tst_csvtableformat.moc"
