// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/emulator/emulatortransport.h"

#include "serial/emulator/carveraemulator.h"

namespace Toffee {

EmulatorTransport::EmulatorTransport(CarveraEmulator *emulator, QObject *parent)
    : LineTransport(parent)
    , m_emulator(emulator ? emulator : new CarveraEmulator)
    , m_ownsEmulator(emulator == nullptr)
{
    connect(
        m_emulator, &CarveraEmulator::lineSent, this,
        [this](const QByteArray &line) {
            if (m_open)
                Q_EMIT lineReceived(line);
        },
        Qt::QueuedConnection);
    connect(
        m_emulator, &CarveraEmulator::linkClosed, this,
        [this] { lose(tr("The link to the emulator dropped.")); }, Qt::QueuedConnection);
}

EmulatorTransport::~EmulatorTransport()
{
    if (m_ownsEmulator)
        delete m_emulator;
}

void EmulatorTransport::open()
{
    m_open = true;
    QMetaObject::invokeMethod(this, &LineTransport::opened, Qt::QueuedConnection);
}

void EmulatorTransport::close()
{
    if (!m_open)
        return;
    m_open = false;
    Q_EMIT closed();
}

void EmulatorTransport::lose(const QString &message)
{
    if (!m_open)
        return;
    Q_EMIT errorOccurred(message);
    close();
}

void EmulatorTransport::writeLine(const QByteArray &line)
{
    if (!m_open) {
        Q_EMIT errorOccurred(tr("The link to the emulator is not open."));
        return;
    }
    QMetaObject::invokeMethod(
        m_emulator, [e = m_emulator, line] { e->receiveLine(line); }, Qt::QueuedConnection);
}

void EmulatorTransport::writeRealtime(char c)
{
    if (m_open)
        QMetaObject::invokeMethod(
            m_emulator, [e = m_emulator, c] { e->receiveRealtime(c); }, Qt::QueuedConnection);
}

QString EmulatorTransport::description() const
{
    return tr("built-in emulator");
}

} // namespace Toffee
