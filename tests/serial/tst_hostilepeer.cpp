// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli against a machine that misbehaves. The test opens a real pseudo-terminal and plays the machine
// on its master side; the real toffee-cli runs as a child process on the slave. Every run has a hard time
// limit (killed and failed beyond it), and its peak memory is read from the kernel (/proc/PID/status VmHWM,
// polled while it runs).
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <poll.h>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryFile>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {

// The bound on toffee-cli's peak memory, in either build. Under AddressSanitizer the sanitizer's quarantine
// of freed memory (256 MB by default) is made small for the child, so that what is measured is the program.
constexpr long kPeakBoundKb = 100 * 1024;
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kUnderAsan = true;
#else
constexpr bool kUnderAsan = false;
#endif

// The machine, played by the test: the Carvera's strings (docs/CARVERA.md), with a misbehaviour or two.
class PtyMachine
{
public:
    QByteArray state = "Idle"; // what "?" reports
    QByteArray lineEnd = "\r\n";
    QByteArray tloReport = "current tool offset [-105.688] , reference tool offset [-72.300]";
    QByteArray offsetsReply; // instead of the M493.4 report, when set
    qint64 floodLines = 0; // unknown lines sent while M491 runs
    bool answerAfterFlood = true; // false: after the flood the machine says nothing more
    int chunk = 0; // at most this many bytes per write, with a short pause after each (0: as they come)
    bool neverRead = false;

    PtyMachine()
    {
        m_master = posix_openpt(O_RDWR | O_NOCTTY);
        if (m_master < 0 || grantpt(m_master) != 0 || unlockpt(m_master) != 0)
            return;
        m_device = QString::fromLocal8Bit(ptsname(m_master));
        // Held open, raw, so that nothing is echoed and the master never reads EIO between clients.
        m_slave = ::open(ptsname(m_master), O_RDWR | O_NOCTTY | O_NONBLOCK);
        termios raw {};
        if (m_slave >= 0 && tcgetattr(m_slave, &raw) == 0) {
            cfmakeraw(&raw);
            tcsetattr(m_slave, TCSANOW, &raw);
        }
        ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
    }
    ~PtyMachine()
    {
        if (m_slave >= 0)
            ::close(m_slave);
        if (m_master >= 0)
            ::close(m_master);
    }
    [[nodiscard]] QString device() const { return m_device; }
    [[nodiscard]] qint64 flooded() const { return m_flooded; }
    [[nodiscard]] QList<QByteArray> received() const { return m_received; }

    // Fills the direction from the client to the machine, which this machine never reads.
    qsizetype fillClientOutput()
    {
        const QByteArray junk(4096, 'x');
        qsizetype total = 0;
        while (true) {
            const ssize_t n = ::write(m_slave, junk.constData(), size_t(junk.size()));
            if (n <= 0)
                return total;
            total += n;
        }
    }

    // Reads what came, answers it, writes what is due; waits at most `ms` for something to happen.
    void step(int ms)
    {
        refill();
        pollfd fd { m_master, short((neverRead ? 0 : POLLIN) | (pending() ? POLLOUT : 0)), 0 };
        if (::poll(&fd, 1, ms) <= 0)
            return;
        if (fd.revents & POLLIN)
            readInput();
        if (fd.revents & POLLOUT)
            writeOutput();
    }

private:
    [[nodiscard]] bool pending() const { return m_outPos < m_out.size(); }

    void say(const QByteArray &line) { m_out += line + lineEnd; }

    QByteArray status() const
    {
        return '<' + state
            + "|MPos:-88.0000,-9.0000,-10.0000,0.0000,0.0000|WPos:-88.0000,-9.0000,49.0000,0.0000,0.0000"
              "|T:2,-33.388,-1,0>";
    }

    void readInput()
    {
        char buffer[4096];
        const ssize_t n = ::read(m_master, buffer, sizeof buffer);
        for (ssize_t i = 0; i < n; ++i) {
            const char c = buffer[i];
            if (c == '?') {
                if (!m_silent)
                    say(status());
            } else if (c == '\n' || c == '\r') {
                answer(std::exchange(m_line, {}));
            } else {
                m_line += c;
            }
        }
    }

    void answer(const QByteArray &line)
    {
        m_received.append(line);
        if (m_silent)
            return;
        if (line.isEmpty() || line == ";") {
            say("ok");
        } else if (line == "version") {
            say("version = 2.1.0c-hostile"); // a Carvera's shell: no "ok"
        } else if (line == "M493.4") {
            if (!offsetsReply.isEmpty()) {
                say(offsetsReply);
                return;
            }
            say(tloReport);
            say("no one-off tool setter position offsets configured");
            say("ok");
        } else if (line == "M491") {
            m_flooding = floodLines > 0;
            if (!m_flooding)
                endProbe();
        } else {
            say("error:Unsupported command - " + line);
        }
    }

    void endProbe()
    {
        if (!answerAfterFlood) {
            m_silent = true;
            return;
        }
        say("[PRB:-88.000,-9.000,-105.688:1]");
        say("M493.1");
        say("Done ATC");
        say("ok");
    }

    // Keeps about 64 KB of the flood queued, never the whole of it.
    void refill()
    {
        if (!m_flooding || m_out.size() - m_outPos > 65536)
            return;
        m_out.remove(0, m_outPos);
        m_outPos = 0;
        for (int i = 0; i < 4096 && m_flooded < floodLines; ++i, ++m_flooded)
            say("unknown line " + QByteArray::number(m_flooded));
        if (m_flooded == floodLines) {
            m_flooding = false;
            endProbe();
        }
    }

    void writeOutput()
    {
        const qsizetype size
            = chunk > 0 ? std::min<qsizetype>(chunk, m_out.size() - m_outPos) : m_out.size() - m_outPos;
        const ssize_t n = ::write(m_master, m_out.constData() + m_outPos, size_t(size));
        if (n > 0)
            m_outPos += n;
        if (!pending()) {
            m_out.clear();
            m_outPos = 0;
        }
        if (chunk > 0)
            ::usleep(300); // so that each piece arrives on its own
    }

    int m_master = -1;
    int m_slave = -1;
    QString m_device;
    QByteArray m_line;
    QByteArray m_out;
    qsizetype m_outPos = 0;
    bool m_flooding = false;
    bool m_silent = false;
    qint64 m_flooded = 0;
    QList<QByteArray> m_received;
};

struct CliRun
{
    int exitCode = -1; // -1: killed, or ended by a signal
    bool overran = false; // killed at the test's limit
    qint64 elapsedMs = 0;
    qint64 peakRssKb = 0;
    QByteArray out;
    QByteArray err;
};

// Runs toffee-cli with `arguments` against `machine`, which is served until the CLI ends or `limitMs`
// passes.
CliRun runCli(const QStringList &arguments, PtyMachine &machine, int limitMs)
{
    CliRun run;
    QTemporaryFile out;
    QTemporaryFile err;
    if (!out.open() || !err.open()) {
        run.err = "TEST: no temporary files";
        return run;
    }
    const QByteArray program = TOFFEE_BIN_DIR "/toffee-cli";
    QList<QByteArray> args { program };
    for (const QString &a : arguments)
        args << a.toLocal8Bit();
    std::vector<char *> argv;
    for (QByteArray &a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);

    QElapsedTimer clock;
    clock.start();
    const pid_t pid = ::fork();
    if (pid == 0) {
        if (kUnderAsan) {
            const char *given = std::getenv("ASAN_OPTIONS");
            const std::string options = std::string(given ? given : "") + ":quarantine_size_mb=1";
            ::setenv("ASAN_OPTIONS", options.c_str(), 1);
        }
        ::dup2(out.handle(), STDOUT_FILENO);
        ::dup2(err.handle(), STDERR_FILENO);
        ::execv(program.constData(), argv.data());
        ::_exit(127);
    }
    if (pid < 0) {
        run.err = "TEST: fork failed";
        return run;
    }
    int status = 0;
    rusage usage {};
    // The peak is read from /proc/PID/status (VmHWM) while the program runs, once it is the program: wait4's
    // ru_maxrss would also count the copy of this test process that fork() made before exec().
    const QByteArray proc = "/proc/" + QByteArray::number(pid);
    const QByteArray exe = QFileInfo(QString::fromLocal8Bit(program)).canonicalFilePath().toLocal8Bit();
    QElapsedTimer sincePoll;
    sincePoll.start();
    long peakKb = 0;
    while (true) {
        machine.step(2);
        if (sincePoll.elapsed() >= 5) {
            sincePoll.restart();
            char target[4096];
            const ssize_t n = ::readlink(QByteArray(proc + "/exe").constData(), target, sizeof target - 1);
            if (n > 0 && QByteArray(target, n) == exe) {
                QFile statusFile(QString::fromLatin1(QByteArray(proc + "/status")));
                if (statusFile.open(QIODevice::ReadOnly)) {
                    for (const QByteArray &line : statusFile.readAll().split('\n')) {
                        if (line.startsWith("VmHWM:"))
                            peakKb = std::max(peakKb, line.mid(6).trimmed().split(' ').value(0).toLong());
                    }
                }
            }
        }
        const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
        if (done == pid)
            break;
        if (clock.elapsed() > limitMs) {
            ::kill(pid, SIGKILL);
            ::wait4(pid, &status, 0, &usage);
            run.overran = true;
            break;
        }
    }
    run.elapsedMs = clock.elapsed();
    run.peakRssKb = peakKb;
    run.exitCode = !run.overran && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    out.seek(0);
    err.seek(0);
    run.out = out.readAll();
    run.err = err.readAll();
    return run;
}

QString describe(const CliRun &run)
{
    return u"exit %1 after %2 ms%3, peak %4 MB\nstdout: %5\nstderr: %6"_s.arg(run.exitCode)
        .arg(run.elapsedMs)
        .arg(run.overran ? u" (killed at the test's limit)"_s : QString())
        .arg(run.peakRssKb / 1024)
        .arg(QString::fromUtf8(run.out.left(2000)), QString::fromUtf8(run.err.left(2000)));
}

} // namespace

class TestHostilePeer : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QVERIFY(QFile::exists(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"))); }

    void aWellBehavedMachineAnswers()
    {
        PtyMachine machine;
        QVERIFY(!machine.device().isEmpty());
        const CliRun run = runCli({ u"--port"_s, machine.device(), u"report"_s }, machine, 20000);
        QVERIFY2(run.exitCode == 0, qPrintable(describe(run)));
        QVERIFY2(run.out.contains("T2: TLO -33.388 mm"), qPrintable(describe(run)));
    }

    // Millions of lines nobody asked for while a probe runs, then silence: the CLI keeps a bounded tail,
    // gives up at its limit and says so.
    void aFloodDuringAProbeKeepsMemoryBounded()
    {
        PtyMachine machine;
        machine.floodLines = 3'000'000;
        machine.answerAfterFlood = false;
        const CliRun run
            = runCli({ u"--port"_s, machine.device(), u"--timeout"_s, u"15"_s, u"probe"_s }, machine, 60000);
        qInfo("flood of %lld lines: %s", machine.flooded(), qPrintable(describe(run)));
        QVERIFY2(!run.overran, qPrintable(describe(run)));
        QCOMPARE(machine.flooded(), machine.floodLines); // the CLI read all of it
        QVERIFY2(run.peakRssKb > 0 && run.peakRssKb < kPeakBoundKb, qPrintable(describe(run)));
        QVERIFY2(run.exitCode == 5, qPrintable(describe(run)));
        QVERIFY2(run.elapsedMs < 20000, qPrintable(describe(run))); // its 15 s, and a little
        QVERIFY2(run.err.contains("did not answer \"M491\" within 15.0 s"), qPrintable(describe(run)));
        QVERIFY2(run.err.contains("3000000 lines"), qPrintable(describe(run)));
    }

    // The same flood, then the probe's own ending: the result comes after the flood and is still read.
    void aFloodThenTheProbeResultStillMeasures()
    {
        PtyMachine machine;
        machine.floodLines = 500'000;
        const CliRun run = runCli({ u"--port"_s, machine.device(), u"probe"_s }, machine, 60000);
        qInfo("%s", qPrintable(describe(run)));
        QVERIFY2(run.exitCode == 0, qPrintable(describe(run)));
        QVERIFY2(run.out.contains("T2: TLO -33.388 mm"), qPrintable(describe(run)));
        QVERIFY2(run.peakRssKb > 0 && run.peakRssKb < kPeakBoundKb, qPrintable(describe(run)));
    }

    void repliesSplitAnywhereReadTheSame_data()
    {
        QTest::addColumn<int>("chunk");
        QTest::addColumn<QByteArray>("lineEnd");
        QTest::newRow("one byte at a time, CR LF") << 1 << QByteArray("\r\n");
        QTest::newRow("one byte at a time, LF") << 1 << QByteArray("\n");
        QTest::newRow("two bytes, CR") << 2 << QByteArray("\r");
        QTest::newRow("three bytes, CR LF") << 3 << QByteArray("\r\n");
        QTest::newRow("seven bytes, LF") << 7 << QByteArray("\n");
    }
    void repliesSplitAnywhereReadTheSame()
    {
        QFETCH(int, chunk);
        QFETCH(QByteArray, lineEnd);
        PtyMachine machine;
        machine.chunk = chunk;
        machine.lineEnd = lineEnd;
        const CliRun run = runCli({ u"--port"_s, machine.device(), u"report"_s }, machine, 30000);
        QVERIFY2(run.exitCode == 0, qPrintable(describe(run)));
        QVERIFY2(
            run.out.contains("T2: TLO -33.388 mm (current tool MCS Z -105.688, reference MCS Z -72.300)"),
            qPrintable(describe(run)));
    }

    // The machine never reads what it is sent, and the way to it is full: the CLI gives up at its limit.
    void aMachineThatNeverReadsEndsAtTheTimeout()
    {
        PtyMachine machine;
        machine.neverRead = true;
        QVERIFY(machine.fillClientOutput() > 0);
        const CliRun run
            = runCli({ u"--port"_s, machine.device(), u"--timeout"_s, u"2"_s, u"status"_s }, machine, 20000);
        qInfo("%s", qPrintable(describe(run)));
        QVERIFY2(!run.overran, qPrintable(describe(run)));
        QVERIFY2(run.exitCode == 5, qPrintable(describe(run)));
        QVERIFY2(run.elapsedMs >= 2000 && run.elapsedMs < 5000, qPrintable(describe(run)));
        QVERIFY2(!run.err.isEmpty(), qPrintable(describe(run)));
    }

    void aMachineThatStaysInRunEndsAtTheTimeout()
    {
        PtyMachine machine;
        machine.state = "Run";
        const CliRun run
            = runCli({ u"--port"_s, machine.device(), u"--timeout"_s, u"2"_s, u"status"_s }, machine, 30000);
        qInfo("%s", qPrintable(describe(run)));
        QVERIFY2(!run.overran, qPrintable(describe(run)));
        QVERIFY2(run.exitCode == 5, qPrintable(describe(run)));
        QVERIFY2(run.elapsedMs >= 2000 && run.elapsedMs < 6000, qPrintable(describe(run)));
        QVERIFY2(run.err.contains("stayed busy (Run)"), qPrintable(describe(run)));
    }

    // 100 KB of "error:...": a refusal, cut short, not silence.
    void anOverlongRefusalIsStillARefusal()
    {
        PtyMachine machine;
        machine.offsetsReply = "error:" + QByteArray(100 * 1024, 'e');
        const CliRun run
            = runCli({ u"--port"_s, machine.device(), u"--timeout"_s, u"3"_s, u"report"_s }, machine, 20000);
        qInfo("%s", qPrintable(describe(run)));
        QVERIFY2(run.exitCode == 4, qPrintable(describe(run)));
        QVERIFY2(run.err.contains("refused \"M493.4\""), qPrintable(describe(run)));
        QVERIFY2(run.err.size() < 2000, qPrintable(describe(run))); // an excerpt, not 100 KB
    }

    void anImpossibleOffsetReportIsAMachineError()
    {
        PtyMachine machine;
        machine.tloReport = "current tool offset [1e308] , reference tool offset [-1e308]";
        const CliRun run = runCli({ u"--port"_s, machine.device(), u"report"_s }, machine, 20000);
        qInfo("%s", qPrintable(describe(run)));
        QVERIFY2(run.exitCode == 4, qPrintable(describe(run)));
        QVERIFY2(!run.out.contains("inf"), qPrintable(describe(run)));
        QVERIFY2(run.err.contains("no machine can have"), qPrintable(describe(run)));
    }
};

QTEST_GUILESS_MAIN(TestHostilePeer)
#include "tst_hostilepeer.moc"
