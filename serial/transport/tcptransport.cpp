// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/transport/tcptransport.h"

#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

#include <QHostAddress>

using namespace Qt::StringLiterals;

namespace Toffee {

Result<TcpTransport::Address> TcpTransport::parseAddress(const QString &text, quint16 defaultPort)
{
    const QString trimmed = text.trimmed();
    const auto refuse = [&trimmed, defaultPort] {
        return Error { TcpTransport::tr("\"%1\" is not a machine's address: give HOST or HOST:PORT (the port "
                                        "is %2 when not given), such as 192.168.1.57 or carvera.local:2222.")
                           .arg(trimmed)
                           .arg(defaultPort) };
    };
    QString host = trimmed;
    QString port;
    bool hasPort = false;
    if (trimmed.startsWith(u'[')) {
        const qsizetype close = trimmed.indexOf(u']');
        if (close < 0)
            return refuse();
        host = trimmed.mid(1, close - 1);
        const QString rest = trimmed.mid(close + 1);
        if (!rest.isEmpty() && !rest.startsWith(u':'))
            return refuse();
        hasPort = !rest.isEmpty();
        port = rest.mid(1);
        if (QHostAddress(host).protocol() != QAbstractSocket::IPv6Protocol)
            return refuse();
    } else if (trimmed.count(u':') == 1) {
        host = trimmed.section(u':', 0, 0);
        port = trimmed.section(u':', 1);
        hasPort = true;
    } else if (trimmed.count(u':') > 1) {
        return refuse(); // an IPv6 address needs its brackets to be told from a port
    }
    if (host.isEmpty() || host.size() > 253
        || std::any_of(host.cbegin(), host.cend(), [](QChar c) { return c.unicode() < 0x21 || c.isSpace(); }))
        return refuse();
    Address address { host, defaultPort };
    if (hasPort) {
        bool ok = false;
        const uint value = port.toUInt(&ok);
        if (!ok || value < 1 || value > 65535 || port.startsWith(u'+'))
            return refuse();
        address.port = quint16(value);
    }
    return address;
}

TcpTransport::TcpTransport(const Address &address, QObject *parent)
    : StreamTransport(parent)
    , m_address(address)
{
    m_connectTimer.setSingleShot(true);
    // Precise: a coarse timer may fire up to 5 % early (4.75 s of a 5 s limit), and a limit is a promise to
    // wait that long.
    m_connectTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_connectTimer, &QTimer::timeout, this, &TcpTransport::connectTimedOut);
    connect(&m_socket, &QTcpSocket::connected, this, &TcpTransport::connected);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, &TcpTransport::handleError);
    // Qt reads what the kernel holds into memory without end: a flood would be one read of hundreds of MB.
    m_socket.setReadBufferSize(kReadSliceBytes);
}

TcpTransport::~TcpTransport()
{
    releaseWatch();
}

QString TcpTransport::name() const
{
    return m_address.text();
}

QString TcpTransport::description() const
{
    return tr("%1 over the network").arg(name()) + modeSuffix();
}

void TcpTransport::open()
{
    opening();
    m_connected = false;
    releaseWatch();
    m_socket.abort();
    m_connectTimer.start(m_connectTimeoutMs > 0 ? m_connectTimeoutMs : kConnectTimeoutMs);
    m_socket.connectToHost(m_address.host, m_address.port);
}

void TcpTransport::close()
{
    m_connectTimer.stop();
    const bool wasOpen = m_connected || m_socket.state() != QAbstractSocket::UnconnectedState;
    stop();
    m_connected = false;
    releaseWatch();
    m_socket.abort();
    if (wasOpen)
        Q_EMIT closed();
}

void TcpTransport::connected()
{
    m_connectTimer.stop();
    m_connected = true;
    tuneSocket();
    start(&m_socket);
}

// Nagle off (a command is a few bytes that want to go now), and a link that died noticed in seconds.
void TcpTransport::tuneSocket()
{
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    m_socket.setSocketOption(QAbstractSocket::KeepAliveOption, 1);
    const int fd = int(m_socket.socketDescriptor());
    if (fd < 0)
        return;
    releaseWatch();
    m_watch = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);
    const int idle = kKeepAliveIdleS;
    const int interval = kKeepAliveIntervalS;
    const int count = kKeepAliveCount;
    const unsigned int unacknowledged = kUnacknowledgedMs;
    ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPIDLE, &idle, sizeof idle);
    ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPINTVL, &interval, sizeof interval);
    ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPCNT, &count, sizeof count);
    ::setsockopt(fd, IPPROTO_TCP, TCP_USER_TIMEOUT, &unacknowledged, sizeof unacknowledged);
}

bool TcpTransport::peerReset() const
{
    tcp_info info {};
    socklen_t size = sizeof info;
    // After a FIN the socket waits for this side to close (CLOSE_WAIT); after an RST it is closed at once.
    return m_watch >= 0 && ::getsockopt(m_watch, IPPROTO_TCP, TCP_INFO, &info, &size) == 0
        && info.tcpi_state == TCP_CLOSE;
}

void TcpTransport::releaseWatch()
{
    if (m_watch >= 0)
        ::close(m_watch); // the connection ends once Qt's descriptor is closed too
    m_watch = -1;
}

void TcpTransport::connectTimedOut()
{
    if (m_connected)
        return;
    m_socket.abort();
    Q_EMIT errorOccurred(
        tr("%1 did not answer within %2 s. Check that the machine is switched on and on this "
           "network, and its address (the machine's screen shows it).")
            .arg(name())
            .arg((m_connectTimeoutMs > 0 ? m_connectTimeoutMs : kConnectTimeoutMs) / 1000.0));
}

void TcpTransport::handleError(QAbstractSocket::SocketError error)
{
    if (!m_connected) {
        m_connectTimer.stop();
        QString message;
        switch (error) {
        case QAbstractSocket::ConnectionRefusedError:
            message
                = tr("Nothing answers at %1 (the connection was refused): the machine's Wi-Fi console is "
                     "off, or the port is wrong (a Carvera listens on %2). Check the address and try again.")
                      .arg(name())
                      .arg(kDefaultPort);
            break;
        case QAbstractSocket::HostNotFoundError:
            message = tr("%1 is not a host name this computer can find. Give the machine's address as the "
                         "machine's screen shows it (such as 192.168.1.57).")
                          .arg(m_address.host);
            break;
        default:
            message = tr("Cannot reach %1: %2. Check that this computer and the machine are on the same "
                         "network.")
                          .arg(name(), m_socket.errorString());
            break;
        }
        Q_EMIT errorOccurred(message);
        return;
    }
    const bool reset = error == QAbstractSocket::RemoteHostClosedError && peerReset();
    releaseWatch();
    const QString message = error == QAbstractSocket::RemoteHostClosedError && !reset
        ? tr(
            "The machine at %1 closed the connection: it was switched off or restarted, or it serves another "
            "program now. Check the machine, then connect again.")
              .arg(name())
        : tr("The link to %1 was lost (%2): the machine was switched off or left the network. Check the "
             "machine, then connect again.")
              .arg(name(), reset ? qt_error_string(ECONNRESET) : m_socket.errorString());
    Q_EMIT errorOccurred(message);
    close();
}

} // namespace Toffee
