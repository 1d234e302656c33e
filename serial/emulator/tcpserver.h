// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QHostAddress>
#include <QList>
#include <QObject>
#include <QTcpServer>

#include "serial/emulator/emulatorwire.h"

class QTcpSocket;

namespace Toffee {

class CarveraEmulator;

// Serves an emulator on a TCP port, as a Carvera serves its console over Wi-Fi (port 2222 on a machine):
// plain text or Makera's frames. Like the peer it takes more than one client and says everything to all of
// them. A "close link" fault drops every client and goes on listening.
class TcpServer final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(TcpServer)

public:
    // What waits for a client that does not read; beyond it, the client is dropped.
    static constexpr qsizetype kMaxPendingBytes = 256 * 1024;

    TcpServer(CarveraEmulator *emulator, bool framed, QObject *parent = nullptr);
    ~TcpServer() override;

    // Listens; port 0 takes a free one. False, with errorString(), when it cannot.
    bool listen(const QHostAddress &address, quint16 port);
    [[nodiscard]] QHostAddress address() const { return m_server.serverAddress(); }
    [[nodiscard]] quint16 port() const { return m_server.serverPort(); }
    [[nodiscard]] QString errorString() const { return m_server.errorString(); }
    // A "close link" fault resets the connections (RST, as a machine that lost power mid-stream) instead of
    // closing them.
    void setDropByReset(bool reset) { m_dropByReset = reset; }
    // A client is connected (the beacon's BUSY).
    [[nodiscard]] bool isBusy() const { return !m_clients.isEmpty(); }
    [[nodiscard]] int clientCount() const { return int(m_clients.size()); }
    // Drops every connection at once, as a machine that leaves the network (a close fault, and tests).
    void dropAll();

Q_SIGNALS:
    void busyChanged(bool busy);

private:
    void accept();
    void send(const QByteArray &line);
    void drop(QTcpSocket *client);

    CarveraEmulator *m_emulator;
    EmulatorWire m_wire;
    QTcpServer m_server;
    QList<QTcpSocket *> m_clients;
    bool m_dropByReset = false;
};

} // namespace Toffee
