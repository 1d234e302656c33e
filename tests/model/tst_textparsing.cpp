// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "model/textparsing.h"

using namespace Toffee;

class TestTextParsing : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void parsesDecimals_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<double>("value");
        QTest::newRow("integer") << QByteArray("12") << true << 12.0;
        QTest::newRow("negative") << QByteArray("-105.688") << true << -105.688;
        QTest::newRow("leading plus (LinuxCNC writes it)") << QByteArray("+0.511000") << true << 0.511;
        QTest::newRow("leading point") << QByteArray(".5") << true << 0.5;
        QTest::newRow("exponent") << QByteArray("1e-3") << true << 0.001;
        QTest::newRow("zero") << QByteArray("0") << true << 0.0;
        QTest::newRow("empty") << QByteArray("") << false << 0.0;
        QTest::newRow("lone sign") << QByteArray("-") << false << 0.0;
        QTest::newRow("double sign") << QByteArray("+-1") << false << 0.0;
        QTest::newRow("trailing garbage") << QByteArray("1.5mm") << false << 0.0;
        QTest::newRow("comma decimal") << QByteArray("1,5") << false << 0.0;
        QTest::newRow("inf") << QByteArray("inf") << false << 0.0;
        QTest::newRow("nan") << QByteArray("nan") << false << 0.0;
        QTest::newRow("hex") << QByteArray("0x10") << false << 0.0;
        QTest::newRow("overflow") << QByteArray("1e400") << false << 0.0;
        QTest::newRow("inner space") << QByteArray("1 2") << false << 0.0;
    }
    void parsesDecimals()
    {
        QFETCH(QByteArray, text);
        QFETCH(bool, valid);
        QFETCH(double, value);
        const auto parsed = parseDecimal(text);
        QCOMPARE(parsed.has_value(), valid);
        if (valid)
            QCOMPARE(*parsed, value);
    }

    void parsesIntegers_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<qint64>("value");
        QTest::newRow("tool") << QByteArray("5") << true << qint64(5);
        QTest::newRow("plus") << QByteArray("+7") << true << qint64(7);
        QTest::newRow("minus one (empty spindle)") << QByteArray("-1") << true << qint64(-1);
        QTest::newRow("decimal") << QByteArray("5.0") << false << qint64(0);
        QTest::newRow("letters") << QByteArray("5a") << false << qint64(0);
        QTest::newRow("empty") << QByteArray() << false << qint64(0);
        QTest::newRow("too big") << QByteArray("99999999999999999999") << false << qint64(0);
    }
    void parsesIntegers()
    {
        QFETCH(QByteArray, text);
        QFETCH(bool, valid);
        QFETCH(qint64, value);
        const auto parsed = parseInteger(text);
        QCOMPARE(parsed.has_value(), valid);
        if (valid)
            QCOMPARE(*parsed, value);
    }

    void refusesInvalidUtf8()
    {
        QVERIFY(decodeUtf8("caf\xc3\xa9").has_value());
        QCOMPARE(*decodeUtf8("caf\xc3\xa9"), QStringLiteral("café"));
        QVERIFY(!decodeUtf8("caf\xe9").has_value());
        QVERIFY(!decodeUtf8(QByteArray("a\0b", 3)).has_value());
    }
};

QTEST_GUILESS_MAIN(TestTextParsing)
#include "tst_textparsing.moc"
