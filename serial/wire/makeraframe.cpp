// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/wire/makeraframe.h"

#include <algorithm>
#include <array>

namespace Toffee::MakeraFrame {

namespace {

constexpr char kHeader[] = { char(0x86), char(0x68) };
constexpr char kTrailer[] = { char(0x55), char(0xAA) };

constexpr std::array<quint16, 256> makeTable()
{
    std::array<quint16, 256> table {};
    for (int i = 0; i < 256; ++i) {
        quint16 crc = quint16(i << 8);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 0x8000) ? quint16((crc << 1) ^ 0x1021) : quint16(crc << 1);
        table[size_t(i)] = crc;
    }
    return table;
}
constexpr std::array<quint16, 256> kTable = makeTable();

quint16 readU16(const QByteArray &bytes, qsizetype at)
{
    return quint16((quint8(bytes[at]) << 8) | quint8(bytes[at + 1]));
}

} // namespace

quint16 crc16(QByteArrayView bytes)
{
    quint16 crc = 0;
    for (const char c : bytes)
        crc = quint16((crc << 8) ^ kTable[size_t(((crc >> 8) ^ quint8(c)) & 0xFF)]);
    return crc;
}

QByteArray encode(quint8 type, QByteArrayView payload)
{
    payload = payload.first(std::min(payload.size(), kMaxPayload));
    const auto length = quint16(payload.size() + kMinLength);
    QByteArray frame;
    frame.reserve(payload.size() + kOverhead);
    frame.append(kHeader, 2);
    frame.append(char(length >> 8)).append(char(length & 0xFF)).append(char(type)).append(payload);
    const quint16 crc = crc16(QByteArrayView(frame).sliced(2));
    frame.append(char(crc >> 8)).append(char(crc & 0xFF)).append(kTrailer, 2);
    return frame;
}

void Decoder::reset()
{
    m_pending.clear();
}

QList<Frame> Decoder::feed(QByteArrayView bytes)
{
    QList<Frame> out;
    // In pieces no larger than a frame, so that m_pending stays bounded whatever one read brings.
    constexpr qsizetype kPiece = kMaxLength + 6;
    for (qsizetype i = 0; i < bytes.size(); i += kPiece) {
        m_pending.append(bytes.sliced(i, std::min(kPiece, bytes.size() - i)));
        drain(out);
    }
    return out;
}

qsizetype Decoder::nextWholeFrame(qsizetype from) const
{
    for (qsizetype at = m_pending.indexOf(QByteArrayView(kHeader, 2), from); at >= 0;
         at = m_pending.indexOf(QByteArrayView(kHeader, 2), at + 1)) {
        if (m_pending.size() - at < 4)
            return -1;
        const qsizetype length = readU16(m_pending, at + 2);
        if (length < kMinLength || length > kMaxLength || m_pending.size() - at < 4 + length + 2)
            continue;
        const QByteArrayView frame = QByteArrayView(m_pending).sliced(at, 4 + length + 2);
        if (frame.sliced(4 + length, 2) == QByteArrayView(kTrailer, 2)
            && crc16(frame.sliced(2, length)) == readU16(m_pending, at + 2 + length))
            return at;
    }
    return -1;
}

void Decoder::drain(QList<Frame> &out)
{
    qsizetype at = 0; // where the search goes on in m_pending
    for (;;) {
        const qsizetype header = m_pending.indexOf(QByteArrayView(kHeader, 2), at);
        if (header < 0) {
            // Keep a last 0x86: it may be the first half of a header.
            const qsizetype keep = !m_pending.isEmpty() && m_pending.back() == kHeader[0] ? 1 : 0;
            m_counts.strayBytes += m_pending.size() - at - keep;
            m_pending.remove(0, m_pending.size() - keep);
            return;
        }
        m_counts.strayBytes += header - at;
        at = header;
        if (m_pending.size() - at < 4)
            break;
        const qsizetype length = readU16(m_pending, at + 2);
        if (length < kMinLength || length > kMaxLength) {
            ++m_counts.badLength;
            at += 1; // the next header may start inside this one
            continue;
        }
        const qsizetype total = 4 + length + 2;
        if (m_pending.size() - at < total) {
            // A stray header whose LEN runs on would hold every frame after it until that many bytes came
            // (522 at most): a later header that opens a whole, valid frame shows this one is none. Resynced
            // within one frame.
            const qsizetype later = nextWholeFrame(at + 1);
            if (later < 0)
                break;
            ++m_counts.badLength;
            m_counts.strayBytes += later - at;
            at = later;
            continue;
        }
        const QByteArrayView frame = QByteArrayView(m_pending).sliced(at, total);
        if (frame.sliced(4 + length, 2) != QByteArrayView(kTrailer, 2)) {
            ++m_counts.badTrailer;
            at += 1;
            continue;
        }
        if (crc16(frame.sliced(2, length)) != readU16(m_pending, at + 2 + length)) {
            ++m_counts.badCrc;
            at += 1;
            continue;
        }
        out.append({ quint8(frame[4]), frame.sliced(5, length - kMinLength).toByteArray() });
        ++m_counts.frames;
        at += total;
    }
    m_pending.remove(0, at); // the start of a frame stays for the next read
}

} // namespace Toffee::MakeraFrame
