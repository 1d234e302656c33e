// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "serial/transport/lineassembler.h"

using namespace Toffee;
using Line = LineAssembler::Line;

namespace {

QList<Line> feedInPieces(LineAssembler &assembler, QByteArrayView bytes, qsizetype piece)
{
    QList<Line> lines;
    for (qsizetype i = 0; i < bytes.size(); i += piece)
        lines += assembler.feed(bytes.sliced(i, std::min(piece, bytes.size() - i)));
    return lines;
}

} // namespace

class TestLineAssembler : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void cutsLines_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QList<QByteArray>>("lines");
        QTest::addColumn<qsizetype>("buffered");
        QTest::newRow("LF") << QByteArray("ok\n") << QList<QByteArray> { "ok" } << qsizetype(0);
        QTest::newRow("CR LF") << QByteArray("ok\r\nok\r\n") << QList<QByteArray> { "ok", "ok" }
                               << qsizetype(0);
        QTest::newRow("CR alone") << QByteArray("<Idle|MPos:0,0,0>\rok\r")
                                  << QList<QByteArray> { "<Idle|MPos:0,0,0>", "ok" } << qsizetype(0);
        QTest::newRow("empty lines skipped")
            << QByteArray("\n\r\n\rok\n\n") << QList<QByteArray> { "ok" } << qsizetype(0);
        QTest::newRow("half a line waits")
            << QByteArray("ok\ncurrent tool") << QList<QByteArray> { "ok" } << qsizetype(12);
        QTest::newRow("NUL is a byte like any")
            << QByteArray("a\0b\n", 4) << QList<QByteArray> { QByteArray("a\0b", 3) } << qsizetype(0);
    }
    void cutsLines()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QList<QByteArray>, lines);
        QFETCH(qsizetype, buffered);
        // Whole, and split at every byte boundary: the same lines either way.
        for (qsizetype piece = 1; piece <= bytes.size(); ++piece) {
            LineAssembler assembler;
            QList<QByteArray> got;
            for (const Line &line : feedInPieces(assembler, bytes, piece)) {
                QVERIFY(!line.truncated);
                got.append(line.bytes);
            }
            QCOMPARE(got, lines);
            QCOMPARE(assembler.buffered(), buffered);
        }
    }

    void everySplitOfAStreamGivesTheSameLines()
    {
        const QByteArray stream = "<Idle|MPos:0,0,-2|WPos:0,0,57|T:2,-33.388>\r\nok\r\ncurrent tool offset "
                                  "[-105.688] , reference tool offset [-72.300]\nok\r";
        LineAssembler whole;
        const QList<Line> expected = whole.feed(stream);
        QCOMPARE(expected.size(), 4);
        for (qsizetype cut = 0; cut <= stream.size(); ++cut) {
            for (qsizetype second = cut; second <= stream.size(); ++second) {
                LineAssembler assembler;
                QList<Line> got = assembler.feed(QByteArrayView(stream).first(cut));
                got += assembler.feed(QByteArrayView(stream).sliced(cut, second - cut));
                got += assembler.feed(QByteArrayView(stream).sliced(second));
                QCOMPARE(got, expected);
            }
        }
    }

    // A line over the cap: its first bytes, at once and marked, then nothing of it until its end.
    void cutsAnOverlongLineAndKeepsItsStart()
    {
        LineAssembler assembler(8);
        QCOMPARE(assembler.feed("error:ab"), QList<Line> {}); // exactly the cap: not yet over it
        QCOMPARE(assembler.buffered(), 8);
        QCOMPARE(assembler.feed("c"), (QList<Line> { { "error:ab", true } }));
        QCOMPARE(assembler.buffered(), 0);
        QCOMPARE(assembler.feed(QByteArray(100000, 'x')), QList<Line> {});
        QCOMPARE(assembler.buffered(), 0);
        QCOMPARE(assembler.feed("yy\nok\n"), (QList<Line> { { "ok", false } }));
    }

    void aLineOfExactlyTheCapIsWhole()
    {
        LineAssembler assembler(8);
        QCOMPARE(assembler.feed("12345678\r\n"), (QList<Line> { { "12345678", false } }));
    }

    void theBufferNeverExceedsTheCap()
    {
        LineAssembler assembler;
        const QByteArray big(LineAssembler::kDefaultMaxLineBytes * 3 + 7, 'z');
        for (qsizetype piece : { 1, 100, 4095, 4096, 4097, 100000 }) {
            assembler.reset();
            qsizetype truncated = 0;
            for (qsizetype i = 0; i < big.size(); i += piece) {
                for (const Line &line :
                    assembler.feed(QByteArrayView(big).sliced(i, std::min(piece, big.size() - i)))) {
                    QVERIFY(line.truncated);
                    QCOMPARE(line.bytes.size(), LineAssembler::kDefaultMaxLineBytes);
                    ++truncated;
                }
                QVERIFY(assembler.buffered() <= LineAssembler::kDefaultMaxLineBytes);
            }
            QCOMPARE(truncated, 1); // one line, reported once
        }
    }

    void resetForgetsAHalfLine()
    {
        LineAssembler assembler;
        QVERIFY(assembler.feed("current tool").isEmpty());
        assembler.reset();
        QCOMPARE(assembler.feed("ok\n"), (QList<Line> { { "ok", false } }));
    }
};

QTEST_GUILESS_MAIN(TestLineAssembler)
#include "tst_lineassembler.moc"
