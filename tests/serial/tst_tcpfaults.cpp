// SPDX-License-Identifier: GPL-3.0-or-later
// TcpTransport when the machine's end misbehaves, on real sockets on 127.0.0.1: a peer that closes, resets or
// falls silent while a command waits, a flood, a receiver holding the event loop, and Makera's frames with
// garbage between them. The peer is the test (tests/support/tcppeer.h).
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

#include "tests/support/tcppeer.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using namespace Toffee::Test;

class TestTcpFaults : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // A receiver that holds the event loop (the window's modal box opened from a status or an alarm: its own
    // loop runs inside the handler) does not stop the reading: the status reports keep coming while it is
    // open, and in order. Before, the socket said nothing more until the handler returned ("no status report
    // for 17 s" while the machine was idle).
    void aReceiverHoldingTheEventLoopDoesNotStopTheReading()
    {
        Peer peer;
        PlainLink plain(peer);
        QVERIFY(openLink(peer, plain.link));
        MachineLink &link = plain.link;
        int sent = 0;
        connect(peer.socket, &QTcpSocket::readyRead, &peer.server, [&peer, &sent] {
            for (const char c : peer.socket->readAll()) {
                if (c == '?')
                    peer.socket->write(QByteArray("<Idle|MPos:0.000,0.000,") + QByteArray::number(++sent)
                        + ".000|WPos:0.000,0.000,0.000>\r\n");
            }
        });
        QList<double> seen;
        int seenInside = 0;
        bool inside = false;
        connect(&link, &MachineLink::statusChanged, &link, [&](const MachineStatus &status) {
            seen << status.mpos[2];
            if (inside)
                ++seenInside;
            if (seen.size() != 1)
                return;
            inside = true;
            QEventLoop modal; // as QMessageBox::exec runs one
            QTimer::singleShot(1500, &modal, &QEventLoop::quit);
            modal.exec();
            inside = false;
        });
        link.setPollInterval(100);
        QVERIFY(runUntil([&] { return seen.size() >= 20; }, 5000));
        QVERIFY2(seenInside >= 8, qPrintable(QString::number(seenInside)));
        for (qsizetype i = 0; i < seen.size(); ++i)
            QCOMPARE(seen.at(i), double(i + 1)); // each once, in the order sent
    }

    // The machine closes the connection (switched off cleanly, restarted, another program took it) while a
    // command waits: the command fails at once, not at its 5 s limit, in words that say what happened.
    void peerClosingFailsTheCommandAtOnce()
    {
        Peer peer;
        PlainLink plain(peer);
        QVERIFY(openLink(peer, plain.link));
        TcpTransport &transport = plain.transport;
        MachineLink &link = plain.link;
        QSignalSpy closed(&link, &MachineLink::closed);
        std::optional<CommandReply> reply;
        link.send("M493.4", MachineLink::kDefaultTimeoutMs, [&reply](const CommandReply &r) { reply = r; });
        QCOMPARE(peer.readUntil("\n"), QByteArray("M493.4\n"));
        QElapsedTimer clock;
        clock.start();
        peer.socket->disconnectFromHost();
        QVERIFY(runUntil([&] { return reply.has_value(); }, 3000));
        QVERIFY2(clock.elapsed() < 500, qPrintable(QString::number(clock.elapsed())));
        QCOMPARE(reply->status, CommandReply::Status::LinkLost);
        QVERIFY2(reply->message.contains(u"while it ran \"M493.4\""_s), qPrintable(reply->message));
        const QString address = u"127.0.0.1:%1"_s.arg(peer.server.serverPort());
        QVERIFY2(reply->message.contains(u"The machine at %1 closed the connection"_s.arg(address)),
            qPrintable(reply->message));
        QVERIFY(!transport.isOpen());
        QCOMPARE(closed.size(), 1);
        // This side closed too, and said so to the machine, which can serve the next client.
        QVERIFY(runUntil([&] { return peer.socket->state() == QAbstractSocket::UnconnectedState; }, 3000));
    }

    // The connection is reset (RST: the machine lost power mid-stream, a router dropped it): the same at
    // once, said as a lost link.
    void peerResettingFailsTheCommandAtOnce()
    {
        Peer peer;
        PlainLink plain(peer);
        QVERIFY(openLink(peer, plain.link));
        TcpTransport &transport = plain.transport;
        MachineLink &link = plain.link;
        std::optional<CommandReply> reply;
        link.send(
            "M491", MachineLink::kMotionTimeoutMs, [&reply](const CommandReply &r) { reply = r; },
            ReplyEnd::Script);
        QCOMPARE(peer.readUntil("\n"), QByteArray("M491\n"));
        const ::linger reset { 1, 0 };
        QCOMPARE(
            ::setsockopt(int(peer.socket->socketDescriptor()), SOL_SOCKET, SO_LINGER, &reset, sizeof reset),
            0);
        QElapsedTimer clock;
        clock.start();
        peer.socket->abort();
        QVERIFY(runUntil([&] { return reply.has_value(); }, 3000));
        QVERIFY2(clock.elapsed() < 500, qPrintable(QString::number(clock.elapsed())));
        QCOMPARE(reply->status, CommandReply::Status::LinkLost);
        const QString address = u"127.0.0.1:%1"_s.arg(peer.server.serverPort());
        QVERIFY2(reply->message.contains(
                     u"The link to %1 was lost (%2)"_s.arg(address, qt_error_string(ECONNRESET))),
            qPrintable(reply->message));
        QVERIFY2(reply->message.contains(u"switched off or left the network"_s), qPrintable(reply->message));
        QVERIFY2(!reply->message.contains(u"closed the connection"_s), qPrintable(reply->message));
        QVERIFY(!transport.isOpen());
    }

    // A peer that took the connection and then says nothing (half-open as the client sees it: a machine
    // hung, or gone without a word while the kernel on its side still acknowledges): the command fails at its
    // own limit, and the link is closed, since a late answer could be taken for the next command's.
    // Keepalives and TCP_USER_TIMEOUT are for a peer whose kernel is gone too, which loopback cannot play:
    // what they are set to is tunesTheConnectedSocket's.
    void silentPeerFailsTheCommandAtItsLimit()
    {
        Peer peer;
        PlainLink plain(peer);
        QVERIFY(openLink(peer, plain.link));
        TcpTransport &transport = plain.transport;
        MachineLink &link = plain.link;
        std::optional<CommandReply> reply;
        QElapsedTimer clock;
        clock.start();
        link.send("M493.4", 1000, [&reply](const CommandReply &r) { reply = r; });
        QCOMPARE(peer.readUntil("\n"), QByteArray("M493.4\n"));
        QVERIFY(runUntil([&] { return reply.has_value(); }, 4000));
        const qint64 elapsed = clock.elapsed();
        QVERIFY2(elapsed >= 1000 && elapsed < 1500, qPrintable(QString::number(elapsed)));
        QCOMPARE(reply->status, CommandReply::Status::Timeout);
        QVERIFY2(reply->message.startsWith(u"The machine did not answer \"M493.4\" within 1.0 s"_s),
            qPrintable(reply->message));
        QVERIFY(!transport.isOpen());
        QVERIFY(runUntil([&] { return peer.socket->state() == QAbstractSocket::UnconnectedState; }, 3000));
    }

    // A peer that floods (lines nobody asked for, as fast as loopback carries them) while a command waits:
    // the transport reads a slice at a time and lets the event loop run between, so the command's 1 s limit
    // still ends it about on time (a flood once made one read of 300 MB and a 3 s limit 6 s).
    void aFloodIsReadASliceAtATimeAndTheLimitHolds()
    {
        const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in address {};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        QVERIFY(::bind(listener, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0);
        QVERIFY(::listen(listener, 1) == 0);
        socklen_t length = sizeof address;
        QVERIFY(::getsockname(listener, reinterpret_cast<sockaddr *>(&address), &length) == 0);
        std::atomic_bool stop = false;
        std::atomic<qint64> sent = 0;
        std::thread flood([&] {
            const int peer = ::accept(listener, nullptr, nullptr);
            if (peer < 0)
                return;
            // The first question answered as a plain machine does, then the flood.
            const QByteArray question = StreamTransport::firstQuestion();
            QByteArray got;
            char buffer[256];
            while (!got.contains(question)) {
                const ssize_t n = ::recv(peer, buffer, sizeof buffer, 0);
                if (n <= 0)
                    return;
                got.append(buffer, n);
            }
            got.remove(0, got.indexOf(question) + question.size());
            ::send(peer, Test::kPlainStatus, std::strlen(Test::kPlainStatus), MSG_NOSIGNAL);
            while (!got.contains('\n')) {
                const ssize_t n = ::recv(peer, buffer, sizeof buffer, 0);
                if (n <= 0)
                    return;
                got.append(buffer, n);
            }
            ::send(peer, "ok\r\n", 4, MSG_NOSIGNAL);
            QByteArray chunk;
            for (int i = 0; i < 4096; ++i)
                chunk += "ALARM: Hard limit\n";
            while (!stop) {
                const ssize_t n = ::send(peer, chunk.constData(), size_t(chunk.size()), MSG_NOSIGNAL);
                if (n <= 0)
                    break;
                sent += n;
            }
            ::close(peer);
        });
        TcpTransport transport(TcpTransport::Address { u"127.0.0.1"_s, ntohs(address.sin_port) });
        transport.setProtocol(StreamTransport::Protocol::Text);
        MachineLink link(&transport);
        link.setGrammar(carveraGrammar());
        link.setPollInterval(0);
        std::optional<CommandReply> reply;
        QElapsedTimer clock;
        link.open();
        QVERIFY(runUntil([&] { return link.isOpen(); }, 4000));
        clock.start();
        link.send("M493.4", 1000, [&reply](const CommandReply &r) { reply = r; });
        const bool ended = runUntil([&] { return reply.has_value(); }, 10000);
        const qint64 elapsed = clock.elapsed();
        stop = true;
        transport.close();
        flood.join();
        ::close(listener);
        QVERIFY(ended);
        qInfo("%lld MB flooded; the 1 s limit ended the command after %lld ms", sent / 1000000, elapsed);
        QVERIFY2(sent > 10'000'000, qPrintable(QString::number(sent)));
        QCOMPARE(reply->status, CommandReply::Status::Timeout);
        QVERIFY2(elapsed < 2500, qPrintable(QString::number(elapsed)));
    }

    // Over TCP, as on a serial port, the framed firmware's bytes may come with noise between its frames
    // (boot text, a broken frame, a stray header byte): found by the transport as framed, and every command
    // still understood, nothing of the noise taken for the machine's words.
    void understandsFramesWithGarbageBetweenThem()
    {
        Peer peer;
        TcpTransport transport(peer.address());
        MachineLink link(&transport);
        link.setGrammar(carveraGrammar());
        link.setPollInterval(0);
        QSignalSpy opened(&link, &MachineLink::opened);
        QSignalSpy lines(&link, &MachineLink::lineReceived);
        link.open();
        QVERIFY(peer.accept());
        const QByteArray query = StreamTransport::firstQuestion();
        QCOMPARE(peer.readUntil(query), query);
        QByteArray broken = MakeraFrame::encode(MakeraFrame::Output, "bad crc\n");
        broken[broken.size() - 3] = char(broken.at(broken.size() - 3) ^ 0x5a);
        peer.socket->write("boot text\r\n" + broken + "\x86"
            + MakeraFrame::encode(MakeraFrame::Status, "<Idle|MPos:0,0,0|T:2,9.652,-1,0>\n") + "\x55\xaa");
        QVERIFY(runUntil([&] { return !opened.isEmpty(); }, 3000));
        QCOMPARE(transport.mode(), ConsoleStream::Mode::Framed);

        std::optional<CommandReply> reply;
        link.send("M493.4", MachineLink::kDefaultTimeoutMs, [&reply](const CommandReply &r) { reply = r; });
        const QByteArray command = MakeraFrame::encode(MakeraFrame::Command, "M493.4");
        QCOMPARE(peer.readUntil(command), command);
        const QByteArray answer = "\x86\x68junk"
            + MakeraFrame::encode(MakeraFrame::Reply, "current tool offset [") + QByteArray("\r\n\x00\xff", 4)
            + broken + MakeraFrame::encode(MakeraFrame::Reply, "9.652] , reference tool offset ") + "noise"
            + MakeraFrame::encode(MakeraFrame::Reply, "[-115.340]\r\n")
            + MakeraFrame::encode(MakeraFrame::Reply, "ok\r\n") + "trailing noise";
        for (qsizetype i = 0; i < answer.size(); i += 5) { // split anywhere
            peer.socket->write(answer.mid(i, 5));
            peer.socket->flush();
        }
        QVERIFY(runUntil([&] { return reply.has_value(); }, 3000));
        QVERIFY2(reply->ok(), qPrintable(reply->message));
        QCOMPARE(reply->lines,
            QList<QByteArray> { "current tool offset [9.652] , reference tool offset [-115.340]" });
        QStringList heard;
        for (const auto &l : std::as_const(lines))
            heard << QString::fromLatin1(l.front().toByteArray());
        QCOMPARE(heard,
            (QStringList { u"current tool offset [9.652] , reference tool offset [-115.340]"_s, u"ok"_s }));
        const auto &counts = transport.stream().frameCounts();
        QCOMPARE(counts.badCrc, 1);
        QVERIFY2(counts.strayBytes >= 20, qPrintable(QString::number(counts.strayBytes)));
        QVERIFY(transport.isOpen());
    }
};

QTEST_GUILESS_MAIN(TestTcpFaults)
#include "tst_tcpfaults.moc"
