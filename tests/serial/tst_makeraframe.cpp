// SPDX-License-Identifier: GPL-3.0-or-later
// Makera's frames: the encoder against the peer's own bytes, and the streaming decoder on frames split at
// every byte, several in one read, garbage between them, and every way a frame can be wrong.
#include <QTest>

#include "serial/wire/makeraframe.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

QList<MakeraFrame::Frame> feedInPieces(
    MakeraFrame::Decoder &decoder, const QByteArray &bytes, qsizetype piece)
{
    QList<MakeraFrame::Frame> frames;
    for (qsizetype i = 0; i < bytes.size(); i += piece)
        frames += decoder.feed(QByteArrayView(bytes).sliced(i, std::min(piece, bytes.size() - i)));
    return frames;
}

} // namespace

class TestMakeraFrame : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // The bytes the firmware sent and took (seen on the peer with --protocol makera, docs/CARVERA.md § 11).
    void encodesAsTheFirmwareDoes_data()
    {
        QTest::addColumn<int>("type");
        QTest::addColumn<QByteArray>("payload");
        QTest::addColumn<QByteArray>("frame");
        QTest::newRow("A1 ?") << int(MakeraFrame::RealTime) << QByteArray("?")
                              << QByteArray::fromHex("86680004a13f353355aa");
        QTest::newRow("A2 version") << int(MakeraFrame::Command) << QByteArray("version")
                                    << QByteArray::fromHex("8668000aa276657273696f6ecca055aa");
        QTest::newRow("90 ok") << int(MakeraFrame::Output) << QByteArray("ok\n")
                               << QByteArray::fromHex("866800069"
                                                      "06f6b0acada55aa");
        QTest::newRow("82 ok") << int(MakeraFrame::Reply) << QByteArray("ok\r\n")
                               << QByteArray::fromHex("8668000782"
                                                      "6f6b0d0a9fa255aa");
        QTest::newRow("A2 empty") << int(MakeraFrame::Command) << QByteArray() << QByteArray();
    }
    void encodesAsTheFirmwareDoes()
    {
        QFETCH(int, type);
        QFETCH(QByteArray, payload);
        QFETCH(QByteArray, frame);
        const QByteArray encoded = MakeraFrame::encode(quint8(type), payload);
        if (!frame.isEmpty())
            QCOMPARE(encoded.toHex(), frame.toHex());
        MakeraFrame::Decoder decoder;
        const auto frames = decoder.feed(encoded);
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames.front().type, quint8(type));
        QCOMPARE(frames.front().payload, payload);
    }

    void crcIsXmodem()
    {
        QCOMPARE(MakeraFrame::crc16("123456789"), quint16(0x31C3)); // the CRC-16/XMODEM check value
        QCOMPARE(MakeraFrame::crc16({}), quint16(0));
    }

    void findsFramesSplitAtEveryByte()
    {
        QByteArray stream;
        QList<QByteArray> payloads;
        for (int i = 0; i < 20; ++i) {
            payloads << QByteArray("line ") + QByteArray::number(i) + '\n';
            stream += MakeraFrame::encode(MakeraFrame::Output, payloads.last());
        }
        for (const qsizetype piece : { 1, 2, 3, 7, 9, 64, 100000 }) {
            MakeraFrame::Decoder decoder;
            const auto frames = feedInPieces(decoder, stream, piece);
            QCOMPARE(frames.size(), payloads.size());
            for (qsizetype i = 0; i < frames.size(); ++i)
                QCOMPARE(frames.at(i).payload, payloads.at(i));
            QCOMPARE(decoder.counts().dropped(), 0);
            QCOMPARE(decoder.counts().strayBytes, 0);
            QCOMPARE(decoder.buffered(), 0);
        }
    }

    // Whatever is wrong, the frame is dropped and counted, and the good frame after it is found, hidden
    // inside the broken one's bytes or not.
    void dropsAndCountsBrokenFrames_data()
    {
        QTest::addColumn<QByteArray>("broken");
        QTest::addColumn<QString>("counted");
        QByteArray frame = MakeraFrame::encode(MakeraFrame::Output, "bad\n");
        QByteArray wrongCrc = frame;
        wrongCrc[frame.size() - 4] = char(wrongCrc[frame.size() - 4] ^ 0x01);
        QByteArray wrongTrailer = frame;
        wrongTrailer[frame.size() - 1] = 'X';
        QTest::newRow("CRC") << wrongCrc << u"crc"_s;
        QTest::newRow("trailer") << wrongTrailer << u"trailer"_s;
        QTest::newRow("LEN 2") << QByteArray::fromHex("8668000290") << u"length"_s;
        QTest::newRow("LEN 517") << QByteArray::fromHex("8668020590") + QByteArray(520, 'x') << u"length"_s;
        QTest::newRow("LEN 65535") << QByteArray::fromHex("8668ffff") << u"length"_s;
        // A header whose frame is cut short by the next one: the next is found inside the broken one's
        // length.
        QTest::newRow("cut short") << QByteArray::fromHex("866800209061626364") << u"dropped"_s;
        QTest::newRow("plain text") << QByteArray("ok\r\nversion = 1.0.5\n") << u"stray"_s;
    }
    void dropsAndCountsBrokenFrames()
    {
        QFETCH(QByteArray, broken);
        QFETCH(QString, counted);
        const QByteArray good = MakeraFrame::encode(MakeraFrame::Status, "<Idle|MPos:0,0,0>\n");
        const QByteArray stream = good + broken + good + good;
        for (const qsizetype piece : { 1, 5, 4096 }) {
            MakeraFrame::Decoder decoder;
            auto frames = feedInPieces(decoder, stream, piece);
            // A frame cut short takes the following bytes as its own until its length is complete: one more
            // good frame afterwards always comes through.
            frames += decoder.feed(good);
            QVERIFY2(frames.size() >= 3, qPrintable(QString::number(frames.size())));
            for (const auto &f : frames)
                QCOMPARE(f.payload, QByteArray("<Idle|MPos:0,0,0>\n"));
            const auto &c = decoder.counts();
            const qint64 n = counted == u"crc" ? c.badCrc
                : counted == u"trailer"        ? c.badTrailer
                : counted == u"length"         ? c.badLength
                : counted == u"dropped"        ? c.dropped()
                                               : c.strayBytes;
            QVERIFY2(n > 0, qPrintable(counted));
            QVERIFY(decoder.buffered() <= MakeraFrame::kMaxLength + 6);
        }
    }

    // A payload at the firmware's limit goes through; beyond it, the encoder cuts it there.
    void holdsToTheLengthLimit()
    {
        const QByteArray most(MakeraFrame::kMaxPayload, 'a');
        MakeraFrame::Decoder decoder;
        auto frames = decoder.feed(MakeraFrame::encode(MakeraFrame::Output, most));
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames.front().payload.size(), MakeraFrame::kMaxPayload);
        frames = decoder.feed(MakeraFrame::encode(MakeraFrame::Output, QByteArray(most + "bc")));
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames.front().payload, most);
    }

    // One stray header whose LEN claims the most (86 68 02 04: 516) held the next good frame until 522 bytes
    // had come, making probes 12 times slower: a whole, valid frame after it is delivered at once.
    void aStrayHeaderHoldsNothingUp()
    {
        MakeraFrame::Decoder decoder;
        const QByteArray good = MakeraFrame::encode(MakeraFrame::Reply, "ok\n");
        const auto frames = decoder.feed(QByteArray(QByteArray("\x86\x68\x02\x04", 4) + good));
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames.front().payload, QByteArray("ok\n"));
        QCOMPARE(decoder.counts().badLength, 1);
        QCOMPARE(decoder.buffered(), 0);
        // Split at every byte, the same.
        MakeraFrame::Decoder byByte;
        const auto pieces
            = feedInPieces(byByte, QByteArray(QByteArray("\x86\x68\x02\x04", 4) + good + good), 1);
        QCOMPARE(pieces.size(), 2);
    }

    // Megabytes of noise: bounded memory, and frames mixed into it still found.
    void staysBoundedOnNoise()
    {
        QByteArray noise(4 * 1024 * 1024, '\0');
        quint32 x = 12345;
        for (char &c : noise) {
            x = x * 1103515245u + 12345u;
            c = char(x >> 24);
            if ((x & 0xff) == 7)
                c = char(0x86); // many a false header
        }
        const QByteArray good = MakeraFrame::encode(MakeraFrame::Output, "still here\n");
        MakeraFrame::Decoder decoder;
        qsizetype found = 0;
        for (qsizetype i = 0; i < noise.size(); i += 65536) {
            for (const auto &f : decoder.feed(QByteArrayView(noise).sliced(i, 65536)))
                found += f.payload == "still here\n";
            QVERIFY(decoder.buffered() <= MakeraFrame::kMaxLength + 6);
            found += decoder.feed(QByteArray(QByteArray(600, 'z') + good)).size();
        }
        QCOMPARE(found, 64);
    }
};

QTEST_GUILESS_MAIN(TestMakeraFrame)
#include "tst_makeraframe.moc"
