// SPDX-License-Identifier: GPL-3.0-or-later
// grblHAL itself (the real controller firmware built to run here, ../shared/peers/grblhal) as a test peer:
// started from the script TOFFEE_GRBLHAL_PEER names, on raw TCP ("telnet") at a free port of 127.0.0.1, with
// a tool setter the test writes (setter <Z> and T<n> <length> lines, read again at every probe) and its
// EEPROM in a state folder (kept between starts when the test passes one: a controller switched off and on),
// stopped by SIGTERM when it goes. Without TOFFEE_GRBLHAL_PEER a test skips and says so: a bare clone still
// passes `make test`; .ci/run sets it from ../shared.
#pragma once

#include <sys/prctl.h>

#include <csignal>
#include <functional>
#include <map>
#include <optional>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QHostAddress>
#include <QProcess>
#include <QSet>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

namespace Toffee::Test {

class GrblHalPeer
{
    Q_DISABLE_COPY_MOVE(GrblHalPeer)

public:
    // The script, or empty when the environment does not name one.
    static QString script() { return qEnvironmentVariable("TOFFEE_GRBLHAL_PEER"); }
    static QString skipReason()
    {
        return QStringLiteral("TOFFEE_GRBLHAL_PEER is not set (.ci/run sets it to ../shared/peers/grblhal/"
                              "start): the tests against grblHAL itself are skipped");
    }

    // A port nobody listens on now: bound, read and let go (another program may take it in between; rare).
    static quint16 freePort()
    {
        QTcpServer server;
        if (!server.listen(QHostAddress::LocalHost, 0))
            return 0;
        return server.serverPort();
    }

    // How the controller is reached: raw TCP on 127.0.0.1, or a pseudo-terminal as its USB serial port
    // (through socat, which `make test` installs).
    enum class Link { Tcp, Pty };

    // `state`: the folder of the controller's EEPROM (settings and tool table), kept between starts; empty: a
    // fresh one of this peer's own. The setter file starts empty (no setter: a probe touches nothing) until
    // writeSetter().
    explicit GrblHalPeer(QString state = {}, Link link = Link::Tcp)
        : m_state(state.isEmpty() ? m_ownState.path() : std::move(state))
        , m_setter(m_files.filePath(QStringLiteral("setter.txt")))
        , m_pty(m_files.filePath(QStringLiteral("tty")))
        , m_port(link == Link::Tcp ? freePort() : 0)
        , m_link(link)
    {
        if (script().isEmpty() || (link == Link::Tcp && m_port == 0) || !writeSetterFile({}))
            return;
        // A free port is only free when it was looked at: another test's server may take it before grblHAL
        // binds it (then something else answers there). A port answered by anything but grblHAL is given up
        // for another.
        for (int attempt = 0; attempt < 3 && !m_ready; ++attempt) {
            if (attempt > 0) {
                stop();
                m_port = freePort();
            }
            m_process.setProgram(script());
            const QStringList where = link == Link::Tcp
                ? QStringList { QStringLiteral("--tcp"), QString::number(m_port) }
                : QStringList { QStringLiteral("--pty"), m_pty };
            m_process.setArguments(where
                + QStringList { QStringLiteral("--setter"), m_setter, QStringLiteral("--state"), m_state });
            m_process.setProcessChannelMode(QProcess::SeparateChannels);
            // grblHAL goes with the test, even one ended by its time limit before its destructors ran (the
            // start script execs the simulator, which keeps the signal asked for here).
            m_process.setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGTERM); });
            m_process.start();
            m_ready = m_process.waitForStarted(5000)
                && (link == Link::Tcp ? waitUntilAnswering(10000) : waitForPty(10000));
        }
    }
    ~GrblHalPeer() { stop(); }

    // Running and answering a status query on its port.
    [[nodiscard]] bool started() const { return m_ready && m_process.state() == QProcess::Running; }
    [[nodiscard]] quint16 port() const { return m_port; }
    // The pseudo-terminal's path (Link::Pty).
    [[nodiscard]] QString pty() const { return m_pty; }
    // What toffee-cli is given to reach it.
    [[nodiscard]] QStringList cliTarget() const
    {
        return m_link == Link::Tcp
            ? QStringList { QStringLiteral("--host"), QStringLiteral("127.0.0.1:%1").arg(m_port) }
            : QStringList { QStringLiteral("--port"), m_pty };
    }

    // One line sent as a client of its own (TCP only, while no other client is connected), and every line
    // it answered up to "ok" or "error:": how a test reads grblHAL's own table ($#) itself.
    [[nodiscard]] QList<QByteArray> ask(const QByteArray &line, int limitMs = 5000) const
    {
        QList<QByteArray> lines;
        exchange(line + '\n', limitMs, [&lines](QByteArray &buffer) {
            qsizetype end = -1;
            while ((end = buffer.indexOf('\n')) >= 0) {
                const QByteArray one = buffer.left(end).trimmed();
                buffer.remove(0, end + 1);
                if (one.isEmpty() || one.startsWith('<'))
                    continue;
                lines.append(one);
                if (one == "ok" || one.startsWith("error:"))
                    return true;
            }
            return false;
        });
        return lines;
    }
    // The status report grblHAL answers to '?' ("<Idle|MPos:…>"), as a client of its own, or nothing.
    [[nodiscard]] QByteArray status(int limitMs = 3000) const
    {
        QByteArray report;
        exchange("?", limitMs, [&report](QByteArray &buffer) {
            const qsizetype start = buffer.indexOf('<');
            const qsizetype end = buffer.indexOf('>', start);
            if (start < 0 || end <= start)
                return false;
            report = buffer.mid(start, end - start + 1);
            return true;
        });
        return report;
    }
    // Tool n's Z offset in grblHAL's own table, as $# reports it ("[T:n|x,y,z|…"), or nothing.
    [[nodiscard]] std::optional<double> tableZ(int tool) const
    {
        const QByteArray prefix = "[T:" + QByteArray::number(tool) + '|';
        for (const QByteArray &line : ask("$#")) {
            if (!line.startsWith(prefix))
                continue;
            const QList<QByteArray> fields = line.split('|');
            const QList<QByteArray> axes = fields.value(1).split(',');
            bool ok = false;
            const double z = axes.value(2).toDouble(&ok);
            if (ok)
                return z;
        }
        return std::nullopt;
    }
    [[nodiscard]] QString state() const { return m_state; }
    [[nodiscard]] QString setterPath() const { return m_setter; }
    [[nodiscard]] qint64 startupMs() const { return m_startupMs; }
    [[nodiscard]] QString errors() { return QString::fromUtf8(m_process.readAllStandardError()); }

    // The setter at machine Z `setterZ` (where a tool of length 0 touches it) and each tool's length below
    // the spindle nose. Rewrite it between probes to model a worn or broken tool.
    bool writeSetter(double setterZ, const std::map<int, double> &toolLengths)
    {
        QByteArray text = "setter " + QByteArray::number(setterZ, 'f', 3) + '\n';
        for (const auto &[tool, length] : toolLengths)
            text += 'T' + QByteArray::number(tool) + ' ' + QByteArray::number(length, 'f', 3) + '\n';
        return writeSetterFile(text);
    }

    // The setter file as written ("T3 20 20.03 20.06": one length per cutting edge, taken in turn).
    bool writeSetterText(const QByteArray &text) { return writeSetterFile(text); }

    void stop()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        // The script execs grblHAL: SIGTERM closes its EEPROM and ends it (about a second here).
        ::kill(pid_t(m_process.processId()), SIGTERM);
        if (!m_process.waitForFinished(10000))
            m_process.kill();
        m_process.waitForFinished(2000);
    }

private:
    // `bytes` sent as a client of its own, then what comes read into a buffer `done` takes from, until it
    // says it has what it wanted or `limitMs` pass. It reads until done: grblHAL's simulator exits when it
    // writes to a client that has gone.
    void exchange(const QByteArray &bytes, int limitMs, const std::function<bool(QByteArray &)> &done) const
    {
        QTcpSocket socket;
        socket.connectToHost(QHostAddress::LocalHost, m_port);
        if (!socket.waitForConnected(2000))
            return;
        socket.write(bytes);
        QByteArray buffer;
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < limitMs) {
            if (socket.bytesAvailable() == 0 && !socket.waitForReadyRead(100))
                continue;
            buffer += socket.readAll();
            if (done(buffer))
                return;
        }
    }

    bool writeSetterFile(const QByteArray &text)
    {
        QFile file(m_setter);
        return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(text) == text.size();
    }

    // The port accepts before grblHAL has booted (about a second): ready once a status query is answered.
    bool waitUntilAnswering(int limitMs)
    {
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < limitMs && m_process.state() == QProcess::Running) {
            QTcpSocket socket;
            socket.connectToHost(QHostAddress::LocalHost, m_port);
            if (!socket.waitForConnected(200)) {
                QTest::qSleep(50);
                continue;
            }
            QByteArray heard;
            while (clock.elapsed() < limitMs && socket.state() == QAbstractSocket::ConnectedState) {
                socket.write("?");
                if (socket.waitForReadyRead(100))
                    heard += socket.readAll();
                if (heard.contains("<") && heard.indexOf('>', heard.indexOf('<')) >= 0) {
                    m_startupMs = clock.elapsed();
                    // Read what is still coming and close only then: the simulator exits when a write to its
                    // client fails (grblHAL_sim's simulator.c, exit(-10)), and a report to a '?' sent just
                    // before the close was such a write; the next client was then refused.
                    while (socket.waitForReadyRead(150))
                        socket.readAll();
                    socket.disconnectFromHost();
                    if (socket.state() != QAbstractSocket::UnconnectedState)
                        socket.waitForDisconnected(500);
                    // grblHAL's report has its buffer field (a Carvera's, another test's, has none), and the
                    // port must be this grblHAL's: another test's grblHAL may hold it, and this one fail to
                    // bind.
                    return heard.contains("|Bf:") && m_process.state() == QProcess::Running && ownsPort();
                }
            }
        }
        return false;
    }

    // Whether the port's listening socket (/proc/net/tcp, state 0A) is one of this process's open files (the
    // script execs grblHAL: the same process).
    bool ownsPort() const
    {
        QSet<QByteArray> inodes;
        for (const char *table : { "/proc/net/tcp", "/proc/net/tcp6" }) {
            QFile file(QString::fromLatin1(table));
            if (!file.open(QIODevice::ReadOnly))
                continue;
            const QList<QByteArray> lines = file.readAll().split('\n');
            for (const QByteArray &line : lines) {
                const QList<QByteArray> f = line.simplified().split(' ');
                if (f.size() < 10 || f.at(3) != "0A")
                    continue;
                bool ok = false;
                if (f.at(1).mid(f.at(1).indexOf(':') + 1).toUInt(&ok, 16) == m_port && ok)
                    inodes.insert("socket:[" + f.at(9) + ']');
            }
        }
        const QDir fds(QStringLiteral("/proc/%1/fd").arg(m_process.processId()));
        const QStringList entries = fds.entryList(QDir::NoDotAndDotDot | QDir::AllEntries | QDir::System);
        for (const QString &fd : entries) {
            if (inodes.contains(QFile::symLinkTarget(fds.filePath(fd)).section(u'/', -1).toLatin1()))
                return true;
        }
        return false;
    }

    // socat makes the link once grblHAL runs; grblHAL is booted about a second later. Opening the terminal to
    // ask would leave its greeting unread by the test's client, so it waits.
    bool waitForPty(int limitMs)
    {
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < limitMs && m_process.state() == QProcess::Running) {
            if (QFileInfo::exists(m_pty)) {
                QTest::qSleep(1500);
                m_startupMs = clock.elapsed();
                return m_process.state() == QProcess::Running;
            }
            QTest::qSleep(50);
        }
        return false;
    }

    QTemporaryDir m_ownState;
    QTemporaryDir m_files;
    QString m_state;
    QString m_setter;
    QString m_pty;
    quint16 m_port = 0;
    Link m_link = Link::Tcp;
    QProcess m_process;
    bool m_ready = false;
    qint64 m_startupMs = 0;
};

} // namespace Toffee::Test
