// SPDX-License-Identifier: GPL-3.0-or-later
// What tst_tcptransport.cpp and x.cpp share.
#pragma once

#include "serial/carvera/carverareplies.h"
#include "serial/machine/machinelink.h"
#include "serial/machineconnection.h"
#include "serial/transport/tcptransport.h"
#include "serial/wire/makeraframe.h"
#include "tests/support/firstquestion.h"
#include "tests/support/silentlistener.h"
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>
#include <arpa/inet.h>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <functional>
#include <memory>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <optional>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

namespace Toffee::Test {

using namespace Qt::StringLiterals;

// Runs the event loop until `done` or `ms` pass; true when done. Woken by the event that changes things, not
// by QTest::qWaitFor's 10 ms naps, so that elapsed times measure the transport rather than the test.
inline bool runUntil(const std::function<bool()> &done, int ms)
{
    QElapsedTimer clock;
    clock.start();
    QTimer deadline; // wakes the wait below at the latest
    deadline.setSingleShot(true);
    deadline.setTimerType(Qt::PreciseTimer);
    deadline.start(ms);
    while (!done()) {
        // Once the deadline has fired no event may come to wake the wait (a coarse timer fires early).
        if (clock.elapsed() >= ms || !deadline.isActive())
            return done();
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    }
    return true;
}

// The machine's end: a listener on 127.0.0.1 that accepts one client and reads what it sends.
struct Peer
{
    QTcpServer server;
    QTcpSocket *socket = nullptr;

    Peer() { server.listen(QHostAddress::LocalHost, 0); }
    [[nodiscard]] TcpTransport::Address address() const { return { u"127.0.0.1"_s, server.serverPort() }; }
    bool accept()
    {
        if (!runUntil([this] { return server.hasPendingConnections(); }, 3000))
            return false;
        socket = server.nextPendingConnection();
        return socket != nullptr;
    }
    // The first question answered as a plain-text machine answers it.
    bool answer()
    {
        return Test::answerFirstQuestion(
            [this] { return socket->readAll(); }, [this](const QByteArray &b) { socket->write(b); });
    }
    // What the client sent until it ends with `end` (or 3 s pass).
    QByteArray readUntil(QByteArrayView end)
    {
        QByteArray got;
        runUntil(
            [&] {
                got += socket->readAll();
                return got.endsWith(end);
            },
            3000);
        return got;
    }
};

// This process's TCP socket whose local end is 127.0.0.1:`port`: the transport keeps its QTcpSocket to
// itself, and what counts is what the kernel was told about the socket anyway.
inline int socketWithLocalPort(quint16 port)
{
    for (int fd = 0; fd < 1024; ++fd) {
        sockaddr_in a {};
        socklen_t size = sizeof a;
        if (::getsockname(fd, reinterpret_cast<sockaddr *>(&a), &size) == 0 && a.sin_family == AF_INET
            && ntohs(a.sin_port) == port)
            return fd;
    }
    return -1;
}

inline int intOption(int fd, int level, int name)
{
    int value = -1;
    socklen_t size = sizeof value;
    return ::getsockopt(fd, level, name, &value, &size) == 0 ? value : -2;
}

// A link opened on `peer`'s first client, in plain text (the test speaks for the machine), without status
// polls; false when it did not open.
inline bool openLink(Peer &peer, MachineLink &link)
{
    link.setPollInterval(0);
    QSignalSpy opened(&link, &MachineLink::opened);
    link.open();
    return peer.accept() && peer.answer() && runUntil([&] { return !opened.isEmpty(); }, 3000);
}

// A Carvera's link in plain text on `peer` (the test speaks for the machine): open it with openLink.
struct PlainLink
{
    TcpTransport transport;
    MachineLink link { &transport };

    explicit PlainLink(const Peer &peer)
        : transport(peer.address())
    {
        transport.setProtocol(StreamTransport::Protocol::Text);
        link.setGrammar(carveraGrammar());
    }
};

} // namespace Toffee::Test
