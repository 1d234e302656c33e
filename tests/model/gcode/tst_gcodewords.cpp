// SPDX-License-Identifier: GPL-3.0-or-later
// The one G-code tokenizer, which the interpreter, the emulator and the console's check share.
#include <QTest>

#include "model/gcode/carvera.h"
#include "model/gcode/gcodewords.h"

using namespace Qt::StringLiterals;
using namespace Toffee;

class TestGCodeWords : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void readsWordsAsControllersDo()
    {
        const auto read = GCodeBlock::read("n10 g43 h 2 (length) Z-30.5 ; the rest is a comment X1");
        QVERIFY(read);
        const GCodeBlock &block = read.value();
        QCOMPARE(block.words.size(), 4);
        QCOMPARE(block.words.at(0).letter, 'N');
        QVERIFY(block.has('G', 43));
        QVERIFY(!block.has('G', 43.1));
        QCOMPARE(block.value('H'), 2.0);
        QCOMPARE(block.value('Z'), -30.5);
        QCOMPARE(block.words.at(2).text.toByteArray(), "h 2");
        QVERIFY(!block.find('X'));
    }

    void tellsSubcodesApart()
    {
        const auto read = GCodeBlock::read("M491.1 H0.05");
        QVERIFY(read);
        QVERIFY(read.value().has('M', 491.1));
        QVERIFY(!read.value().has('M', 491));
    }

    void keepsALetterWithNoNumberAsBare()
    {
        const auto read = GCodeBlock::read("G44 X Y Z");
        QVERIFY(read);
        QCOMPARE(read.value().words.size(), 4);
        QVERIFY(read.value().find('Y')->bare);
        QCOMPARE(read.value().value('Y'), std::nullopt); // there, but no number
    }

    void refusesWhatNoControllerReads_data()
    {
        QTest::addColumn<QByteArray>("block");
        QTest::addColumn<QString>("message");
        QTest::newRow("unclosed comment") << QByteArray("G0 (never closed X1") << u"never closed"_s;
        QTest::newRow("two points") << QByteArray("Z1..2") << u"\"1..2\" is not a number"_s;
        QTest::newRow("nine digits") << QByteArray("X123456789") << u"X123456789 is too large"_s;
        QTest::newRow("stray character") << QByteArray("G0 #1") << u"unexpected \"#\""_s;
        QTest::newRow("a terminal's escape, named not printed")
            << QByteArray("G0 \x1b[2J") << u"unexpected byte 0x1b"_s;
        QTest::newRow("a byte beyond ASCII") << QByteArray("G0 \xc3\xa9") << u"unexpected byte 0xc3"_s;
        QTest::newRow("a function call") << QByteArray("Home(X)") << u"not G-code this controller reads"_s;
    }
    void refusesWhatNoControllerReads()
    {
        QFETCH(QByteArray, block);
        QFETCH(QString, message);
        const auto read = GCodeBlock::read(block);
        QVERIFY(!read);
        QVERIFY2(read.error().message.contains(message), qPrintable(read.error().message));
    }

    void handsAFunctionCallOverWhole()
    {
        GCodeLexer lexer("  CutterCompensationSetAxes([X, Y]) // the axes");
        QCOMPARE(lexer.next(), GCodeLexer::Token::Call);
        QCOMPARE(lexer.call().toByteArray(), "CutterCompensationSetAxes([X, Y])");
        QCOMPARE(lexer.next(), GCodeLexer::Token::End);
    }

    void knowsWhatAHaltedCarveraRuns()
    {
        QVERIFY(carveraRunsWhileHalted(GCodeBlock::read("M105").value()));
        QVERIFY(carveraRunsWhileHalted(GCodeBlock::read("(a comment alone)").value()));
        QVERIFY(!carveraRunsWhileHalted(GCodeBlock::read("G0 X1").value()));
        QVERIFY(!carveraRunsWhileHalted(GCodeBlock::read("M491").value()));
    }
};

QTEST_GUILESS_MAIN(TestGCodeWords)
#include "tst_gcodewords.moc"
