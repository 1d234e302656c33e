// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QTimer>

#include "serial/transport/consolestream.h"
#include "serial/transport/linetransport.h"

class QIODevice;

namespace Toffee {

// A controller at the other end of a byte stream (a serial port, a TCP socket), speaking plain text or
// Makera's frames. With Protocol::Auto it finds out on opening, before `opened`: it sends a status query as a
// frame (the one thing both firmwares answer harmlessly: a plain-text firmware acts on the '?' in it and
// ignores the rest of the frame's bytes as a line, which a line end then flushes), and speaks whatever the
// answer came in. It never sends plain text to a machine that may be framed: over TCP, the framed firmware
// answers no frame again after plain bytes (docs/CARVERA.md § 11). Subclasses open their device and hand it
// over.
class StreamTransport : public LineTransport
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(StreamTransport)

public:
    enum class Protocol { Auto, Text, Framed };
    static constexpr qsizetype kMaxLineBytes = LineAssembler::kDefaultMaxLineBytes;
    // One try of the query waits this long for its answer; three tries, then the machine is said not to
    // answer.
    static constexpr int kDetectTryMs = 1000;
    static constexpr int kDetectTries = 3;
    // The most one read takes from the machine (and the most a socket or port buffers): a flood is read a
    // slice at a time, the event loop and its time limits running between slices.
    static constexpr qint64 kReadSliceBytes = 64 * 1024;

    void setProtocol(Protocol protocol) { m_protocol = protocol; }
    [[nodiscard]] Protocol protocol() const { return m_protocol; }
    // What the link speaks once open (Auto: what was found).
    [[nodiscard]] ConsoleStream::Mode mode() const { return m_stream.mode(); }
    [[nodiscard]] const ConsoleStream &stream() const { return m_stream; }
    // With a protocol forced, what the machine's bytes since opening say it speaks instead: framed when text
    // was forced and nothing at all came back (a framed machine ignores plain text; over TCP it falls
    // silent), text when framed was forced and plain bytes came but no frame. Nothing when the forced
    // protocol was answered, or with Auto. A forced protocol that is wrong otherwise looks like a machine
    // that does not answer.
    [[nodiscard]] std::optional<Protocol> otherProtocolLikely() const;

    [[nodiscard]] bool isOpen() const override;
    // The tries to find the protocol, and the flush of a plain firmware's leftover line.
    [[nodiscard]] int openLimitMs() const override { return (kDetectTries + 1) * kDetectTryMs; }
    void writeLine(const QByteArray &line) override;
    void writeRealtime(char c) override;

    [[nodiscard]] static QString protocolName(Protocol protocol);
    [[nodiscard]] static std::optional<Protocol> parseProtocol(const QString &name);

protected:
    explicit StreamTransport(QObject *parent = nullptr);

    // Opening the device starts: what an earlier opening received is forgotten.
    void opening();
    // The device is open: find the protocol when asked to, then say `opened`.
    void start(QIODevice *device);
    // The device is closed or failed: forget it (no signal).
    void stop();
    // For messages: "/dev/ttyACM0", "192.168.1.57:2222".
    [[nodiscard]] virtual QString name() const = 0;
    // " (framed)" once framed, for description().
    [[nodiscard]] QString modeSuffix() const;

private:
    enum class Phase { Closed, Probing, Flushing, Open };

    void readAvailable();
    void deliver(const QList<LineAssembler::Line> &lines);
    void detect(QByteArrayView bytes);
    void probe();
    void opened(ConsoleStream::Mode mode);
    void timedOut();

    QIODevice *m_device = nullptr;
    Protocol m_protocol = Protocol::Auto;
    Phase m_phase = Phase::Closed;
    ConsoleStream m_stream { ConsoleStream::Mode::Text, kMaxLineBytes };
    // While probing, what came read both ways.
    ConsoleStream m_asText { ConsoleStream::Mode::Text, kMaxLineBytes };
    ConsoleStream m_asFrames { ConsoleStream::Mode::Framed, kMaxLineBytes };
    QTimer m_timer;
    int m_tries = 0;
    bool m_started = false; // since opening()
    qint64 m_bytesReceived = 0; // since start()
    bool m_sliceQueued = false; // the next slice of what is waiting is to be read
};

} // namespace Toffee
