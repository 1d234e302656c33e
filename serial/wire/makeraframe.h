// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QList>

namespace Toffee {

// Makera's framed protocol (its firmware from 1.0.4/1.0.5, on USB and Wi-Fi alike; docs/CARVERA.md § 11):
//   86 68 | LEN (2, big-endian) | TYPE (1) | PAYLOAD | CRC (2, big-endian) | 55 AA
// LEN counts TYPE, PAYLOAD and CRC; CRC is CRC-16/XMODEM over LEN, TYPE and PAYLOAD.
namespace MakeraFrame {

enum Type : quint8 {
    RealTime = 0xA1, // to the machine: one real-time byte (?, Ctrl-X, !, ~)
    Command = 0xA2, // to the machine: one command line
    Status = 0x81, // from the machine: a status report
    Reply = 0x82, // from the machine: over TCP, the shell's answers and "ok"
    Output = 0x90, // from the machine: any other text, one or several lines with their ends
};

// The firmware refuses a LEN above 516: a payload of at most 513 bytes.
constexpr qsizetype kMaxLength = 516;
constexpr qsizetype kMinLength = 3; // TYPE and CRC, no payload
constexpr qsizetype kMaxPayload = kMaxLength - kMinLength;
constexpr qsizetype kOverhead = 9; // header, LEN, TYPE, CRC, trailer

[[nodiscard]] quint16 crc16(QByteArrayView bytes);
// One frame; a payload beyond kMaxPayload is cut there (no command Toffee sends comes near it).
[[nodiscard]] QByteArray encode(quint8 type, QByteArrayView payload);

struct Frame
{
    quint8 type = 0;
    QByteArray payload;
    friend bool operator==(const Frame &, const Frame &) = default;
};

// Finds the frames in a byte stream however it arrives: split at any byte, several in one read, bytes between
// them. A frame whose LEN is out of range, whose CRC or trailer is wrong, is dropped and counted, and the
// search goes on from the byte after its header, so that a frame hidden in a broken one is still found; bytes
// outside frames are counted, never delivered. Linear time; it holds at most one frame's bytes. Pure: no I/O.
class Decoder
{
public:
    struct Counts
    {
        qint64 frames = 0;
        qint64 strayBytes = 0; // outside any frame
        qint64 badLength = 0;
        qint64 badCrc = 0;
        qint64 badTrailer = 0;
        [[nodiscard]] qint64 dropped() const { return badLength + badCrc + badTrailer; }
    };

    [[nodiscard]] QList<Frame> feed(QByteArrayView bytes);
    void reset();
    [[nodiscard]] const Counts &counts() const { return m_counts; }
    // Bytes of a frame not yet complete; never more than kMaxLength + 6.
    [[nodiscard]] qsizetype buffered() const { return m_pending.size(); }

private:
    // Takes what m_pending holds: frames out, stray bytes counted; leaves only the start of a frame.
    void drain(QList<Frame> &out);
    // Where, from `from` on, a whole frame with a right trailer and CRC starts in m_pending; -1 if none.
    [[nodiscard]] qsizetype nextWholeFrame(qsizetype from) const;

    QByteArray m_pending;
    Counts m_counts;
};

} // namespace MakeraFrame
} // namespace Toffee
