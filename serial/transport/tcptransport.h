// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QTcpSocket>
#include <QTimer>

#include "model/result.h"
#include "serial/transport/streamtransport.h"

namespace Toffee {

// A Carvera over Wi-Fi: its console on a TCP port (2222 on a machine), plain text or Makera's frames
// (StreamTransport). Connecting has a time limit; keepalives and a limit on unacknowledged data notice a
// machine that vanished (switched off, out of range) within seconds rather than the system's minutes.
class TcpTransport final : public StreamTransport
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(TcpTransport)

public:
    static constexpr quint16 kDefaultPort = 2222;
    static constexpr int kConnectTimeoutMs = 5000;
    // Keepalive probes after this much silence, one a second, three unanswered: the link is gone.
    static constexpr int kKeepAliveIdleS = 2;
    static constexpr int kKeepAliveIntervalS = 1;
    static constexpr int kKeepAliveCount = 3;
    // Data the machine has not acknowledged for this long: the link is gone.
    static constexpr int kUnacknowledgedMs = 5000;

    struct Address
    {
        QString host;
        quint16 port = kDefaultPort;
        // "HOST:PORT", an IPv6 address in brackets: as parseAddress reads it back.
        [[nodiscard]] QString text() const
        {
            return (host.contains(u':') ? u'[' + host + u']' : host) + u':' + QString::number(port);
        }
    };
    // "HOST", "HOST:PORT", "[IPv6]" or "[IPv6]:PORT".
    // `defaultPort`: the port when the text gives none (the Carvera's 2222; LinuxCNC's linuxcncrsh 5007).
    [[nodiscard]] static Result<Address> parseAddress(const QString &text, quint16 defaultPort = kDefaultPort);

    explicit TcpTransport(const Address &address, QObject *parent = nullptr);
    [[nodiscard]] const Address &address() const { return m_address; }
    ~TcpTransport() override;

    // 0: kConnectTimeoutMs.
    void setConnectTimeoutMs(int milliseconds) { m_connectTimeoutMs = milliseconds; }
    void open() override;
    void close() override;
    [[nodiscard]] QString description() const override;
    // Connecting, then finding the protocol.
    [[nodiscard]] int openLimitMs() const override
    {
        return (m_connectTimeoutMs > 0 ? m_connectTimeoutMs : kConnectTimeoutMs)
            + StreamTransport::openLimitMs();
    }

protected:
    [[nodiscard]] QString name() const override;

private:
    void connected();
    void handleError(QAbstractSocket::SocketError error);
    void connectTimedOut();
    void tuneSocket();
    // The machine ended the connection with a reset (RST: it lost power, the network dropped it) rather than
    // closing it: Qt reports both as RemoteHostClosedError and closes its descriptor; the socket's TCP state,
    // read through m_watch, tells them apart.
    [[nodiscard]] bool peerReset() const;
    void releaseWatch();

    Address m_address;
    QTcpSocket m_socket;
    QTimer m_connectTimer;
    int m_connectTimeoutMs = kConnectTimeoutMs;
    bool m_connected = false;
    int m_watch = -1; // a second descriptor of the connected socket; released whenever the link ends
};

} // namespace Toffee
