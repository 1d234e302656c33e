// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/emulator/tcpserver.h"

#include <sys/socket.h>

#include <QTcpSocket>

#include "serial/emulator/carveraemulator.h"

namespace Toffee {

TcpServer::TcpServer(CarveraEmulator *emulator, bool framed, QObject *parent)
    : QObject(parent)
    , m_emulator(emulator)
    , m_wire(
          emulator, framed ? EmulatorWire::Mode::Framed : EmulatorWire::Mode::Text, EmulatorWire::Link::Tcp)
{
    connect(&m_server, &QTcpServer::newConnection, this, &TcpServer::accept);
    connect(m_emulator, &CarveraEmulator::lineSent, this, &TcpServer::send);
    connect(m_emulator, &CarveraEmulator::linkClosed, this, &TcpServer::dropAll);
}

TcpServer::~TcpServer()
{
    const QSignalBlocker blocker(this);
    for (QTcpSocket *client : std::as_const(m_clients)) {
        client->disconnect(this);
        client->abort();
        delete client;
    }
}

bool TcpServer::listen(const QHostAddress &address, quint16 port)
{
    return m_server.listen(address, port);
}

void TcpServer::accept()
{
    while (QTcpSocket *client = m_server.nextPendingConnection()) {
        client->setParent(nullptr);
        client->setSocketOption(QAbstractSocket::LowDelayOption, 1); // each line goes as it is printed
        if (m_clients.isEmpty())
            m_wire.reset(); // a half-received line does not outlive the clients that sent it
        m_clients.append(client);
        connect(client, &QTcpSocket::readyRead, this, [this, client] { m_wire.receive(client->readAll()); });
        connect(client, &QTcpSocket::disconnected, this, [this, client] { drop(client); });
        if (m_clients.size() == 1)
            Q_EMIT busyChanged(true);
    }
}

void TcpServer::send(const QByteArray &line)
{
    const QByteArray bytes = m_wire.encode(line);
    if (bytes.isEmpty())
        return;
    const QList<QTcpSocket *> clients = m_clients;
    for (QTcpSocket *client : clients) {
        if (client->bytesToWrite() + bytes.size() > kMaxPendingBytes) {
            drop(client); // it has not read for a long while
            continue;
        }
        client->write(bytes);
    }
}

void TcpServer::drop(QTcpSocket *client)
{
    if (!m_clients.removeOne(client))
        return;
    client->disconnect(this);
    client->abort();
    client->deleteLater();
    if (m_clients.isEmpty())
        Q_EMIT busyChanged(false);
}

void TcpServer::dropAll()
{
    const QList<QTcpSocket *> clients = m_clients;
    if (m_dropByReset) {
        const ::linger reset { 1, 0 };
        for (QTcpSocket *client : clients)
            ::setsockopt(int(client->socketDescriptor()), SOL_SOCKET, SO_LINGER, &reset, sizeof reset);
    }
    for (QTcpSocket *client : clients)
        drop(client);
}

} // namespace Toffee
