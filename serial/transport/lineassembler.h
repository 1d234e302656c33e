// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QList>

namespace Toffee {

// Cuts a byte stream into lines, however it arrives: '\n' or '\r' ends a line, empty lines are skipped.
// Memory is bounded: a line longer than the cap is delivered as its first `maxLineBytes` bytes, marked
// truncated, as soon as it overflows, and the rest of it is discarded up to its end. Pure: no I/O.
class LineAssembler
{
public:
    static constexpr qsizetype kDefaultMaxLineBytes = 4096;

    struct Line
    {
        QByteArray bytes; // without its line end
        bool truncated = false; // the line went on beyond the cap; what was beyond it is lost
        friend bool operator==(const Line &, const Line &) = default;
    };

    explicit LineAssembler(qsizetype maxLineBytes = kDefaultMaxLineBytes);

    // The lines that `bytes` complete, in order.
    [[nodiscard]] QList<Line> feed(QByteArrayView bytes);
    // Forgets a partial line, as after reopening the port.
    void reset();

    [[nodiscard]] qsizetype maxLineBytes() const { return m_max; }
    // Bytes of a line not yet ended; never more than maxLineBytes().
    [[nodiscard]] qsizetype buffered() const { return m_buffer.size(); }

private:
    qsizetype m_max;
    QByteArray m_buffer;
    bool m_discarding = false; // inside an over-long line, until its end
};

} // namespace Toffee
