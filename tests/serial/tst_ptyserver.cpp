// SPDX-License-Identifier: GPL-3.0-or-later
// PtyServer on a real pseudo-terminal, with a client that does not read.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <sys/resource.h>
#include <thread>
#include <unistd.h>

#include <QTest>

#include "serial/carvera/carverareplies.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/emulator/ptyserver.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

// Aborts the test if it is still running after `seconds`: a busy-spinning server would never return.
class Watchdog
{
public:
    explicit Watchdog(int seconds)
        : m_thread([this, seconds] {
            for (int i = 0; i < seconds * 10 && !m_done; ++i)
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
            if (!m_done) {
                std::fprintf(stderr, "FAIL: still running after %d s: the server spins\n", seconds);
                std::abort();
            }
        })
    { }
    ~Watchdog()
    {
        m_done = true;
        m_thread.join();
    }

private:
    std::atomic<bool> m_done = false;
    std::thread m_thread;
};

double cpuSeconds()
{
    rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec)
        + double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

} // namespace

class TestPtyServer : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void aClientThatNeverReadsCostsNeitherCpuNorMemory()
    {
        Watchdog watchdog(20);
        CarveraEmulator emulator;
        PtyServer server(&emulator);
        QVERIFY2(server.start(), qPrintable(server.errorString()));

        // Far more than the terminal holds, with nobody reading.
        constexpr int kReports = 2000;
        for (int i = 0; i < kReports; ++i)
            emulator.receiveRealtime('?');
        QVERIFY(server.droppedLines() > 0);
        QVERIFY(server.pendingBytes() <= PtyServer::kMaxPendingBytes);

        // Waiting for room costs nothing: no spinning on EAGAIN.
        const double before = cpuSeconds();
        QTest::qWait(1000);
        QVERIFY2(cpuSeconds() - before < 0.3, qPrintable(QString::number(cpuSeconds() - before)));

        // A client that reads at last gets whole lines, each a status report, and then answers again.
        const int client
            = ::open(server.devicePath().toLocal8Bit().constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
        QVERIFY(client >= 0);
        QByteArray received;
        auto drain = [&] {
            char buffer[4096];
            ssize_t n = 0;
            while ((n = ::read(client, buffer, sizeof buffer)) > 0)
                received.append(buffer, n);
        };
        QTRY_VERIFY_WITH_TIMEOUT((drain(), server.pendingBytes() == 0), 5000);
        QTest::qWait(50);
        drain();
        QVERIFY(received.endsWith("\r\n"));
        const QList<QByteArray> lines = received.chopped(2).split('\n');
        for (const QByteArray &line : lines)
            QVERIFY2(parseStatusReport(line.trimmed()).has_value(), line.constData());
        QCOMPARE(lines.size() + server.droppedLines(), kReports);

        received.clear();
        QCOMPARE(::write(client, "?", 1), 1);
        QTRY_VERIFY_WITH_TIMEOUT((drain(), received.endsWith(">\r\n")), 5000);
        QVERIFY(parseStatusReport(received.trimmed()).has_value());
        ::close(client);
    }

    void splitsTheStreamAsTheFirmwareDoes()
    {
        CarveraEmulator emulator;
        QList<QByteArray> replies;
        connect(&emulator, &CarveraEmulator::lineSent, this, [&](const QByteArray &l) { replies.append(l); });
        // '?' in the middle of a line is real-time; '\r' ends a line; a line's own bytes are kept in order.
        emulator.receiveBytes("M493");
        emulator.receiveBytes("?.4\r");
        QTRY_COMPARE(replies.size(), 5);
        QVERIFY(replies.at(0).startsWith("<Idle|"));
        QVERIFY(parseTloReport(replies.at(1)).has_value());
        QCOMPARE(replies.last(), QByteArray("ok"));
    }

    void quotesAnUnknownCommandPrintably()
    {
        CarveraEmulator emulator;
        QList<QByteArray> replies;
        connect(&emulator, &CarveraEmulator::lineSent, this, [&](const QByteArray &l) { replies.append(l); });
        // A lower-case word is the firmware's shell's: refused by name, quoted printably and cut short.
        emulator.receiveBytes(QByteArray(QByteArray("q\xff\x01") + QByteArray(10000, 'z') + '\n'));
        QTRY_COMPARE(replies.size(), 1);
        QVERIFY(replies.front().startsWith("error:Unsupported command - q??z"));
        QVERIFY(replies.front().size() <= CarveraEmulator::kMaxLineBytes);
    }
};

QTEST_GUILESS_MAIN(TestPtyServer)
#include "tst_ptyserver.moc"
