// SPDX-License-Identifier: GPL-3.0-or-later
// HSMWorks / Fusion .hsmlib tool libraries (model/camimport/hsmlibrary.cpp).
#include <QRegularExpression>
#include <QStringEncoder>
#include <QTest>

#include "model/camimport/camreaders.h"
#include "tests/support/camfiles.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

// A library of `tools` as text, without the encoding its bytes are in; the first tool's <tool> on line 3.
QString libraryText(const QString &tools, const QString &declaration = u"UTF-16"_s)
{
    return u"<?xml version=\"1.0\" encoding=\"%1\"?>\n<tool-library xmlns=\"%2\" version=\"18\">\n%3"
           u"</tool-library>\n"_s.arg(declaration, QLatin1StringView(Test::kHsmNamespace), tools);
}

QByteArray encoded(const QString &text, QStringConverter::Encoding encoding, bool bom)
{
    QStringEncoder encoder(encoding, bom ? QStringEncoder::Flag::WriteBom : QStringEncoder::Flag::Default);
    return encoder.encode(text);
}

// `count` attributes a1="1" a2="2" …, separated by `separator`.
QString attributes(int count, const QString &name = u"a"_s, const QString &separator = u" "_s)
{
    QString out;
    for (int i = 1; i <= count; ++i)
        out += separator + name + QString::number(i) + u"=\""_s + QString::number(i) + u'"';
    return out;
}

// Tool 1 with its holder `levels` elements deep inside <tool> (<tool> itself is at depth 2).
QString deepTool(int levels)
{
    return QString(Test::hsmTool(1))
        .replace(u"<holder><section diameter=\"16\" length=\"20\"/></holder>"_s,
            QString(u"<holder>"_s).repeated(levels) + QString(u"</holder>"_s).repeated(levels));
}

} // namespace

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
        QTest::newRow("an odd number of UTF-16 bytes") << whole.chopped(1) << 0 << u"not well-formed XML"_s;
        QTest::newRow("not US-ASCII") << libraryText(good, u"US-ASCII"_s).toLatin1().replace("6 mm", "\xe9")
                                      << 4 << u"it is not valid US-ASCII text."_s;
        QTest::newRow("an encoding Toffee does not know")
            << libraryText(good, u"EBCDIC-US"_s).toLatin1() << 1
            << u"it is in \"EBCDIC-US\", an encoding Toffee does not know; save it as UTF-16 or UTF-8."_s;
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

    void readsEveryEncodingXmlDetects_data()
    {
        QTest::addColumn<QByteArray>("xml");
        const QString tools
            = Test::hsmTool(4) + Test::hsmTool(12, u"diameter=\"0.125\""_s, u"inches"_s, u"⅛ in ball, Ø 😀"_s);
        const QString utf16 = libraryText(tools);
        // XML 1.0 Appendix F: without a byte-order mark, UTF-16 is known by its first bytes, 00 3C 00 3F or
        // 3C 00 3F 00.
        QTest::newRow("UTF-16BE without BOM") << encoded(utf16, QStringConverter::Utf16BE, false);
        QTest::newRow("UTF-16LE without BOM") << encoded(utf16, QStringConverter::Utf16LE, false);
        QTest::newRow("UTF-16BE with BOM") << encoded(utf16, QStringConverter::Utf16BE, true);
        QTest::newRow("UTF-16LE with BOM") << encoded(utf16, QStringConverter::Utf16LE, true);
        QTest::newRow("UTF-16BE, no declaration")
            << encoded(QString(utf16).remove(u"<?xml version=\"1.0\" encoding=\"UTF-16\"?>"_s),
                   QStringConverter::Utf16BE, false);
        QTest::newRow("UTF-16BE declared UTF-16BE")
            << encoded(libraryText(tools, u"UTF-16BE"_s), QStringConverter::Utf16BE, false);
        QTest::newRow("UTF-8") << libraryText(tools, u"UTF-8"_s).toUtf8();
        QTest::newRow("UTF-8 with BOM") << "\xef\xbb\xbf"_ba + libraryText(tools, u"UTF-8"_s).toUtf8();
    }
    void readsEveryEncodingXmlDetects()
    {
        QFETCH(QByteArray, xml);
        const auto read = readHsmLibrary(xml);
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().size(), 2);
        QCOMPARE(read.value().at(0).line, 3);
        QCOMPARE(read.value().at(1).number, 12);
        QCOMPARE(read.value().at(1).description, u"⅛ in ball, Ø 😀"_s);
        QCOMPARE(read.value().at(1).line, 12);
    }

    void readsADeclaredEightBitEncoding()
    {
        const QByteArray xml = libraryText(
            Test::hsmTool(1, u"diameter=\"6\""_s, u"millimeters"_s, u"Ø 6 Fräser"_s), u"ISO-8859-1"_s)
                                   .toLatin1();
        QVERIFY(xml.contains("\xd8 6 Fr\xe4ser"));
        const auto read = readHsmLibrary(xml);
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().front().description, u"Ø 6 Fräser"_s);
    }

    // QXmlStreamReader compares each attribute with every earlier one of its element, resolves a prefix by
    // searching every declaration in scope, and matches each element against every attribute default of a
    // DTD: a small file could take minutes. Such files are refused before it reads them, by a scan as long
    // as the file.
    void refusesWhatWouldMakeReadingSlow_data()
    {
        QTest::addColumn<QByteArray>("xml");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("message");
        const QString good = Test::hsmTool(1);
        const auto tool = [&good](const QString &extra) {
            return QString(good).replace(u"<tool guid"_s, u"<tool"_s + extra + u" guid"_s);
        };
        QTest::newRow("a tool with 257 attributes")
            << Test::hsmLibrary(tool(attributes(254))) << 3
            << u"<tool> has more than 256 attributes; an element of an HSM library has a few dozen at most"_s;
        QTest::newRow("100,000 attributes on the root")
            << Test::hsmLibrary(good, u"tool-library"_s,
                   QLatin1StringView(Test::kHsmNamespace) + u"\""_s + attributes(100'000) + u" x=\""_s)
            << 2 << u"<tool-library> has more than 256 attributes"_s;
        QTest::newRow("1,000,000 attributes, UTF-16BE without BOM") << encoded(
            libraryText(tool(attributes(1'000'000, u"b"_s, u"\n"_s))), QStringConverter::Utf16BE,
            false) << 3 << u"<tool> has more than 256 attributes"_s;
        QTest::newRow("300 attributes in UTF-8") << libraryText(tool(attributes(300)), u"UTF-8"_s).toUtf8()
                                                 << 3 << u"<tool> has more than 256 attributes"_s;
        QTest::newRow("attributes spread over lines")
            << Test::hsmLibrary(tool(attributes(300, u"a"_s, u"\n"_s))) << 3
            << u"<tool> has more than 256 attributes"_s;
        QTest::newRow("65 levels")
            << Test::hsmLibrary(deepTool(63)) << 10
            << u"<holder> is nested 65 elements deep; an HSM library nests a few, and Toffee reads up to 64"_s;
        QTest::newRow("a million levels")
            << Test::hsmLibrary(deepTool(1'000'000)) << 10 << u"<holder> is nested 65 elements deep"_s;
        QTest::newRow("17 namespaces in scope") << Test::hsmLibrary(QString(good).replace(u"<holder>"_s,
            u"<holder"_s + attributes(8, u"xmlns:h"_s) + u"><holder"_s + attributes(8, u"xmlns:i"_s)
                + u"></holder>"_s)) << 10 << u"<holder> brings the XML namespaces declared to 17"_s;
        // UTF-7 writes "<" as "+ADw-": the bounds hold for the text as the reader decodes it.
        QTest::newRow("markup hidden in UTF-7")
            << libraryText(tool(attributes(300)), u"UTF-7"_s).toUtf8().replace("<tool ", "+ADw-tool ") << 3
            << u"<tool> has more than 256 attributes"_s;
        QTest::newRow("a document type")
            << Test::hsmLibrary(good).replace(encoded(u"<tool-library"_s, QStringConverter::Utf16LE, false),
                   encoded(u"<!DOCTYPE tool-library [<!ATTLIST tool a CDATA \"1\">]>\n<tool-library"_s,
                       QStringConverter::Utf16LE, false))
            << 2 << u"it has a document type declaration (<!DOCTYPE>)"_s;
    }
    void refusesWhatWouldMakeReadingSlow()
    {
        QFETCH(QByteArray, xml);
        QFETCH(int, line);
        QFETCH(QString, message);
        const auto read = readHsmLibrary(xml);
        QVERIFY2(!read.ok(), "the library was read");
        QVERIFY2(read.error().message.contains(message), qPrintable(read.error().message));
        QCOMPARE(read.error().line, line);
    }

    // The bounds themselves are read, and what looks like markup in comments, instructions, CDATA sections
    // and attribute values counts for nothing.
    void readsUpToTheBounds_data()
    {
        QTest::addColumn<QByteArray>("xml");
        const QString good = Test::hsmTool(1);
        QTest::newRow("256 attributes") << Test::hsmLibrary(
            QString(good).replace(u"<coolant mode=\"flood\"/>"_s, u"<coolant"_s + attributes(256) + u"/>"_s));
        QTest::newRow("64 levels") << Test::hsmLibrary(deepTool(62));
        QTest::newRow("16 namespaces in scope") << Test::hsmLibrary(QString(good).replace(u"<holder>"_s,
            u"<holder"_s + attributes(8, u"xmlns:h"_s) + u"><holder"_s + attributes(7, u"xmlns:i"_s)
                + u"></holder>"_s));
        const QString markup = u"<a"_s + attributes(300) + u">"_s;
        QTest::newRow("markup in a comment") << Test::hsmLibrary(good + u"<!-- "_s + markup + u" -->\n"_s);
        QTest::newRow("markup in an instruction")
            << Test::hsmLibrary(good + u"<?toffee "_s + markup + u" ?>\n"_s);
        QTest::newRow("markup in CDATA") << Test::hsmLibrary(
            QString(good).replace(u"6 mm flat"_s, u"<![CDATA[6 mm "_s + markup + u"]]>"_s));
        QTest::newRow("markup in values")
            << Test::hsmLibrary(QString(good).replace(u"type=\"flat end mill\""_s,
                   u"type=\"flat end mill"_s + QString(markup).remove(u'<').remove(u'"')
                       + u"\" mode='a=\"1\" >'"_s));
    }
    void readsUpToTheBounds()
    {
        QFETCH(QByteArray, xml);
        const auto read = readHsmLibrary(xml);
        QVERIFY2(read.ok(), qPrintable(read.error().text()));
        QCOMPARE(read.value().front().number, 1);
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
