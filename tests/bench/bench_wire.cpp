// SPDX-License-Identifier: GPL-3.0-or-later
// The Wi-Fi link's own cost on 127.0.0.1 (issue 28), and the speed of Makera's frame codec.
// Round trips, one at a time, p50 and p99 in microseconds:
//  - the yardstick: a 20-byte line echoed by a QTcpServer's socket back to a QTcpSocket;
//  - "G90" and its "ok" through Toffee's stack: MachineLink over a TcpTransport to the emulator's TcpServer,
//    plain text, then framed.
// Both ends of every kind live in this one thread and its event loop: the yardstick pays the same event loop
// turns as the stack (a QTcpSocket's write goes out on the loop's next turn, on either end), so the ratio is
// what Toffee adds above Qt's sockets, not what Qt costs above the system's calls. The kinds take turns, 100
// round trips at a time, so that a burst of other work falls on all of them alike (in rounds of 1,000 to
// 4,000 a p99 ratio wandered from 0.8 to 1.6 between runs; in rounds of 100, from 1.0 to 1.2). A blocking
// POSIX echo, no event loop at all, shows the loopback's own floor. Then the decoder and the encoder over a
// buffer of mixed frames with garbage between them.
//   toffee-bench-wire [ROUND-TRIPS]   (default 20,000 of each kind, after 200 to warm up)
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QRandomGenerator>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

#include "serial/carvera/carverareplies.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/emulator/tcpserver.h"
#include "serial/machine/machinelink.h"
#include "serial/transport/tcptransport.h"
#include "serial/wire/makeraframe.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

constexpr QByteArrayView kEchoLine = "G0 X100.000 Y20.000\n"; // 20 bytes with its line end
constexpr int kRound = 100; // round trips of one kind before the next kind's turn
constexpr int kWarmUp = 200;
constexpr int kLimitMs = 10000;

[[noreturn]] void fail(const QString &message)
{
    std::fprintf(stderr, "toffee-bench-wire: %s\n", qPrintable(message));
    std::exit(1);
}

// Turns the event loop until `done`, in a QEventLoop that sleeps until something happens (never
// QTest::qWaitFor, which naps 10 ms a turn); fails after kLimitMs.
void waitUntil(const std::function<bool()> &done, const char *what)
{
    QEventLoop loop;
    QElapsedTimer clock;
    clock.start();
    QTimer limit;
    limit.start(kLimitMs); // only wakes the loop to give up
    while (!done()) {
        if (clock.elapsed() > kLimitMs)
            fail(u"no %1 within %2 s"_s.arg(QLatin1StringView(what)).arg(kLimitMs / 1000));
        loop.processEvents(QEventLoop::WaitForMoreEvents);
    }
}

// One kind of round trip: send() starts one, and its answer calls `answered`.
class RoundTrip
{
public:
    virtual ~RoundTrip() = default;
    virtual void send() = 0;
    std::function<void()> answered;
};

class EchoTrip final : public RoundTrip
{
public:
    EchoTrip()
    {
        if (!m_server.listen(QHostAddress::LocalHost, 0))
            fail(m_server.errorString());
        QObject::connect(&m_server, &QTcpServer::newConnection, &m_server, [this] {
            m_peer = m_server.nextPendingConnection();
            m_peer->setSocketOption(QAbstractSocket::LowDelayOption, 1);
            QObject::connect(
                m_peer, &QTcpSocket::readyRead, m_peer, [this] { m_peer->write(m_peer->readAll()); });
        });
        QObject::connect(&m_client, &QTcpSocket::readyRead, &m_client, [this] {
            m_received += m_client.readAll();
            if (m_received.endsWith('\n')) {
                m_received.clear();
                answered();
            }
        });
        m_client.connectToHost(QHostAddress::LocalHost, m_server.serverPort());
        waitUntil([this] { return m_peer && m_client.state() == QAbstractSocket::ConnectedState; }, "echo");
        m_client.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    }
    void send() override { m_client.write(kEchoLine.data(), kEchoLine.size()); }

private:
    QTcpServer m_server;
    QTcpSocket *m_peer = nullptr; // the server's, deleted with it
    QTcpSocket m_client;
    QByteArray m_received;
};

class LinkTrip final : public RoundTrip
{
public:
    explicit LinkTrip(bool framed)
        : m_server(&m_emulator, framed)
    {
        if (!m_server.listen(QHostAddress::LocalHost, 0))
            fail(m_server.errorString());
        m_transport
            = std::make_unique<TcpTransport>(TcpTransport::Address { u"127.0.0.1"_s, m_server.port() });
        m_transport->setProtocol(
            framed ? StreamTransport::Protocol::Framed : StreamTransport::Protocol::Text);
        m_link = std::make_unique<MachineLink>(m_transport.get());
        m_link->setGrammar(carveraGrammar());
        m_link->setPollInterval(0); // the command's round trip alone, no status reports between
        bool opened = false;
        QObject::connect(m_link.get(), &MachineLink::opened, m_link.get(), [&opened] { opened = true; });
        QObject::connect(m_transport.get(), &LineTransport::errorOccurred, m_link.get(), &fail);
        m_link->open();
        waitUntil([&opened] { return opened; }, "connection to the emulator");
    }
    void send() override
    {
        m_link->send("G90", MachineLink::kDefaultTimeoutMs, [this](const CommandReply &reply) {
            if (!reply.ok())
                fail(reply.message);
            answered();
        });
    }

private:
    CarveraEmulator m_emulator;
    TcpServer m_server;
    // Made once the server listens, on the port it took.
    std::unique_ptr<TcpTransport> m_transport;
    std::unique_ptr<MachineLink> m_link;
};

// `count` round trips back to back, each sent from where the last one's answer arrived (as toffee-cli's
// link-test does), all in one event loop.
void measure(RoundTrip &trip, int count, QList<double> *micros)
{
    QElapsedTimer clock;
    int done = 0;
    trip.answered = [&] {
        if (micros)
            micros->append(double(clock.nsecsElapsed()) / 1e3);
        if (++done < count) {
            clock.start();
            trip.send();
        }
    };
    clock.start();
    trip.send();
    waitUntil([&done, count] { return done == count; }, "answer");
    trip.answered = [] {
        fail(u"an answer came that nothing asked for"_s);
    };
}

// The same echo with blocking calls and no event loop: client and server ends of one loopback connection.
QList<double> posixEcho(int count)
{
    const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address {};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (::bind(listener, reinterpret_cast<sockaddr *>(&address), length) != 0 || ::listen(listener, 1) != 0
        || ::getsockname(listener, reinterpret_cast<sockaddr *>(&address), &length) != 0)
        fail(u"cannot listen on 127.0.0.1"_s);
    const int client = ::socket(AF_INET, SOCK_STREAM, 0);
    if (::connect(client, reinterpret_cast<sockaddr *>(&address), length) != 0)
        fail(u"cannot connect to 127.0.0.1"_s);
    const int server = ::accept(listener, nullptr, nullptr);
    const int one = 1;
    ::setsockopt(client, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    ::setsockopt(server, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    const auto receive = [](int fd, char *buffer) {
        for (qsizetype got = 0; got < kEchoLine.size();) {
            const ssize_t n = ::recv(fd, buffer + got, size_t(kEchoLine.size() - got), 0);
            if (n <= 0)
                fail(u"the POSIX echo lost its connection"_s);
            got += n;
        }
    };
    QList<double> micros;
    char buffer[64];
    QElapsedTimer clock;
    for (int i = 0; i < kWarmUp + count; ++i) {
        clock.start();
        ::send(client, kEchoLine.data(), size_t(kEchoLine.size()), 0);
        receive(server, buffer);
        ::send(server, buffer, size_t(kEchoLine.size()), 0);
        receive(client, buffer);
        if (i >= kWarmUp)
            micros.append(double(clock.nsecsElapsed()) / 1e3);
    }
    ::close(client);
    ::close(server);
    ::close(listener);
    return micros;
}

double percentile(QList<double> values, double p)
{
    std::sort(values.begin(), values.end());
    return values.at(std::min<qsizetype>(values.size() - 1, qsizetype(double(values.size()) * p)));
}

struct Message
{
    quint8 type;
    QByteArray payload;
};

// What a Carvera sends while a job runs, mostly: status reports, "ok"s, output of every length now and then
// up to a full frame; a frame in 50 comes after a few stray bytes, one in 100 has its CRC broken.
QByteArray mixedStream(qsizetype bytes, QList<Message> *messages, qint64 *good, qint64 *broken)
{
    QRandomGenerator random(28);
    const QByteArray status
        = "<Run|MPos:-120.500,-80.250,-30.125|WPos:10.000,20.000,5.000|F:800.0,800.0,100.0|"
          "S:10000.0,10000.0,100.0|T:3,-32.410,-1|W:0.00|L:0|C:0,0,0,0,0>\n";
    QByteArray out;
    out.reserve(bytes + 1024);
    for (int i = 0; out.size() < bytes; ++i) {
        Message m;
        switch (i % 4) {
        case 0:
            m = { MakeraFrame::Status, status };
            break;
        case 1:
        case 2:
            m = { MakeraFrame::Reply, "ok\r\n" };
            break;
        default:
            m = { MakeraFrame::Output, QByteArray(random.bounded(i % 40 == 3 ? 513 : 80) + 1, 'x') };
            break;
        }
        if (i % 50 == 49)
            out += QByteArrayView("\x86junk\r\n\x86\x68", 9);
        QByteArray frame = MakeraFrame::encode(m.type, m.payload);
        if (i % 100 == 99) {
            frame[frame.size() - 3] = char(frame[frame.size() - 3] ^ 0x5A);
            ++*broken;
        } else {
            ++*good;
        }
        out += frame;
        messages->append(std::move(m));
    }
    return out;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const int count = argc > 1 ? QByteArray(argv[1]).toInt() : 20000;
    if (count < kRound)
        fail(u"give at least %1 round trips"_s.arg(kRound));

    EchoTrip echo;
    LinkTrip text(false);
    LinkTrip framed(true);
    RoundTrip *const trips[] = { &echo, &text, &framed };
    QList<double> micros[3];
    for (RoundTrip *trip : trips)
        measure(*trip, kWarmUp, nullptr);
    for (int round = 0; round < count / kRound; ++round) {
        for (int k = 0; k < 3; ++k)
            measure(*trips[k], kRound, &micros[k]);
    }
    const QList<double> posix = posixEcho(count);

    const double yardstickP50 = percentile(micros[0], 0.5);
    const double yardstickP99 = percentile(micros[0], 0.99);
    const char *const names[] = {
        "TCP echo of a 20-byte line, QTcpServer to QTcpSocket, one event loop (the yardstick)",
        "G90 and its ok: MachineLink, TcpTransport, emulator's TcpServer, plain text",
        "the same, framed",
    };
    std::printf("| round trip on 127.0.0.1, %lld of each | p50 | p99 | p50 / yardstick | p99 / yardstick |\n"
                "|---|---:|---:|---:|---:|\n",
        static_cast<long long>(micros[0].size()));
    for (int k = 0; k < 3; ++k) {
        const double p50 = percentile(micros[k], 0.5);
        const double p99 = percentile(micros[k], 0.99);
        std::printf("| %s | %.1f µs | %.1f µs | %.2f× | %.2f× |\n", names[k], p50, p99, p50 / yardstickP50,
            p99 / yardstickP99);
    }
    std::printf(
        "| for scale: the same echo, blocking POSIX calls, no event loop | %.1f µs | %.1f µs | | |\n\n",
        percentile(posix, 0.5), percentile(posix, 0.99));

    // The codec: 32 MB of frames, decoded as they would come in 64 KiB reads; median of 5.
    QList<Message> messages;
    qint64 good = 0;
    qint64 broken = 0;
    const QByteArray stream = mixedStream(32 * 1000 * 1000, &messages, &good, &broken);
    QList<double> decodeSeconds;
    for (int run = 0; run < 5; ++run) {
        MakeraFrame::Decoder decoder;
        qint64 frames = 0;
        QElapsedTimer clock;
        clock.start();
        for (qsizetype at = 0; at < stream.size(); at += 65536)
            frames += decoder
                          .feed(QByteArrayView(stream).sliced(
                              at, std::min<qsizetype>(65536, stream.size() - at)))
                          .size();
        decodeSeconds.append(double(clock.nsecsElapsed()) / 1e9);
        if (frames != good || decoder.counts().badCrc != broken)
            fail(u"the decoder found %1 frames and %2 broken, not %3 and %4"_s.arg(frames)
                     .arg(decoder.counts().badCrc)
                     .arg(good)
                     .arg(broken));
    }
    QList<double> encodeSeconds;
    qint64 encodedBytes = 0;
    for (int run = 0; run < 5; ++run) {
        encodedBytes = 0;
        QElapsedTimer clock;
        clock.start();
        for (const Message &m : std::as_const(messages))
            encodedBytes += MakeraFrame::encode(m.type, m.payload).size();
        encodeSeconds.append(double(clock.nsecsElapsed()) / 1e9);
    }
    const double decode = percentile(decodeSeconds, 0.5);
    const double encode = percentile(encodeSeconds, 0.5);
    std::printf("| Makera's frames, median of 5 | MB/s | million frames/s |\n|---|---:|---:|\n");
    std::printf(
        "| decode %.1f MB in 64 KiB reads: %lld frames, %lld with a broken CRC, stray bytes before 1 in 50 | "
        "%.0f | %.2f |\n",
        double(stream.size()) / 1e6, static_cast<long long>(good + broken), static_cast<long long>(broken),
        double(stream.size()) / 1e6 / decode, double(good + broken) / 1e6 / decode);
    std::printf("| encode the same %lld frames (%.1f MB) | %.0f | %.2f |\n",
        static_cast<long long>(messages.size()), double(encodedBytes) / 1e6,
        double(encodedBytes) / 1e6 / encode, double(messages.size()) / 1e6 / encode);
    return 0;
}
