// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/transport/lineassembler.h"

#include <algorithm>

namespace Toffee {

LineAssembler::LineAssembler(qsizetype maxLineBytes)
    : m_max(std::max<qsizetype>(1, maxLineBytes))
{
    m_buffer.reserve(m_max);
}

void LineAssembler::reset()
{
    m_buffer.clear();
    m_discarding = false;
}

QList<LineAssembler::Line> LineAssembler::feed(QByteArrayView bytes)
{
    QList<Line> lines;
    qsizetype i = 0;
    while (i < bytes.size()) {
        // The run of bytes up to the next line end, or to the end of what came.
        qsizetype end = i;
        while (end < bytes.size() && bytes[end] != '\n' && bytes[end] != '\r')
            ++end;
        if (!m_discarding) {
            const qsizetype room = m_max - m_buffer.size();
            m_buffer.append(bytes.sliced(i, std::min(room, end - i)));
            if (end - i > room) {
                lines.append({ std::exchange(m_buffer, {}), true });
                m_buffer.reserve(m_max);
                m_discarding = true;
            }
        }
        if (end == bytes.size())
            break;
        if (!m_buffer.isEmpty()) {
            lines.append({ m_buffer, false });
            m_buffer.clear();
        }
        m_discarding = false;
        i = end + 1;
    }
    return lines;
}

} // namespace Toffee
