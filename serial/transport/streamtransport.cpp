// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/transport/streamtransport.h"

#include <QIODevice>

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// What a plain-text controller says to the frame's bytes before the line end: the Carvera "ok - ignore:
// [\x86h]" (or "ok" to the line end alone), grblHAL "error:2".
bool isFlushAnswer(const QByteArray &line)
{
    return line.startsWith("ok") || line.startsWith("error:");
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

QByteArray StreamTransport::firstQuestion()
{
    // 86 68 00 0C A2 "version ?" D6 7D 55 AA: to grblHAL, 0x86, the length and 0xAA are dropped, 0xA2 asks
    // for its PID log, '?' for a status report, the rest is a line it refuses; no byte moves or switches
    // anything (tst_streamtransport checks every byte against grblHAL's real-time commands).
    return ConsoleStream(ConsoleStream::Mode::Framed, kMaxLineBytes).encodeLine("version ?");
}

void StreamTransport::opening()
{
    m_phase = Phase::Closed;
}

void StreamTransport::start(QIODevice *device)
{
    m_device = device;
    connect(device, &QIODevice::readyRead, this, &StreamTransport::readAvailable, Qt::UniqueConnection);
    m_tries = 0;
    m_phase = Phase::Probing;
    m_silent = false;
    m_heard = false;
    m_asText.reset(ConsoleStream::Mode::Text);
    m_asFrames.reset(ConsoleStream::Mode::Framed);
    if (!m_asksFirst) {
        m_silent = true;
        return opened(ConsoleStream::Mode::Text);
    }
    probe();
}

void StreamTransport::stop()
{
    m_timer.stop();
    m_phase = Phase::Closed;
    m_queued.clear();
    if (m_device) // only what start() connected: the subclass's own connections to its device stay
        disconnect(m_device, &QIODevice::readyRead, this, &StreamTransport::readAvailable);
    m_device = nullptr;
}

void StreamTransport::probe()
{
    ++m_tries;
    m_device->write(firstQuestion());
    m_timer.start(kDetectTryMs);
}

void StreamTransport::answered(ConsoleStream::Mode mode)
{
    const bool framed = mode == ConsoleStream::Mode::Framed;
    if (m_protocol == Protocol::Auto || (m_protocol == Protocol::Framed) == framed)
        return opened(mode);
    m_timer.stop();
    m_phase = Phase::Closed;
    const QString message = framed
        ? tr("%1 speaks Makera's frames (its firmware from 1.0.4 on), not the plain text chosen. Plain text "
             "would leave it deaf until it is restarted, so nothing more was sent. Choose automatic "
             "(--protocol "
             "auto, or leave it out) or framed.")
              .arg(name())
        : tr("%1 speaks plain text, not Makera's frames as chosen. Nothing more was sent. Choose automatic "
             "(--protocol auto, or leave it out) or text.")
              .arg(name());
    Q_EMIT errorOccurred(message);
    close();
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
        return answered(ConsoleStream::Mode::Text); // quiet after the answer, or no answer (a courtesy): text
    if (m_phase != Phase::Probing)
        return;
    if (m_tries < kDetectTries)
        return probe();
    if (m_opensSilent && !m_heard) {
        // Nothing at all came back: a console that answers nothing unasked-for. The frame's bytes wait in its
        // line buffer: a line end ends them, and the link opens in plain text for the next question.
        m_device->write("\n");
        m_silent = true;
        return opened(ConsoleStream::Mode::Text);
    }
    const QString message
        = tr("%1 did not answer within %2 s, in plain text or in Makera's frames. Check that the machine is "
             "switched on and has started, and the address or port.")
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
    if (m_device->bytesAvailable() > 0 && !m_sliceQueued) {
        m_sliceQueued = true;
        QTimer::singleShot(0, this, [this] {
            m_sliceQueued = false;
            readAvailable();
        });
    }
    if (m_phase == Phase::Open)
        return queueLines(m_stream.feed(bytes));
    detect(bytes);
}

void StreamTransport::detect(QByteArrayView bytes)
{
    m_heard = m_heard || !bytes.isEmpty();
    if (m_phase == Phase::Probing) {
        // Any frame that passes its checks is the framed firmware's (its answer, or its boot lines).
        if (!m_asFrames.feed(bytes).isEmpty() || m_asFrames.frameCounts().frames > 0)
            return answered(ConsoleStream::Mode::Framed);
        for (const LineAssembler::Line &line : m_asText.feed(bytes)) {
            if (line.bytes.startsWith('<') && line.bytes.endsWith('>')) {
                // Plain text (a status report: grblHAL says "error:20" first): the frame's other bytes may
                // wait in the controller's line buffer; end that line.
                m_phase = Phase::Flushing;
                m_flushAnswered = false;
                m_device->write("\n");
                m_timer.start(kDetectTryMs);
                return;
            }
        }
        return;
    }
    if (m_phase == Phase::Flushing) {
        // Whatever comes now answers the question: once a line end's answer has come, each line waits for
        // quiet again (seen on grblHAL under load: the status report, then "error:20", then "error:2").
        for (const LineAssembler::Line &line : m_asText.feed(bytes)) {
            if (m_flushAnswered || isFlushAnswer(line.bytes)) {
                m_flushAnswered = true;
                m_timer.start(kSettleMs);
            }
        }
    }
}

void StreamTransport::queueLines(const QList<LineAssembler::Line> &lines)
{
    m_queued += lines;
    if (m_queued.isEmpty() || m_deliveryQueued)
        return;
    m_deliveryQueued = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_deliveryQueued = false;
            deliverQueued();
        },
        Qt::QueuedConnection);
}

void StreamTransport::deliverQueued()
{
    while (!m_queued.isEmpty() && m_phase == Phase::Open) {
        const LineAssembler::Line line = m_queued.takeFirst();
        if (line.truncated) {
            // Not a controller's line, but its start may still say what it is ("error:..."): keep that, drop
            // the rest rather than grow without bound, and say so once for each such line.
            Q_EMIT errorOccurred(tr("%1 sent a line longer than %2 bytes; only its first %2 bytes were kept.")
                                     .arg(name())
                                     .arg(kMaxLineBytes));
        }
        Q_EMIT lineReceived(line.bytes);
        if (!isOpen())
            break; // a receiver closed the link
    }
    if (m_phase != Phase::Open)
        m_queued.clear();
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
