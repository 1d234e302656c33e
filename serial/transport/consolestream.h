// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "serial/transport/lineassembler.h"
#include "serial/wire/makeraframe.h"

namespace Toffee {

// The Carvera's console as bytes: plain text lines, or Makera's frames (docs/CARVERA.md § 11). Turns what the
// machine sends into its lines, and lines and real-time characters into what it takes. Framed, a status frame
// is its own line; the text of the other frames is one stream, cut into lines as plain text is (a frame may
// hold several lines or part of one); bytes outside frames and frames that fail their checks are counted,
// never taken for the machine's words. Pure: no I/O.
class ConsoleStream
{
public:
    enum class Mode { Text, Framed };

    explicit ConsoleStream(
        Mode mode = Mode::Text, qsizetype maxLineBytes = LineAssembler::kDefaultMaxLineBytes);

    [[nodiscard]] Mode mode() const { return m_mode; }
    // Forgets what is half received, as after reopening the port, and speaks `mode` from now on.
    void reset(Mode mode);

    [[nodiscard]] QList<LineAssembler::Line> feed(QByteArrayView bytes);
    [[nodiscard]] QByteArray encodeLine(QByteArrayView line) const;
    [[nodiscard]] QByteArray encodeRealtime(char c) const;

    // Framed: what was dropped (MakeraFrame::Decoder::Counts) and the frames of a type the console does not
    // read (file transfer, diagnose).
    [[nodiscard]] const MakeraFrame::Decoder::Counts &frameCounts() const { return m_decoder.counts(); }
    [[nodiscard]] qint64 otherFrames() const { return m_otherFrames; }

private:
    Mode m_mode;
    LineAssembler m_text;
    LineAssembler m_status;
    MakeraFrame::Decoder m_decoder;
    qint64 m_otherFrames = 0;
};

} // namespace Toffee
