// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/transport/consolestream.h"

namespace Toffee {

ConsoleStream::ConsoleStream(Mode mode, qsizetype maxLineBytes)
    : m_mode(mode)
    , m_text(maxLineBytes)
    , m_status(maxLineBytes)
{ }

void ConsoleStream::reset(Mode mode)
{
    m_mode = mode;
    m_text.reset();
    m_status.reset();
    m_decoder.reset();
}

QList<LineAssembler::Line> ConsoleStream::feed(QByteArrayView bytes)
{
    if (m_mode == Mode::Text)
        return m_text.feed(bytes);
    QList<LineAssembler::Line> lines;
    for (const MakeraFrame::Frame &frame : m_decoder.feed(bytes)) {
        switch (frame.type) {
        case MakeraFrame::Status: {
            // A report is whole in its frame: a missing line end does not join it to the next one.
            lines += m_status.feed(frame.payload);
            lines += m_status.feed("\n");
            break;
        }
        case MakeraFrame::Reply:
        case MakeraFrame::Output:
            lines += m_text.feed(frame.payload);
            break;
        default:
            ++m_otherFrames;
            break;
        }
    }
    return lines;
}

QByteArray ConsoleStream::encodeLine(QByteArrayView line) const
{
    if (m_mode == Mode::Text)
        return line.toByteArray() + '\n';
    // The line alone: the firmware takes a frame's payload as one line, and "…\n" as the line and an empty
    // one after it ("ok - ignore: []" for an empty line, no plain "ok").
    return MakeraFrame::encode(MakeraFrame::Command, line);
}

QByteArray ConsoleStream::encodeRealtime(char c) const
{
    if (m_mode == Mode::Text)
        return QByteArray(1, c);
    return MakeraFrame::encode(MakeraFrame::RealTime, QByteArrayView(&c, 1));
}

} // namespace Toffee
