// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>

#include "serial/wire/makeraframe.h"

namespace Toffee {

class CarveraEmulator;

// The emulator's console on a byte stream, as the firmware puts it there: plain text lines, or Makera's
// frames (docs/CARVERA.md § 11). Framed, a status report goes in a status frame; over TCP the shell's answers
// and "ok" go in reply frames (82), over a serial port in output frames (90), as on the peer; bytes outside
// frames are ignored. Over TCP, as the peer does, a framed machine that got bytes outside a frame answers no
// frame again.
class EmulatorWire
{
public:
    enum class Mode { Text, Framed };
    enum class Link { Serial, Tcp };

    EmulatorWire(CarveraEmulator *emulator, Mode mode, Link link);

    [[nodiscard]] Mode mode() const { return m_mode; }
    // Bytes from the client, to the emulator.
    void receive(QByteArrayView bytes);
    // A line the emulator printed, as the bytes that go to the client (empty once deaf).
    [[nodiscard]] QByteArray encode(const QByteArray &line) const;
    // A new client: forget a half-received line or frame.
    void reset();
    // Framed over TCP: plain bytes came, and no frame is answered any more.
    [[nodiscard]] bool isDeaf() const { return m_deaf; }

private:
    CarveraEmulator *m_emulator;
    Mode m_mode;
    Link m_link;
    MakeraFrame::Decoder m_decoder;
    bool m_deaf = false;
};

} // namespace Toffee
