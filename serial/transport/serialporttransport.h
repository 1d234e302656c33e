// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QSerialPort>

#include "serial/transport/streamtransport.h"

namespace Toffee {

// A controller on a serial port (or a pseudo-terminal): 8N1, no flow control; plain text lines ended by \n or
// \r, or Makera's frames (StreamTransport).
class SerialPortTransport final : public StreamTransport
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(SerialPortTransport)

public:
    static constexpr int kDefaultBaud = 115200;

    explicit SerialPortTransport(const QString &portName, int baud = kDefaultBaud, QObject *parent = nullptr);

    void open() override;
    void close() override;
    [[nodiscard]] QString description() const override;

protected:
    [[nodiscard]] QString name() const override { return m_name; }

private:
    void handleError(QSerialPort::SerialPortError error);

    QSerialPort m_port;
    QString m_name; // as the user gave it: QSerialPort drops "/dev/"
    int m_baud;
};

} // namespace Toffee
