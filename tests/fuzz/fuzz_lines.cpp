// SPDX-License-Identifier: GPL-3.0-or-later
// The line assembler on any byte stream, cut anywhere. The first byte picks the cap (small caps reach the
// over-long path with short inputs), the second how many of the next bytes give the lengths of the pieces
// the stream is fed in; the rest is the stream.
// Promised: the pieces give exactly the lines the whole stream gives, and those a plain reading of it
// gives; no line is empty, holds '\r' or '\n', or exceeds the cap (a cut one is exactly the cap); the
// buffer never exceeds the cap.
#include <algorithm>

#include "serial/transport/lineassembler.h"
#include "tests/fuzz/fuzzcheck.h"

using namespace Toffee;
using Line = LineAssembler::Line;

namespace {

// The promise, written the plain way: one byte at a time, no buffer management.
QList<Line> reference(QByteArrayView stream, qsizetype cap)
{
    QList<Line> lines;
    QByteArray line;
    bool over = false;
    for (char c : stream) {
        if (c == '\n' || c == '\r') {
            if (!over && !line.isEmpty())
                lines.append({ line, false });
            line.clear();
            over = false;
        } else if (!over && line.size() == cap) {
            lines.append({ line, true });
            line.clear();
            over = true;
        } else if (!over) {
            line += c;
        }
    }
    return lines;
}

QString shown(const QList<Line> &lines)
{
    QString out;
    for (const Line &line : lines)
        out += QString::fromLatin1(line.bytes.left(60)) + (line.truncated ? u"[cut]|" : u"|");
    return out;
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
    if (size < 2)
        return 0;
    const qsizetype cap = data[0] < 192 ? 1 + data[0] % 64 : LineAssembler::kDefaultMaxLineBytes;
    const size_t pieceCount = std::min<size_t>(data[1] % 32, size - 2);
    const uint8_t *pieces = data + 2;
    const QByteArrayView stream = Fuzz::bytes(data + 2 + pieceCount, size - 2 - pieceCount);

    LineAssembler whole(cap);
    const QList<Line> expected = whole.feed(stream);
    checkLines(expected, cap);
    TOFFEE_FUZZ_CHECK(whole.buffered() <= cap, QString::number(whole.buffered()));
    TOFFEE_FUZZ_CHECK(
        expected == reference(stream, cap), shown(expected) + u" vs " + shown(reference(stream, cap)));

    LineAssembler cut(cap);
    QList<Line> got;
    const bool allEmpty = std::all_of(pieces, pieces + pieceCount, [](uint8_t p) { return p == 0; });
    qsizetype at = 0;
    for (size_t i = 0; at < stream.size(); ++i) {
        // A piece of 0 is an empty read; without pieces (or with empty ones only), one byte at a time.
        const qsizetype length = allEmpty ? 1 : qsizetype(pieces[i % pieceCount]);
        const qsizetype n = std::min(length, stream.size() - at);
        got += cut.feed(stream.sliced(at, n));
        TOFFEE_FUZZ_CHECK(cut.buffered() <= cap, QString::number(cut.buffered()));
        at += n;
    }
    TOFFEE_FUZZ_CHECK(got == expected, shown(got) + u" vs " + shown(expected));
    TOFFEE_FUZZ_CHECK(cut.buffered() == whole.buffered(), QString::number(cut.buffered()));
    return 0;
}
