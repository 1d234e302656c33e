// SPDX-License-Identifier: GPL-3.0-or-later
// A TCP port on 127.0.0.1 where connecting hangs, as to a machine that is switched off: honest, on loopback.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <QList>

namespace Toffee::Test {

// A listener that never accepts, its queue full: backlog 0 holds one connection, which it makes itself; Linux
// then drops a new client's SYN (net.ipv4.tcp_abort_on_overflow 0, the default), so the client's connect
// waits on its SYN retries, neither refused nor answered.
struct SilentListener
{
    int listener = -1;
    QList<int> queued;
    quint16 port = 0;
    bool full = false; // false: the port does not hang, and a test on it would prove nothing

    SilentListener()
    {
        listener = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in a {};
        a.sin_family = AF_INET;
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t size = sizeof a;
        if (::bind(listener, reinterpret_cast<sockaddr *>(&a), size) != 0 || ::listen(listener, 0) != 0
            || ::getsockname(listener, reinterpret_cast<sockaddr *>(&a), &size) != 0)
            return;
        port = ntohs(a.sin_port);
        // Connections until one does not complete: the queue is full from then on.
        for (int i = 0; i < 8 && !full; ++i) {
            const int s = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
            ::connect(s, reinterpret_cast<sockaddr *>(&a), sizeof a);
            pollfd p { s, POLLOUT, 0 };
            if (::poll(&p, 1, 300) == 1) {
                queued << s;
            } else {
                ::close(s);
                full = true;
            }
        }
    }
    ~SilentListener()
    {
        for (const int s : std::as_const(queued))
            ::close(s);
        ::close(listener);
    }
    SilentListener(const SilentListener &) = delete;
    SilentListener &operator=(const SilentListener &) = delete;
};

} // namespace Toffee::Test
