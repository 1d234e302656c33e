// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/emulator/ptyserver.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <QFile>
#include <QSocketNotifier>

#include "serial/emulator/carveraemulator.h"

namespace Toffee {

PtyServer::PtyServer(CarveraEmulator *emulator, const QString &linkPath, QObject *parent)
    : QObject(parent)
    , m_emulator(emulator)
    , m_wire(emulator, EmulatorWire::Mode::Text, EmulatorWire::Link::Serial)
    , m_linkPath(linkPath)
{
    connect(m_emulator, &CarveraEmulator::lineSent, this, &PtyServer::send);
    connect(m_emulator, &CarveraEmulator::linkClosed, this, [this] {
        stop();
        start();
    });
}

PtyServer::~PtyServer()
{
    stop();
    if (!m_linkPath.isEmpty())
        QFile::remove(m_linkPath);
}

void PtyServer::setFramed(bool framed)
{
    m_wire = EmulatorWire(m_emulator, framed ? EmulatorWire::Mode::Framed : EmulatorWire::Mode::Text,
        EmulatorWire::Link::Serial);
}

bool PtyServer::start()
{
    m_master = posix_openpt(O_RDWR | O_NOCTTY);
    if (m_master < 0 || grantpt(m_master) != 0 || unlockpt(m_master) != 0) {
        m_error = tr("cannot open a pseudo-terminal: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        stop();
        return false;
    }
    m_devicePath = QString::fromLocal8Bit(ptsname(m_master));
    m_slave = ::open(ptsname(m_master), O_RDWR | O_NOCTTY);
    if (m_slave >= 0) {
        termios raw {};
        if (tcgetattr(m_slave, &raw) == 0) {
            cfmakeraw(&raw);
            cfsetspeed(&raw, B115200);
            tcsetattr(m_slave, TCSANOW, &raw);
        }
    }
    ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
    m_notifier = new QSocketNotifier(qintptr(m_master), QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &PtyServer::readMaster);
    m_writable = new QSocketNotifier(qintptr(m_master), QSocketNotifier::Write, this);
    m_writable->setEnabled(false);
    connect(m_writable, &QSocketNotifier::activated, this, &PtyServer::flush);
    if (!m_linkPath.isEmpty()) {
        QFile::remove(m_linkPath);
        if (!QFile::link(m_devicePath, m_linkPath))
            m_error = tr("cannot make the link %1").arg(m_linkPath);
    }
    m_out.clear();
    m_wire.reset();
    Q_EMIT deviceChanged(m_devicePath);
    return true;
}

void PtyServer::stop()
{
    // Later: stop() may run inside one of their own signals (a "close link" fault while reading).
    for (QSocketNotifier *notifier : { m_notifier, m_writable }) {
        if (notifier) {
            notifier->setEnabled(false);
            notifier->deleteLater();
        }
    }
    m_notifier = m_writable = nullptr;
    if (m_slave >= 0)
        ::close(m_slave);
    if (m_master >= 0)
        ::close(m_master);
    m_slave = m_master = -1;
    m_out.clear();
}

void PtyServer::readMaster()
{
    const int master = m_master;
    char buffer[4096];
    while (m_master == master) {
        const ssize_t n = ::read(master, buffer, sizeof buffer);
        if (n <= 0)
            return;
        m_wire.receive(QByteArrayView(buffer, n));
    }
}

void PtyServer::send(const QByteArray &line)
{
    if (m_master < 0)
        return;
    const QByteArray bytes = m_wire.encode(line);
    if (m_out.size() + bytes.size() > kMaxPendingBytes) {
        ++m_droppedLines; // the client has not read for a while: lose the line rather than wait or grow
        return;
    }
    m_out += bytes;
    flush();
}

void PtyServer::flush()
{
    while (!m_out.isEmpty() && m_master >= 0) {
        const ssize_t n = ::write(m_master, m_out.constData(), size_t(m_out.size()));
        if (n > 0) {
            m_out.remove(0, n);
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else if (n < 0 && errno == EAGAIN) {
            break; // the terminal is full: the write notifier says when it has room again
        } else {
            m_out.clear(); // the terminal failed: nothing more gets through
        }
    }
    if (m_writable)
        m_writable->setEnabled(!m_out.isEmpty());
}

} // namespace Toffee
