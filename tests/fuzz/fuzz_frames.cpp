// SPDX-License-Identifier: GPL-3.0-or-later
// Makera's frame decoder on any byte stream, cut anywhere, and the console's framed reading on top of it. The
// first byte picks the console's line cap (small caps reach the over-long path with short inputs), the next
// two where the stream is cut: the bytes before that point go in one at a time, the rest in one read; the
// rest of the input is the stream. Promised: the whole stream gives exactly the frames, counts and leftover
// bytes a plain reading of it gives; the cut stream gives the same frames and leftover, and says the stream
// was damaged exactly when the whole one does. Why a stray header was dropped may depend on how the bytes
// arrive (held with one frame's bytes at most, a header whose frame is not yet whole is a bad length when a
// later frame completes first and a bad trailer when its own does), so the cut stream's counts of each kind
// are not promised: they are diagnostics, the frames are the contract. Each frame's payload fits kMaxPayload,
// its encoding is in the stream (the frames in order, apart) and decodes again to that frame alone; the
// decoder never holds more than one frame's bytes. Framed, the console counts what the decoder counts, and
// its lines are never empty, never hold a line end, never exceed the cap, and are the same however the stream
// is cut.
#include <algorithm>

#include "serial/transport/consolestream.h"
#include "serial/wire/makeraframe.h"
#include "tests/fuzz/fuzzcheck.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using MakeraFrame::Decoder;
using MakeraFrame::Frame;
using Line = LineAssembler::Line;

namespace {

// The most the decoder may hold: a whole frame but its last byte, with room to spare for a header's start.
constexpr qsizetype kMaxBuffered = MakeraFrame::kMaxLength + 6;

struct Decoded
{
    QList<Frame> frames;
    Decoder::Counts counts;
    qsizetype leftover = 0; // bytes still held at the end: the start of a frame
};

// The first header from `from` on that opens a whole frame with its length, trailer and CRC right; -1 if
// none.
qsizetype wholeFrameAfter(QByteArrayView s, qsizetype from)
{
    for (qsizetype j = from; j + 3 < s.size(); ++j) {
        if (quint8(s[j]) != 0x86 || quint8(s[j + 1]) != 0x68)
            continue;
        const qsizetype length = qsizetype((quint8(s[j + 2]) << 8) | quint8(s[j + 3]));
        if (length < MakeraFrame::kMinLength || length > MakeraFrame::kMaxLength || s.size() - j < length + 6)
            continue;
        if (quint8(s[j + 4 + length]) != 0x55 || quint8(s[j + 5 + length]) != 0xAA)
            continue;
        const qsizetype crc = qsizetype((quint8(s[j + 2 + length]) << 8) | quint8(s[j + 3 + length]));
        if (MakeraFrame::crc16(s.sliced(j + 2, length)) == crc)
            return j;
    }
    return -1;
}

// The promise, written the plain way: the whole stream in hand, no buffer, no pieces.
Decoded reference(QByteArrayView s)
{
    Decoded d;
    const auto u16 = [s](qsizetype at) {
        return qsizetype((quint8(s[at]) << 8) | quint8(s[at + 1]));
    };
    qsizetype i = 0;
    for (;;) {
        qsizetype h = i;
        while (h + 1 < s.size() && !(quint8(s[h]) == 0x86 && quint8(s[h + 1]) == 0x68))
            ++h;
        if (h + 1 >= s.size()) {
            // No header: every byte is stray but a last 0x86, which may be the first half of one.
            const qsizetype keep = i < s.size() && quint8(s.back()) == 0x86 ? 1 : 0;
            d.counts.strayBytes += s.size() - i - keep;
            d.leftover = keep;
            return d;
        }
        d.counts.strayBytes += h - i;
        i = h;
        if (s.size() - i < 4)
            break;
        const qsizetype length = u16(i + 2);
        if (length < MakeraFrame::kMinLength || length > MakeraFrame::kMaxLength) {
            ++d.counts.badLength;
            ++i;
            continue;
        }
        if (s.size() - i < length + 6) {
            // A header whose frame cannot be whole yet is a stray one when a later header opens a whole,
            // valid frame: the decoder resynchronises there rather than hold every frame after it.
            if (const qsizetype later = wholeFrameAfter(s, i + 1); later >= 0) {
                ++d.counts.badLength;
                d.counts.strayBytes += later - i;
                i = later;
                continue;
            }
            break;
        }
        if (quint8(s[i + 4 + length]) != 0x55 || quint8(s[i + 5 + length]) != 0xAA) {
            ++d.counts.badTrailer;
            ++i;
            continue;
        }
        if (MakeraFrame::crc16(s.sliced(i + 2, length)) != u16(i + 2 + length)) {
            ++d.counts.badCrc;
            ++i;
            continue;
        }
        d.frames.append(
            { quint8(s[i + 4]), s.sliced(i + 5, length - MakeraFrame::kMinLength).toByteArray() });
        ++d.counts.frames;
        i += length + 6;
    }
    d.leftover = s.size() - i;
    return d;
}

bool same(const Decoder::Counts &a, const Decoder::Counts &b)
{
    return a.frames == b.frames && a.strayBytes == b.strayBytes && a.badLength == b.badLength
        && a.badCrc == b.badCrc && a.badTrailer == b.badTrailer;
}

QString shown(const Decoder::Counts &c)
{
    return u"frames %1 stray %2 length %3 crc %4 trailer %5"_s.arg(c.frames)
        .arg(c.strayBytes)
        .arg(c.badLength)
        .arg(c.badCrc)
        .arg(c.badTrailer);
}

QString shown(const QList<Frame> &frames)
{
    QString out;
    for (const Frame &f : frames)
        out += QString::number(f.type, 16) + u':' + QString::fromLatin1(f.payload.left(40).toHex()) + u'|';
    return out;
}

QString shown(const QList<Line> &lines)
{
    QString out;
    for (const Line &line : lines)
        out += QString::fromLatin1(line.bytes.left(60)) + (line.truncated ? u"[cut]|" : u"|");
    return out;
}

void checkFrames(const QList<Frame> &frames, QByteArrayView stream)
{
    qsizetype from = 0;
    for (const Frame &f : frames) {
        TOFFEE_FUZZ_CHECK(f.payload.size() <= MakeraFrame::kMaxPayload, QString::number(f.payload.size()));
        const QByteArray bytes = MakeraFrame::encode(f.type, f.payload);
        TOFFEE_FUZZ_CHECK(bytes.size() == f.payload.size() + MakeraFrame::kOverhead, shown({ f }));
        // Found in order and apart: a frame never shares bytes with the one before it.
        const qsizetype at = stream.indexOf(bytes, from);
        TOFFEE_FUZZ_CHECK(at >= 0, shown({ f }));
        from = at + bytes.size();

        Decoder again;
        const QList<Frame> decoded = again.feed(bytes);
        TOFFEE_FUZZ_CHECK(decoded == QList<Frame> { f }, shown(decoded) + u" vs " + shown({ f }));
        TOFFEE_FUZZ_CHECK(again.counts().frames == 1 && again.counts().dropped() == 0
                && again.counts().strayBytes == 0 && again.buffered() == 0,
            shown(again.counts()));
    }
}

void checkLines(const QList<Line> &lines, qsizetype cap)
{
    for (const Line &line : lines) {
        TOFFEE_FUZZ_CHECK(!line.bytes.isEmpty(), shown(lines));
        TOFFEE_FUZZ_CHECK(!line.bytes.contains('\r') && !line.bytes.contains('\n'), shown(lines));
        TOFFEE_FUZZ_CHECK(line.bytes.size() <= cap, shown(lines));
        TOFFEE_FUZZ_CHECK(!line.truncated || line.bytes.size() == cap, shown(lines));
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 3)
        return 0;
    const qsizetype cap = data[0] < 192 ? 1 + data[0] % 64 : LineAssembler::kDefaultMaxLineBytes;
    const QByteArrayView stream = Fuzz::bytes(data + 3, size - 3);
    const qsizetype cut = ((qsizetype(data[1]) << 8) | data[2]) % (stream.size() + 1);

    Decoder whole;
    const QList<Frame> frames = whole.feed(stream);
    TOFFEE_FUZZ_CHECK(whole.buffered() <= kMaxBuffered, QString::number(whole.buffered()));
    checkFrames(frames, stream);
    const Decoded expected = reference(stream);
    TOFFEE_FUZZ_CHECK(frames == expected.frames, shown(frames) + u" vs " + shown(expected.frames));
    TOFFEE_FUZZ_CHECK(
        same(whole.counts(), expected.counts), shown(whole.counts()) + u" vs " + shown(expected.counts));
    TOFFEE_FUZZ_CHECK(whole.buffered() == expected.leftover, QString::number(whole.buffered()));

    Decoder pieces;
    QList<Frame> got;
    for (qsizetype i = 0; i < cut; ++i) {
        got += pieces.feed(stream.sliced(i, 1));
        TOFFEE_FUZZ_CHECK(pieces.buffered() <= kMaxBuffered, QString::number(pieces.buffered()));
    }
    got += pieces.feed(stream.sliced(cut));
    TOFFEE_FUZZ_CHECK(pieces.buffered() <= kMaxBuffered, QString::number(pieces.buffered()));
    TOFFEE_FUZZ_CHECK(got == frames, shown(got) + u" vs " + shown(frames));
    const auto damaged = [](const Decoder::Counts &c) {
        return c.dropped() + c.strayBytes > 0;
    };
    TOFFEE_FUZZ_CHECK(pieces.counts().frames == whole.counts().frames
            && damaged(pieces.counts()) == damaged(whole.counts()),
        shown(pieces.counts()) + u" vs " + shown(whole.counts()));
    TOFFEE_FUZZ_CHECK(pieces.buffered() == whole.buffered(), QString::number(pieces.buffered()));

    ConsoleStream console(ConsoleStream::Mode::Framed, cap);
    const QList<Line> lines = console.feed(stream);
    checkLines(lines, cap);
    TOFFEE_FUZZ_CHECK(same(console.frameCounts(), whole.counts()), shown(console.frameCounts()));
    const auto read = [](const Frame &f) {
        return f.type == MakeraFrame::Status || f.type == MakeraFrame::Reply || f.type == MakeraFrame::Output;
    };
    TOFFEE_FUZZ_CHECK(
        console.otherFrames() == frames.size() - std::count_if(frames.begin(), frames.end(), read),
        QString::number(console.otherFrames()));

    ConsoleStream cutConsole(ConsoleStream::Mode::Framed, cap);
    QList<Line> cutLines;
    for (qsizetype i = 0; i < cut; ++i)
        cutLines += cutConsole.feed(stream.sliced(i, 1));
    cutLines += cutConsole.feed(stream.sliced(cut));
    TOFFEE_FUZZ_CHECK(cutLines == lines, shown(cutLines) + u" vs " + shown(lines));
    return 0;
}
