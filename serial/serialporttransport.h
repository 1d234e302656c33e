// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QSerialPort>

#include "serial/lineassembler.h"
#include "serial/linetransport.h"

namespace Toffee {

// A controller on a serial port (or a pseudo-terminal): 8N1, no flow control, lines ended by \n or \r.
class SerialPortTransport final : public LineTransport
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(SerialPortTransport)

public:
    static constexpr int kDefaultBaud = 115200;
    static constexpr qsizetype kMaxLineBytes = LineAssembler::kDefaultMaxLineBytes;

    explicit SerialPortTransport(const QString &portName, int baud = kDefaultBaud, QObject *parent = nullptr);

    void open() override;
    void close() override;
    [[nodiscard]] bool isOpen() const override { return m_port.isOpen(); }
    void writeLine(const QByteArray &line) override;
    void writeRealtime(char c) override;
    [[nodiscard]] QString description() const override;

private:
    void readAvailable();
    void handleError(QSerialPort::SerialPortError error);

    QSerialPort m_port;
    QString m_name; // as the user gave it: QSerialPort drops "/dev/"
    int m_baud;
    LineAssembler m_lines { kMaxLineBytes };
};

} // namespace Toffee
