// SPDX-License-Identifier: GPL-3.0-or-later
// HSMWorks / Fusion .hsmlib tool libraries (model/camimport/hsmlibrary.cpp).
#include <QRegularExpression>
#include <QTest>

#include "model/camimport/camreaders.h"
#include "tests/support/camfiles.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestHsmLibrary : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void readsAUtf16LibraryWithItsByteOrderMark()
    {
        const QByteArray xml = Test::hsmLibrary(Test::hsmTool(4)
            + Test::hsmTool(
                12, u"diameter=\"0.125\" flute-length=\"0.5\""_s, u"inches"_s, u"⅛ in ball, Ø"_s));
        QVERIFY(xml.startsWith("\xff\xfe<\0?\0"_ba));
        const auto read = readHsmLibrary(xml);
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().size(), 2);
        const CamTool &t4 = read.value().at(0);
        QCOMPARE(t4.number, 4);
        QCOMPARE(t4.description, u"6 mm flat"_s);
        QCOMPARE(t4.type, u"flat end mill"_s);
        QCOMPARE(t4.units, Units::Millimetre);
        QCOMPARE(t4.diameter, 6.0);
        QCOMPARE(t4.fluteLength, 20.0);
        QCOMPARE(t4.overallLength, 50.0);
        QCOMPARE(t4.line, 3);
        const CamTool &t12 = read.value().at(1);
        QCOMPARE(t12.number, 12);
        QCOMPARE(t12.description, u"⅛ in ball, Ø"_s);
        QCOMPARE(t12.units, Units::Inch);
        QCOMPARE(t12.diameter, 0.125);
        QCOMPARE(t12.overallLength, std::nullopt);
    }

    void readsTheLengthOffsetForANote()
    {
        const auto read = readHsmLibrary(Test::hsmLibrary(Test::hsmTool(4)
            + QString(Test::hsmTool(5)).replace(u"length-offset=\"5\""_s, u"length-offset=\"25\""_s)));
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().at(0).lengthOffset, 4);
        QCOMPARE(read.value().at(1).lengthOffset, 25);
    }

    void readsTheOlderToolTableAndUtf8()
    {
        const QString xml
            = u"<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<tool-table xmlns=\"%1\">\n%2</tool-table>\n"_s
                  .arg(QLatin1StringView(Test::kHsmNamespace), Test::hsmTool(1));
        const auto read = readHsmLibrary(xml.toUtf8());
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().front().number, 1);
    }

    void refusesAMalformedLibraryWhole_data()
    {
        QTest::addColumn<QByteArray>("xml");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("message");
        const QString good = Test::hsmTool(1);
        const QByteArray whole = Test::hsmLibrary(good + Test::hsmTool(2));
        QTest::newRow("truncated") << whole.first(whole.size() / 2 & ~1) << 0 << u"not well-formed XML"_s;
        QTest::newRow("unclosed element") << Test::hsmLibrary(
            QString(good).replace(u"<coolant mode=\"flood\"/>"_s, u"<coolant mode=\"flood\">"_s))
                                          << 0 << u"not well-formed XML"_s;
        QTest::newRow("not XML") << "G21\nG0 X0\n"_ba << 1 << u"not well-formed XML"_s;
        QTest::newRow("empty") << QByteArray() << 1 << u"not well-formed XML"_s;
        QTest::newRow("wrong namespace") << Test::hsmLibrary(good, u"tool-library"_s,
            u"urn:other"_s) << 2 << u"its root element is <tool-library> in namespace \"urn:other\""_s;
        QTest::newRow("wrong root") << Test::hsmLibrary(good, u"tools"_s) << 2
                                    << u"its root element is <tools>"_s;
        QTest::newRow("nc number abc")
            << Test::hsmLibrary(QString(good).replace(u"nc number=\"1\""_s, u"nc number=\"abc\""_s)) << 5
            << u"tool 1: its nc number is \"abc\", not a tool number."_s;
        QTest::newRow("diameter NaN") << Test::hsmLibrary(Test::hsmTool(1, u"diameter=\"NaN\""_s)) << 7
                                      << u"tool 1: its body diameter is \"NaN\", not a number."_s;
        QTest::newRow("negative diameter") << Test::hsmLibrary(Test::hsmTool(1, u"diameter=\"-3\""_s)) << 3
                                           << u"tool 1 (T1): the diameter is -3 mm; it cannot be negative."_s;
        QTest::newRow("no nc") << Test::hsmLibrary(QString(good).remove(QRegularExpression(u"<nc [^>]*>"_s)))
                               << 0 << u"tool 1: it has no <nc number=…>"_s;
        QTest::newRow("no unit") << Test::hsmLibrary(Test::hsmTool(1, u"diameter=\"6\""_s, u""_s)) << 3
                                 << u"tool 1: its unit is \"\""_s;
        QTest::newRow("repeated number") << Test::hsmLibrary(good + Test::hsmTool(2) + good) << 21
                                         << u"tool 3 (T1): number 1 is taken already (tool 1)"_s;
        QTest::newRow("no tools") << Test::hsmLibrary({}) << 0 << u"holds no tools"_s;
        QTest::newRow("two nc") << Test::hsmLibrary(
            good + QString(Test::hsmTool(2)).replace(u"<coolant mode=\"flood\"/>"_s, u"<nc number=\"7\"/>"_s))
                                << 15 << u"tool 2: it has a second <nc> (the first is on line 14)"_s;
        QTest::newRow("two bodies") << Test::hsmLibrary(QString(good).replace(
            u"<motion spindle-rpm=\"18000\" cutting-feedrate=\"800\"/>"_s, u"<body diameter=\"8\"/>"_s))
                                    << 9 << u"tool 1: it has a second <body> (the first is on line 8)"_s;
        QTest::newRow("two descriptions")
            << Test::hsmLibrary(QString(good).replace(
                   u"<coolant mode=\"flood\"/>"_s, u"<description>other</description>"_s))
            << 6 << u"tool 1: it has a second <description> (the first is on line 4)"_s;
        QTest::newRow("length offset abc")
            << Test::hsmLibrary(QString(good).replace(u"length-offset=\"1\""_s, u"length-offset=\"H1\""_s))
            << 5 << u"tool 1: its nc length-offset is \"H1\", not a whole number."_s;
    }
    void refusesAMalformedLibraryWhole()
    {
        QFETCH(QByteArray, xml);
        QFETCH(int, line);
        QFETCH(QString, message);
        const auto read = readHsmLibrary(xml);
        QVERIFY2(!read.ok(), "the library was read");
        QVERIFY2(read.error().message.contains(message), qPrintable(read.error().message));
        if (line > 0)
            QCOMPARE(read.error().line, line);
    }

    void aSyntaxErrorNamesItsLineAndColumn()
    {
        const QString xml
            = u"<tool-library xmlns=\"%1\">\n  <tool unit=\"millimeters\">\n    <nc number=1/>\n"_s.arg(
                QLatin1StringView(Test::kHsmNamespace));
        const auto read = readHsmLibrary(xml.toUtf8());
        QVERIFY(!read.ok());
        QCOMPARE(read.error().line, 3);
        QVERIFY2(read.error().message.startsWith(u"column 16: this is not well-formed XML"_s),
            qPrintable(read.error().message));
    }
};

QTEST_GUILESS_MAIN(TestHsmLibrary)
#include "tst_hsmlibrary.moc"
