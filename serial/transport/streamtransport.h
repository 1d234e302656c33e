// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QTimer>

#include "serial/transport/consolestream.h"
#include "serial/transport/linetransport.h"

class QIODevice;

namespace Toffee {

// A controller at the other end of a byte stream (a serial port, a TCP socket), speaking plain text or
// Makera's frames. On opening, before `opened`, it asks one question that every controller Toffee knows
// answers harmlessly (firstQuestion()): a command line `version ?` in one of Makera's frames. The framed
// firmware answers it as `version` in a frame; a plain-text Carvera acts on the real-time '?' inside it with
// a plain status report; grblHAL does the same (after an error for the rest), and none of the frame's other
// bytes is a real-time command to it (the A1 frame of a bare '?' was: 0xA1 toggles its mist coolant). Plain
// text is never sent before the answer: over TCP the framed firmware answers no frame again after plain bytes
// (docs/CARVERA.md § 11). A plain answer is followed by a line end, which ends the frame's leftover bytes as
// one line, and its answer is awaited. A protocol forced (text, framed) is checked by the same question and
// refused, with nothing more sent, when the machine speaks the other. Subclasses open their device and hand
// it over.
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
    // After the line end's answer, the link is open once the controller has been quiet this long: the
    // question's other answers (grblHAL's "error:20" to the frame's 0xA2) come in no fixed order and are
    // read here, not taken for the answer to the first command.
    static constexpr int kSettleMs = 200;
    // The most one read takes from the machine (and the most a socket or port buffers): a flood is read a
    // slice at a time, the event loop and its time limits running between slices.
    static constexpr qint64 kReadSliceBytes = 64 * 1024;

    void setProtocol(Protocol protocol) { m_protocol = protocol; }
    // When the first question gets no answer at all: opens in plain text instead of failing, openedSilent()
    // saying so (linuxcncrsh, LinuxCNC's console, answers nothing before its hello). For a controller not
    // yet known on a network link.
    void setOpensSilent(bool silent) { m_opensSilent = silent; }
    // Asks no first question: opens at once in plain text (LinuxCNC chosen: its console takes no frame).
    void setAsksFirst(bool asks) { m_asksFirst = asks; }
    // The link opened without an answer to the first question (or without asking it).
    [[nodiscard]] bool openedSilent() const { return m_silent; }
    [[nodiscard]] Protocol protocol() const { return m_protocol; }
    // What the link speaks once open (what the first question found).
    [[nodiscard]] ConsoleStream::Mode mode() const { return m_stream.mode(); }
    [[nodiscard]] const ConsoleStream &stream() const { return m_stream; }
    // The bytes of the first question, as sent on every opening.
    [[nodiscard]] static QByteArray firstQuestion();

    [[nodiscard]] bool isOpen() const override;
    // The tries of the first question, and the line end after a plain answer.
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
    // The lines read wait in one queue and are given to the receivers from the event loop, never from the
    // device's readyRead: a receiver that holds the loop (a modal box) would otherwise stop the reading (a
    // device does not say readyRead again while its readyRead is being handled). Nested, the queue keeps the
    // order.
    void queueLines(const QList<LineAssembler::Line> &lines);
    void deliverQueued();
    void detect(QByteArrayView bytes);
    void probe();
    // The first question was answered in `mode`: open, or refuse a protocol forced otherwise.
    void answered(ConsoleStream::Mode mode);
    void opened(ConsoleStream::Mode mode);
    void timedOut();

    QIODevice *m_device = nullptr;
    Protocol m_protocol = Protocol::Auto;
    Phase m_phase = Phase::Closed;
    bool m_flushAnswered = false; // in Flushing: the line end was answered; now waiting for quiet
    ConsoleStream m_stream { ConsoleStream::Mode::Text, kMaxLineBytes };
    // While asking the first question, what came read both ways.
    ConsoleStream m_asText { ConsoleStream::Mode::Text, kMaxLineBytes };
    ConsoleStream m_asFrames { ConsoleStream::Mode::Framed, kMaxLineBytes };
    QTimer m_timer;
    int m_tries = 0;
    bool m_opensSilent = false;
    bool m_asksFirst = true;
    bool m_silent = false;
    bool m_heard = false; // anything came while the first question was asked
    bool m_sliceQueued = false; // the next slice of what is waiting is to be read
    QList<LineAssembler::Line> m_queued; // read, not yet given to the receivers
    bool m_deliveryQueued = false;
};

} // namespace Toffee
