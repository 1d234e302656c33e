// SPDX-License-Identifier: GPL-3.0-or-later
#include "ptyserver.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <QFile>
#include <QSocketNotifier>

#include "carveraemulator.h"

namespace Toffee {

PtyServer::PtyServer(CarveraEmulator *emulator, const QString &linkPath, QObject *parent)
    : QObject(parent)
    , m_emulator(emulator)
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
    if (!m_linkPath.isEmpty()) {
        QFile::remove(m_linkPath);
        if (!QFile::link(m_devicePath, m_linkPath))
            m_error = tr("cannot make the link %1").arg(m_linkPath);
    }
    m_line.clear();
    Q_EMIT deviceChanged(m_devicePath);
    return true;
}

void PtyServer::stop()
{
    delete m_notifier;
    m_notifier = nullptr;
    if (m_slave >= 0)
        ::close(m_slave);
    if (m_master >= 0)
        ::close(m_master);
    m_slave = m_master = -1;
}

void PtyServer::readMaster()
{
    char buffer[4096];
    while (true) {
        const ssize_t n = ::read(m_master, buffer, sizeof buffer);
        if (n <= 0)
            return;
        for (ssize_t i = 0; i < n; ++i)
            feed(buffer[i]);
    }
}

void PtyServer::feed(char c)
{
    if (c == '?' || c == 0x18) {
        m_emulator->receiveRealtime(c);
    } else if ((c == '!' || c == '~') && m_line.isEmpty()) {
        m_emulator->receiveRealtime(c);
    } else if (c == '\n' || c == '\r') {
        m_emulator->receiveLine(std::exchange(m_line, {}));
    } else if (m_line.size() < 4096) {
        m_line += c;
    }
}

void PtyServer::send(const QByteArray &line)
{
    if (m_master < 0)
        return;
    const QByteArray bytes = line + "\r\n";
    qsizetype written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(m_master, bytes.constData() + written, size_t(bytes.size() - written));
        if (n <= 0) {
            if (errno == EAGAIN || errno == EINTR)
                continue;
            return;
        }
        written += n;
    }
}

} // namespace Toffee
