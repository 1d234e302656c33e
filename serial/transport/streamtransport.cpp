// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/transport/streamtransport.h"

#include <QIODevice>

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// What the plain-text firmware says to the frame's bytes before its line end ("ok - ignore: [\x86h]"), or to
// the line end alone.
bool isFlushAnswer(const QByteArray &line)
{
    return line.startsWith("ok");
}

} // namespace

StreamTransport::StreamTransport(QObject *parent)
    : LineTransport(parent)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &StreamTransport::timedOut);
}

QString StreamTransport::protocolName(Protocol protocol)
{
    switch (protocol) {
    case Protocol::Auto:
        return u"auto"_s;
    case Protocol::Text:
        return u"text"_s;
    case Protocol::Framed:
        return u"framed"_s;
    }
    return {};
}

std::optional<StreamTransport::Protocol> StreamTransport::parseProtocol(const QString &name)
{
    for (const Protocol p : { Protocol::Auto, Protocol::Text, Protocol::Framed }) {
        if (name == protocolName(p))
            return p;
    }
    return std::nullopt;
}

bool StreamTransport::isOpen() const
{
    return m_device && m_device->isOpen() && m_phase != Phase::Closed;
}

QString StreamTransport::modeSuffix() const
{
    return m_phase == Phase::Open && m_stream.mode() == ConsoleStream::Mode::Framed ? tr(" (framed)")
                                                                                    : QString();
}

std::optional<StreamTransport::Protocol> StreamTransport::otherProtocolLikely() const
{
    if (!m_started)
        return std::nullopt; // the device never opened: a protocol has nothing to do with it
    if (m_protocol == Protocol::Text && m_bytesReceived == 0)
        return Protocol::Framed;
    const MakeraFrame::Decoder::Counts &counts = m_stream.frameCounts();
    if (m_protocol == Protocol::Framed && counts.frames == 0 && counts.strayBytes > 0)
        return Protocol::Text;
    return std::nullopt;
}

void StreamTransport::opening()
{
    m_started = false;
    m_bytesReceived = 0;
}

void StreamTransport::start(QIODevice *device)
{
    m_started = true;
    m_device = device;
    connect(device, &QIODevice::readyRead, this, &StreamTransport::readAvailable, Qt::UniqueConnection);
    m_tries = 0;
    m_bytesReceived = 0;
    switch (m_protocol) {
    case Protocol::Text:
        return opened(ConsoleStream::Mode::Text);
    case Protocol::Framed:
        return opened(ConsoleStream::Mode::Framed);
    case Protocol::Auto:
        m_phase = Phase::Probing;
        m_asText.reset(ConsoleStream::Mode::Text);
        m_asFrames.reset(ConsoleStream::Mode::Framed);
        probe();
        return;
    }
}

void StreamTransport::stop()
{
    m_timer.stop();
    m_phase = Phase::Closed;
    if (m_device) // only what start() connected: the subclass's own connections to its device stay
        disconnect(m_device, &QIODevice::readyRead, this, &StreamTransport::readAvailable);
    m_device = nullptr;
}

void StreamTransport::probe()
{
    ++m_tries;
    m_device->write(m_asFrames.encodeRealtime('?'));
    m_timer.start(kDetectTryMs);
}

void StreamTransport::opened(ConsoleStream::Mode mode)
{
    m_timer.stop();
    m_stream.reset(mode);
    m_phase = Phase::Open;
    // Queued, like every other signal of a transport: callers connect after calling open().
    QMetaObject::invokeMethod(this, &LineTransport::opened, Qt::QueuedConnection);
}

void StreamTransport::timedOut()
{
    if (m_phase == Phase::Flushing)
        return opened(ConsoleStream::Mode::Text); // the flush's answer is a courtesy: the link is plain text
    if (m_phase != Phase::Probing)
        return;
    if (m_tries < kDetectTries)
        return probe();
    const QString message
        = tr("%1 did not answer a status query, as plain text or framed, within %2 s. Check that it is a "
             "Carvera, that it is switched on and has started, and the address or port.")
              .arg(name())
              .arg(kDetectTries * kDetectTryMs / 1000);
    Q_EMIT errorOccurred(message);
    close();
}

void StreamTransport::readAvailable()
{
    if (!m_device)
        return;
    // One slice at a time, back to the event loop between them: however much arrives, one read holds at most
    // a slice, and time limits fire on time.
    const QByteArray bytes = m_device->read(kReadSliceBytes);
    m_bytesReceived += bytes.size();
    if (m_device->bytesAvailable() > 0 && !m_sliceQueued) {
        m_sliceQueued = true;
        QTimer::singleShot(0, this, [this] {
            m_sliceQueued = false;
            readAvailable();
        });
    }
    if (m_phase == Phase::Open)
        return deliver(m_stream.feed(bytes));
    detect(bytes);
}

void StreamTransport::detect(QByteArrayView bytes)
{
    if (m_phase == Phase::Probing) {
        // Any frame that passes its checks is the framed firmware's (a status, or its boot lines).
        if (!m_asFrames.feed(bytes).isEmpty() || m_asFrames.frameCounts().frames > 0)
            return opened(ConsoleStream::Mode::Framed);
        for (const LineAssembler::Line &line : m_asText.feed(bytes)) {
            if (line.bytes.startsWith('<') && line.bytes.endsWith('>')) {
                // Plain text: the frame's other bytes wait in the firmware's line buffer; end that line.
                m_phase = Phase::Flushing;
                m_device->write("\n");
                m_timer.start(kDetectTryMs);
                return;
            }
        }
        return;
    }
    if (m_phase == Phase::Flushing) {
        for (const LineAssembler::Line &line : m_asText.feed(bytes)) {
            if (isFlushAnswer(line.bytes))
                return opened(ConsoleStream::Mode::Text);
        }
    }
}

void StreamTransport::deliver(const QList<LineAssembler::Line> &lines)
{
    for (const LineAssembler::Line &line : lines) {
        if (line.truncated) {
            // Not a controller's line, but its start may still say what it is ("error:..."): keep that, drop
            // the rest rather than grow without bound, and say so once for each such line.
            Q_EMIT errorOccurred(tr("%1 sent a line longer than %2 bytes; only its first %2 bytes were kept.")
                                     .arg(name())
                                     .arg(kMaxLineBytes));
        }
        Q_EMIT lineReceived(line.bytes);
        if (!isOpen())
            return; // a receiver closed the link
    }
}

void StreamTransport::writeLine(const QByteArray &line)
{
    if (!isOpen() || m_phase != Phase::Open) {
        Q_EMIT errorOccurred(tr("%1 is not open.").arg(name()));
        return;
    }
    m_device->write(m_stream.encodeLine(line));
}

void StreamTransport::writeRealtime(char c)
{
    if (isOpen() && m_phase == Phase::Open)
        m_device->write(m_stream.encodeRealtime(c));
}

} // namespace Toffee
