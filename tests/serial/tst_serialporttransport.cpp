// SPDX-License-Identifier: GPL-3.0-or-later
// SerialPortTransport on a real pseudo-terminal that the test writes to byte by byte.
#include <cstdlib>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <QSignalSpy>
#include <QTest>

#include "serial/transport/serialporttransport.h"
#include "tests/support/firstquestion.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

struct Pty
{
    int master = -1;
    QString slave;

    Pty()
    {
        master = posix_openpt(O_RDWR | O_NOCTTY);
        if (master >= 0 && grantpt(master) == 0 && unlockpt(master) == 0) {
            slave = QString::fromLocal8Bit(ptsname(master));
            ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
        }
    }
    ~Pty() { close(); }
    void write(const QByteArray &bytes) const
    {
        QVERIFY(::write(master, bytes.constData(), size_t(bytes.size())) == bytes.size());
    }
    QByteArray read() const
    {
        QByteArray out(4096, '\0');
        const ssize_t n = ::read(master, out.data(), size_t(out.size()));
        out.resize(n > 0 ? n : 0);
        return out;
    }
    void close()
    {
        if (master >= 0)
            ::close(master);
        master = -1;
    }
};

// The first question answered as a plain-text machine answers it.
bool answer(const Pty &pty)
{
    return Test::answerFirstQuestion([&pty] { return pty.read(); }, [&pty](const QByteArray &b) { pty.write(b); });
}

} // namespace

class TestSerialPortTransport : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void buffersPartialLinesAndSplitsOnCrOrLf()
    {
        Pty pty;
        QVERIFY(!pty.slave.isEmpty());
        SerialPortTransport transport(pty.slave);
        transport.setProtocol(StreamTransport::Protocol::Text); // the test speaks for the machine
        QSignalSpy opened(&transport, &LineTransport::opened);
        QSignalSpy lines(&transport, &LineTransport::lineReceived);
        transport.open();
        QVERIFY(answer(pty));
        QTRY_COMPARE(opened.size(), 1);
        QCOMPARE(transport.description(), pty.slave + u" at 115200 baud"_s);

        pty.write("o");
        QTest::qWait(50);
        QCOMPARE(lines.size(), 0); // half a line is not a line
        pty.write("k\r\n<Idle|MPos:0,0,0>\rcurrent tool offset [1] , ref");
        QTRY_COMPARE(lines.size(), 2);
        QCOMPARE(lines.at(0).front().toByteArray(), QByteArray("ok"));
        QCOMPARE(lines.at(1).front().toByteArray(), QByteArray("<Idle|MPos:0,0,0>"));
        pty.write("erence tool offset [0]\n");
        QTRY_COMPARE(lines.size(), 3);
        QCOMPARE(lines.at(2).front().toByteArray(),
            QByteArray("current tool offset [1] , reference tool offset [0]"));
    }

    void writesLinesAndRealtimeCharacters()
    {
        Pty pty;
        SerialPortTransport transport(pty.slave);
        transport.setProtocol(StreamTransport::Protocol::Text); // the test speaks for the machine
        QSignalSpy opened(&transport, &LineTransport::opened);
        transport.open();
        QVERIFY(answer(pty));
        QTRY_COMPARE(opened.size(), 1);
        transport.writeLine("M493.4");
        transport.writeRealtime('?');
        QByteArray received;
        QTRY_VERIFY((received += pty.read()).size() >= 8);
        QCOMPARE(received, QByteArray("M493.4\n?"));
    }

    // An over-long line keeps its first 4096 bytes, so that what it starts with ("error:") is still read;
    // the rest is dropped up to its end, and the transport says so once.
    void cutsAnOverlongLineOnce()
    {
        Pty pty;
        SerialPortTransport transport(pty.slave);
        transport.setProtocol(StreamTransport::Protocol::Text); // the test speaks for the machine
        QSignalSpy opened(&transport, &LineTransport::opened);
        QSignalSpy lines(&transport, &LineTransport::lineReceived);
        QSignalSpy errors(&transport, &LineTransport::errorOccurred);
        transport.open();
        QVERIFY(answer(pty));
        QTRY_COMPARE(opened.size(), 1);
        pty.write("error:");
        for (int i = 0; i < 3; ++i) {
            pty.write(QByteArray(3000, 'x'));
            QTest::qWait(20);
        }
        pty.write("\nok\n");
        QTRY_COMPARE(lines.size(), 2);
        QCOMPARE(lines.at(0).front().toByteArray(), "error:" + QByteArray(4090, 'x'));
        QCOMPARE(lines.at(1).front().toByteArray(), QByteArray("ok")); // the rest never became a line
        QCOMPARE(errors.size(), 1);
        QVERIFY(errors.front().front().toString().contains(u"longer than 4096 bytes"_s));
    }

    void reportsAPortThatGoesAway()
    {
        Pty pty;
        SerialPortTransport transport(pty.slave);
        transport.setProtocol(StreamTransport::Protocol::Text); // the test speaks for the machine
        QSignalSpy opened(&transport, &LineTransport::opened);
        QSignalSpy errors(&transport, &LineTransport::errorOccurred);
        QSignalSpy closed(&transport, &LineTransport::closed);
        transport.open();
        QVERIFY(answer(pty));
        QTRY_COMPARE(opened.size(), 1);
        pty.close(); // the machine is switched off
        QTRY_COMPARE_WITH_TIMEOUT(closed.size(), 1, 5000);
        QVERIFY(!transport.isOpen());
        QCOMPARE(errors.size(), 1); // once, not a flood
        const QString said = errors.last().front().toString();
        QVERIFY2(said.contains(pty.slave) && said.contains(u"stopped answering"_s), qPrintable(said));
        // Not a stale errno's words ("File exists", "Inappropriate ioctl for device").
        QVERIFY2(!said.contains(u'('), qPrintable(said));
    }

    // The first question is `version ?` in a frame, and a plain-text firmware's answer to its '?' makes the
    // link plain text: a line end then flushes the frame's other bytes from the firmware's line ("ok - ignore:
    // [..]"), and nothing said before is taken for the machine's words (boot lines).
    void findsPlainTextByItsAnswerToAFramedQuery()
    {
        Pty pty;
        SerialPortTransport transport(pty.slave);
        QSignalSpy opened(&transport, &LineTransport::opened);
        QSignalSpy lines(&transport, &LineTransport::lineReceived);
        transport.open();
        QByteArray sent;
        QTRY_VERIFY((sent += pty.read()).size() >= 10);
        QCOMPARE(sent, MakeraFrame::encode(MakeraFrame::Command, "version ?"));
        pty.write("version = 2.1.0c\r\nok\r\n<Idle|MPos:0,0,0|T:1,0.000,-1,0>\r\n");
        sent.clear();
        QTRY_COMPARE((sent += pty.read()), QByteArray("\n"));
        QCOMPARE(opened.size(), 0); // not before the flush is answered
        pty.write(QByteArray("ok - ignore: [\x86h]\r\n"));
        QTRY_COMPARE(opened.size(), 1);
        QCOMPARE(transport.mode(), ConsoleStream::Mode::Text);
        QCOMPARE(lines.size(), 0);
        transport.writeLine("M493.4");
        sent.clear();
        QTRY_COMPARE((sent += pty.read()), QByteArray("M493.4\n"));
        pty.write("ok\r\n");
        QTRY_COMPARE(lines.size(), 1);
        QCOMPARE(lines.front().front().toByteArray(), QByteArray("ok"));
    }

    // The framed firmware answers in a frame: from then on every line goes out as a frame, and what comes
    // back is read from frames split anywhere, with the bytes between them never taken for the machine's.
    void findsFramesByTheirAnswer()
    {
        Pty pty;
        SerialPortTransport transport(pty.slave);
        QSignalSpy opened(&transport, &LineTransport::opened);
        QSignalSpy lines(&transport, &LineTransport::lineReceived);
        transport.open();
        QByteArray sent;
        QTRY_VERIFY((sent += pty.read()).size() >= 10);
        pty.write(MakeraFrame::encode(MakeraFrame::Status, "<Idle|MPos:0,0,0>\n"));
        QTRY_COMPARE(opened.size(), 1);
        QCOMPARE(transport.mode(), ConsoleStream::Mode::Framed);
        QVERIFY(transport.description().endsWith(u" (framed)"_s));
        transport.writeLine("M493.4");
        transport.writeRealtime('?');
        sent.clear();
        const QByteArray expected = MakeraFrame::encode(MakeraFrame::Command, "M493.4")
            + MakeraFrame::encode(MakeraFrame::RealTime, "?");
        QTRY_COMPARE((sent += pty.read()), expected);
        const QByteArray reply = MakeraFrame::encode(MakeraFrame::Output, "current tool offset [0.000] , ")
            + "stray text\n" + MakeraFrame::encode(MakeraFrame::Output, "reference tool offset [-115.340]\n")
            + MakeraFrame::encode(MakeraFrame::Reply, "ok\r\n")
            + MakeraFrame::encode(MakeraFrame::Status, "<Idle|MPos:0,0,0>\n");
        for (qsizetype i = 0; i < reply.size(); i += 7) { // split at any byte
            pty.write(reply.mid(i, 7));
            QTest::qWait(2);
        }
        QTRY_COMPARE(lines.size(), 3);
        QCOMPARE(lines.at(0).front().toByteArray(),
            QByteArray("current tool offset [0.000] , reference tool offset [-115.340]"));
        QCOMPARE(lines.at(1).front().toByteArray(), QByteArray("ok"));
        QCOMPARE(lines.at(2).front().toByteArray(), QByteArray("<Idle|MPos:0,0,0>"));
        QCOMPARE(transport.stream().frameCounts().strayBytes, 11);
    }

    // A port where nothing answers: three questions a second apart, then a clear error and the port closed.
    void saysWhenNothingAnswersTheQuery()
    {
        Pty pty;
        SerialPortTransport transport(pty.slave);
        QSignalSpy opened(&transport, &LineTransport::opened);
        QSignalSpy errors(&transport, &LineTransport::errorOccurred);
        QSignalSpy closed(&transport, &LineTransport::closed);
        transport.open();
        QTRY_COMPARE_WITH_TIMEOUT(closed.size(), 1, 5000);
        QCOMPARE(opened.size(), 0);
        QCOMPARE(errors.size(), 1);
        QVERIFY2(errors.front().front().toString().contains(
                     u"did not answer within 3 s, in plain text or in Makera's frames"_s),
            qPrintable(errors.front().front().toString()));
        QCOMPARE(pty.read(), StreamTransport::firstQuestion().repeated(3));
    }

    void saysWhyAPortCannotOpen()
    {
        SerialPortTransport transport(u"/dev/no-such-port"_s);
        QSignalSpy errors(&transport, &LineTransport::errorOccurred);
        transport.open();
        QVERIFY(!transport.isOpen());
        QCOMPARE(errors.size(), 0); // queued, like every signal of a transport
        QTRY_COMPARE(errors.size(), 1);
        QVERIFY(errors.front().front().toString().startsWith(u"Cannot open /dev/no-such-port"_s));
    }
};

QTEST_GUILESS_MAIN(TestSerialPortTransport)
#include "tst_serialporttransport.moc"
