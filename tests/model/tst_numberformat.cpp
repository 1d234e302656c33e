// SPDX-License-Identifier: GPL-3.0-or-later
// The one number formatter: files, machine commands and the window each get their format from it.
#include <limits>

#include <QLocale>
#include <QTest>

#include "model/numberformat.h"
#include "model/textparsing.h"

using namespace Qt::StringLiterals;
using namespace Toffee;

class TestNumberFormat : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void cleanup() { QLocale::setDefault(QLocale::c()); }

    void writesFilesExactlyAndWithoutExponent_data()
    {
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("text");
        QTest::newRow("seed TLO") << -33.388 << u"-33.388"_s;
        QTest::newRow("integer") << 45.0 << u"45"_s;
        QTest::newRow("negative zero") << -0.0 << u"0"_s;
        QTest::newRow("tiny") << 0.00001 << u"0.00001"_s;
        QTest::newRow("tenth") << 0.1 << u"0.1"_s;
        QTest::newRow("seven decimals") << 1.2345678 << u"1.2345678"_s;
        QTest::newRow("large") << 1e20 << u"100000000000000000000"_s;
    }
    void writesFilesExactlyAndWithoutExponent()
    {
        QFETCH(double, value);
        QFETCH(QString, text);
        QCOMPARE(formatNumber(value), text);
        QCOMPARE(parseDecimal(text.toLatin1()), value);
        QByteArray bytes = "Z";
        appendNumber(bytes, value);
        QCOMPARE(bytes, "Z" + text.toLatin1());
    }

    void writesANumberThatIsNotFiniteAsZeroOnlyWhenExact()
    {
        QCOMPARE(formatNumber(std::numeric_limits<double>::quiet_NaN()), u"0"_s);
        QCOMPARE(formatNumber(std::numeric_limits<double>::infinity()), u"0"_s);
        // A display that is told a number must never show a made-up zero for an infinity.
        QCOMPARE(formatNumber(std::numeric_limits<double>::infinity(), NumberFormat::fixed(3)), u"inf"_s);
    }

    void roundsFixedDecimalsAsPrintfDoes_data()
    {
        QTest::addColumn<double>("value");
        QTest::addColumn<int>("decimals");
        QTest::addColumn<QString>("text");
        QTest::newRow("pads") << 2.0 << 3 << u"2.000"_s;
        QTest::newRow("rounds up") << 30.4886 << 3 << u"30.489"_s;
        QTest::newRow("rounds down") << -30.4884 << 3 << u"-30.488"_s;
        QTest::newRow("binary below half")
            << 1.0005 << 3 << u"1.000"_s; // 1.0005 is 1.000499999... as a double
        QTest::newRow("no decimals") << 12.6 << 0 << u"13"_s;
        QTest::newRow("never -0.000") << -0.0001 << 3 << u"0.000"_s;
        QTest::newRow("four for inches") << 0.5 << 4 << u"0.5000"_s;
    }
    void roundsFixedDecimalsAsPrintfDoes()
    {
        QFETCH(double, value);
        QFETCH(int, decimals);
        QFETCH(QString, text);
        QCOMPARE(formatNumber(value, NumberFormat::fixed(decimals)), text);
        QCOMPARE(formatNumber(value, NumberFormat::fixed(decimals)),
            QString::number(value, 'f', decimals).replace(u"-0.000"_s, u"0.000"_s));
    }

    void writesCommandsWithAtMostFourDecimalsAndNoTrailingZeros()
    {
        QCOMPARE(numberBytes(-30.488, NumberFormat::command()), "-30.488");
        QCOMPARE(numberBytes(-30.5, NumberFormat::command()), "-30.5");
        QCOMPARE(numberBytes(0.25, NumberFormat::command()), "0.25");
        QCOMPARE(numberBytes(12.0, NumberFormat::command()), "12");
        QCOMPARE(numberBytes(0.123456, NumberFormat::command()), "0.1235");
        QCOMPARE(numberBytes(-0.00001, NumberFormat::command()), "0");
    }

    void displaysAtLeastTheUnitsDecimalsButHidesNone()
    {
        QCOMPARE(displayNumber(-33.388, Units::Millimetre), u"-33.388"_s);
        QCOMPARE(displayNumber(2, Units::Millimetre), u"2.000"_s);
        QCOMPARE(displayNumber(1.5875, Units::Millimetre), u"1.5875"_s);
        QCOMPARE(displayNumber(0.5, Units::Inch), u"0.5000"_s);
        QCOMPARE(displayNumber(0.0, Units::Inch), u"0.0000"_s);
    }

    void quotesAHugeNumberInAMessageShortly()
    {
        QCOMPARE(quotedNumber(1500.25), u"1500.25"_s);
        QCOMPARE(quotedNumber(-100000), u"-100000"_s);
        QCOMPARE(quotedNumber(1e308), u"1e+308"_s);
        QCOMPARE(quotedNumber(-1.5e300), u"-1.5e+300"_s);
        QCOMPARE(quotedNumber(1e-300), u"1e-300"_s);
    }

    void showsPeopleTheirOwnDecimalMarkButNeverGroups()
    {
        QCOMPARE(millimetres(-33.388), u"-33.388 mm"_s);
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        QCOMPARE(millimetres(-33.388), u"-33,388 mm"_s);
        QCOMPARE(millimetres(1234.5, false), u"1234,500"_s);
        QCOMPARE(millimetres(-0.0002), u"0,000 mm"_s);
        QCOMPARE(formatNumber(0.25, NumberFormat::upTo(4).inLocale()), u"0,25"_s);
        // Files and machines get a point whatever the locale.
        QCOMPARE(formatNumber(-33.388), u"-33.388"_s);
        QCOMPARE(numberBytes(-33.388, NumberFormat::fixed(3)), "-33.388");
    }
};

QTEST_GUILESS_MAIN(TestNumberFormat)
#include "tst_numberformat.moc"
