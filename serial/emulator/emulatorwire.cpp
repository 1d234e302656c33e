// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/emulator/emulatorwire.h"

#include "serial/emulator/carveraemulator.h"

namespace Toffee {

EmulatorWire::EmulatorWire(CarveraEmulator *emulator, Mode mode, Link link)
    : m_emulator(emulator)
    , m_mode(mode)
    , m_link(link)
{ }

void EmulatorWire::reset()
{
    m_decoder.reset();
    m_emulator->resetInput();
}

void EmulatorWire::receive(QByteArrayView bytes)
{
    if (m_mode == Mode::Text)
        return m_emulator->receiveBytes(bytes);
    const QList<MakeraFrame::Frame> frames = m_decoder.feed(bytes);
    if (m_link == Link::Tcp && m_decoder.counts().strayBytes > 0)
        m_deaf = true;
    if (m_deaf)
        return;
    for (const MakeraFrame::Frame &frame : frames) {
        if (frame.type == MakeraFrame::RealTime && frame.payload.size() == 1)
            m_emulator->receiveRealtime(frame.payload.front());
        else if (frame.type == MakeraFrame::Command)
            m_emulator->receiveLine(frame.payload);
    }
}

QByteArray EmulatorWire::encode(const QByteArray &line) const
{
    if (m_mode == Mode::Text)
        return line + "\r\n";
    if (m_deaf)
        return {};
    const QByteArray text = line + (line == "ok" ? QByteArray("\r\n") : QByteArray("\n"));
    if (line.startsWith('<'))
        return MakeraFrame::encode(MakeraFrame::Status, text);
    const bool reply = line == "ok" || line.startsWith("version = ");
    return MakeraFrame::encode(reply && m_link == Link::Tcp ? MakeraFrame::Reply : MakeraFrame::Output, text);
}

} // namespace Toffee
