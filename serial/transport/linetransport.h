// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>

namespace Toffee {

// The seam in front of the port: a line-oriented, bidirectional link to a controller. QSerialPort and the
// in-process emulator both implement it; nothing above it knows which one it has.
class LineTransport : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LineTransport)

public:
    using QObject::QObject;
    ~LineTransport() override;

    // Opening may finish later; `opened` or `errorOccurred` tells.
    virtual void open() = 0;
    virtual void close() = 0;
    [[nodiscard]] virtual bool isOpen() const = 0;
    // One command line, without its line end.
    virtual void writeLine(const QByteArray &line) = 0;
    // A real-time character (`?`, Ctrl-X, `!`, `~`): acted on at once, not line-buffered.
    virtual void writeRealtime(char c) = 0;
    // What the link is, for the status bar and the console ("/dev/ttyUSB0 at 115200", "emulator").
    [[nodiscard]] virtual QString description() const = 0;
    // The longest opening can take before the transport says itself that it failed (a connect limit, the
    // protocol found); whoever waits for `opened` waits a little longer, only as a backstop.
    [[nodiscard]] virtual int openLimitMs() const { return 5000; }

Q_SIGNALS:
    void opened();
    // One received line, without its line end.
    void lineReceived(const QByteArray &line);
    void errorOccurred(const QString &message);
    void closed();
};

} // namespace Toffee
