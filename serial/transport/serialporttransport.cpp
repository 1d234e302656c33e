// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/transport/serialporttransport.h"

namespace Toffee {

SerialPortTransport::SerialPortTransport(const QString &portName, int baud, QObject *parent)
    : StreamTransport(parent)
    , m_name(portName)
    , m_baud(baud)
{
    m_port.setPortName(portName);
    connect(&m_port, &QSerialPort::errorOccurred, this, &SerialPortTransport::handleError);
}

void SerialPortTransport::open()
{
    opening();
    m_port.setBaudRate(m_baud);
    m_port.setDataBits(QSerialPort::Data8);
    m_port.setParity(QSerialPort::NoParity);
    m_port.setStopBits(QSerialPort::OneStop);
    m_port.setFlowControl(QSerialPort::NoFlowControl);
    m_port.setReadBufferSize(kReadSliceBytes); // what a flood holds in memory: one slice
    if (!m_port.open(QIODevice::ReadWrite)) {
        // Queued, like every other signal of a transport: callers connect after calling open().
        const QString message
            = tr("Cannot open %1: %2. Check the cable, that no other program has the port open, "
                 "and that you may use serial ports (the dialout group).")
                  .arg(m_name, m_port.errorString());
        QMetaObject::invokeMethod(
            this, [this, message] { Q_EMIT errorOccurred(message); }, Qt::QueuedConnection);
        return;
    }
    start(&m_port);
}

void SerialPortTransport::close()
{
    stop();
    if (!m_port.isOpen())
        return;
    m_port.close();
    Q_EMIT closed();
}

QString SerialPortTransport::description() const
{
    return tr("%1 at %2 baud").arg(m_name).arg(m_baud) + modeSuffix();
}

void SerialPortTransport::handleError(QSerialPort::SerialPortError error)
{
    // Errors while opening are reported by open() itself.
    if (error == QSerialPort::NoError || error == QSerialPort::TimeoutError || !m_port.isOpen())
        return;
    // Any other error means the port can no longer be trusted: a hung-up device makes QSerialPort repeat its
    // error endlessly. Say it once and close, so that pending commands fail at once.
    // A device that vanished (a pty whose other end closed, a USB cable pulled) reports a read, write,
    // resource or unknown error, and errorString() then holds whatever errno was last ("File exists",
    // "Inappropriate ioctl for device"): it is not shown for these.
    const bool vanished = error == QSerialPort::ResourceError || error == QSerialPort::ReadError
        || error == QSerialPort::WriteError || error == QSerialPort::UnknownError;
    const QString message = vanished
        ? tr("The port %1 stopped answering and was closed: the cable was unplugged, the machine switched "
             "off, or the program serving the port ended. Check the cable and the machine, then connect "
             "again.")
              .arg(m_name)
        : tr("The port %1 failed (%2); the link was closed. Check the cable and connect again.")
              .arg(m_name, m_port.errorString());
    m_port.clearError();
    Q_EMIT errorOccurred(message);
    close();
}

} // namespace Toffee
