// SPDX-License-Identifier: GPL-3.0-or-later
// LinuxCNC itself (Debian's linuxcnc-uspace run headless, ../shared/peers/linuxcnc) as a test peer: started
// from the script TOFFEE_LINUXCNC_PEER names, its console (linuxcncrsh) on a free port of 127.0.0.1, with a
// tool setter the test writes (setter <Z>, T<n> <length>; a length changed while it runs with set-length),
// stopped by SIGTERM when it goes (never SIGKILL: LinuxCNC's own processes would be left). One LinuxCNC per
// computer: the tests that start it hold the ctest resource lock "linuxcnc". Without TOFFEE_LINUXCNC_PEER, or
// with LinuxCNC not installed, a test skips and says so: a bare clone still passes `make test`; .ci/run
// installs linuxcnc-uspace and sets the variable from ../shared.
#pragma once

#include <sys/prctl.h>

#include <csignal>
#include <map>
#include <optional>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QHostAddress>
#include <QProcess>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

namespace Toffee::Test {

class LinuxCncPeer
{
    Q_DISABLE_COPY_MOVE(LinuxCncPeer)

public:
    static QString script() { return qEnvironmentVariable("TOFFEE_LINUXCNC_PEER"); }
    // Why the tests against LinuxCNC skip here, or empty when they can run.
    static QString skipReason()
    {
        if (script().isEmpty())
            return QStringLiteral(
                "TOFFEE_LINUXCNC_PEER is not set (.ci/run sets it to ../shared/peers/linuxcnc/"
                "start): the tests against LinuxCNC itself are skipped");
        if (!QFileInfo::exists(QStringLiteral("/usr/bin/linuxcncrsh")))
            return QStringLiteral(
                "LinuxCNC is not installed (apt install linuxcnc-uspace; .ci/run does): the "
                "tests against LinuxCNC itself are skipped");
        return {};
    }
    static quint16 freePort()
    {
        QTcpServer server;
        if (!server.listen(QHostAddress::LocalHost, 0))
            return 0;
        return server.serverPort();
    }

    // Tool lengths (mm below the spindle nose, tools 1-15) on a setter at machine Z `setterZ`.
    explicit LinuxCncPeer(const std::map<int, double> &lengths, double setterZ = -100.0)
        : m_state(m_files.filePath(QStringLiteral("state")))
        , m_port(freePort())
    {
        if (!skipReason().isEmpty() || m_port == 0)
            return;
        QByteArray setter = "setter " + QByteArray::number(setterZ, 'f', 3) + '\n';
        for (const auto &[tool, length] : lengths)
            setter += 'T' + QByteArray::number(tool) + ' ' + QByteArray::number(length, 'f', 3) + '\n';
        QFile file(m_files.filePath(QStringLiteral("setter.txt")));
        if (!file.open(QIODevice::WriteOnly) || file.write(setter) != setter.size())
            return;
        file.close();
        m_process.setProgram(script());
        m_process.setArguments({ QStringLiteral("--state"), m_state, QStringLiteral("--port"),
            QString::number(m_port), QStringLiteral("--setter"), file.fileName() });
        m_process.setProcessChannelMode(QProcess::SeparateChannels);
        m_process.setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGTERM); });
        m_process.start();
        QElapsedTimer clock;
        clock.start();
        QByteArray said;
        while (clock.elapsed() < 60000 && m_process.state() != QProcess::NotRunning) {
            m_process.waitForReadyRead(200);
            said += m_process.readAllStandardOutput();
            for (const QByteArray &line : said.split('\n')) {
                if (line.startsWith("TOOL_TABLE "))
                    m_toolTable = QString::fromUtf8(line.mid(11).trimmed());
                if (line.startsWith("INI "))
                    m_ini = QString::fromUtf8(line.mid(4).trimmed());
            }
            if (said.contains("RSH ") && !m_ini.isEmpty() && !m_toolTable.isEmpty() && answers())
                break;
        }
        m_startupMs = clock.elapsed();
        m_ready = m_process.state() == QProcess::Running && answers();
    }
    ~LinuxCncPeer() { stop(); }

    [[nodiscard]] bool started() const { return m_ready && m_process.state() == QProcess::Running; }
    [[nodiscard]] quint16 port() const { return m_port; }
    [[nodiscard]] QString address() const { return QStringLiteral("127.0.0.1:%1").arg(m_port); }
    [[nodiscard]] QString ini() const { return m_ini; }
    [[nodiscard]] QString toolTable() const { return m_toolTable; }
    [[nodiscard]] qint64 startupMs() const { return m_startupMs; }
    [[nodiscard]] QString errors() { return QString::fromUtf8(m_process.readAllStandardError()); }

    // Lines sent as a client of its own (hello, verbose on, echo off, and with `enable` linuxcncrsh's enable,
    // which takes it from any other client, and set_wait done), each answered by one line (SET … ACK/NAK, or
    // a get's answer): the answers, in order.
    QList<QByteArray> ask(const QList<QByteArray> &lines, bool enable = true, int limitMs = 30000) const
    {
        QTcpSocket socket;
        socket.connectToHost(QHostAddress::LocalHost, m_port);
        if (!socket.waitForConnected(2000))
            return {};
        const QList<QByteArray> opening = enable
            ? QList<QByteArray> { "hello EMC test 1.0", "set verbose on", "set echo off", "set enable EMCTOO",
                  "set set_wait done" }
            : QList<QByteArray> { "hello EMC test 1.0", "set verbose on", "set echo off" };
        QList<QByteArray> answers;
        QByteArray buffer;
        QElapsedTimer clock;
        clock.start();
        for (const QByteArray &line : opening + lines) {
            socket.write(line + '\n');
            std::optional<QByteArray> answer;
            while (!answer && clock.elapsed() < limitMs) {
                if (socket.bytesAvailable() == 0 && !socket.waitForReadyRead(100))
                    continue;
                buffer += socket.readAll();
                buffer.replace('\r', '\n');
                qsizetype end = -1;
                while (!answer && (end = buffer.indexOf('\n')) >= 0) {
                    const QByteArray one = buffer.left(end).trimmed();
                    buffer.remove(0, end + 1);
                    // Echoes of what was sent come back while echo is on.
                    if (!one.isEmpty() && !one.startsWith("set ") && !one.startsWith("hello "))
                        answer = one;
                }
            }
            if (!answer)
                break;
            if (!opening.contains(line))
                answers << *answer;
        }
        socket.disconnectFromHost();
        return answers;
    }
    // One get's value ("TOOL 2" → "2"), asked without taking the enable.
    [[nodiscard]] QByteArray get(const QByteArray &what) const
    {
        const QList<QByteArray> answer = ask({ "get " + what }, false);
        const QByteArray line = answer.value(0);
        const qsizetype space = line.indexOf(' ');
        return space < 0 ? QByteArray() : line.mid(space + 1).trimmed();
    }
    // Out of estop, on, homed, in MDI: what an operator does at LinuxCNC's screen before Toffee measures.
    bool makeReady() const
    {
        ask({ "set estop off", "set machine on", "set mode manual", "set home -1" });
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < 20000 && !get("joint_homed").startsWith("YES YES YES"))
            QTest::qWait(200);
        const QList<QByteArray> mdi = ask({ "set mode mdi", "get mode" });
        return mdi.value(1) == "MODE MDI";
    }
    // Tool n's Z in LinuxCNC's tool.tbl on disk (nothing when the tool has no Z field: LinuxCNC drops zeros;
    // 0 then).
    [[nodiscard]] std::optional<double> tableZ(int tool) const
    {
        QFile file(m_toolTable);
        if (!file.open(QIODevice::ReadOnly))
            return std::nullopt;
        for (const QByteArray &raw : file.readAll().split('\n')) {
            const QList<QByteArray> words = raw.left(raw.indexOf(';')).simplified().split(' ');
            if (words.value(0) != 'T' + QByteArray::number(tool))
                continue;
            for (const QByteArray &w : words) {
                if (w.startsWith('Z'))
                    return w.mid(1).toDouble();
            }
            return 0.0;
        }
        return std::nullopt;
    }
    [[nodiscard]] QByteArray tableFile() const
    {
        QFile file(m_toolTable);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    }
    // Tool n's physical length on the setter changed while LinuxCNC runs (a worn or broken tool).
    bool setLength(int tool, double length) const
    {
        QProcess p;
        p.start(QFileInfo(script()).absoluteDir().filePath(QStringLiteral("set-length")),
            { m_state, QString::number(tool), QString::number(length, 'f', 3) });
        return p.waitForFinished(10000) && p.exitCode() == 0;
    }

    void stop()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        ::kill(pid_t(m_process.processId()), SIGTERM);
        if (!m_process.waitForFinished(20000)) {
            ::kill(pid_t(m_process.processId()), SIGINT);
            m_process.waitForFinished(10000);
        }
    }

private:
    // linuxcncrsh answers a hello once LinuxCNC has started.
    [[nodiscard]] bool answers() const
    {
        QTcpSocket socket;
        socket.connectToHost(QHostAddress::LocalHost, m_port);
        if (!socket.waitForConnected(200))
            return false;
        socket.write("hello EMC test 1.0\n");
        QByteArray heard;
        while (!heard.contains('\n') && socket.waitForReadyRead(1000))
            heard += socket.readAll();
        socket.disconnectFromHost();
        return heard.startsWith("HELLO ACK");
    }

    QTemporaryDir m_files;
    QString m_state;
    quint16 m_port = 0;
    QProcess m_process;
    QString m_toolTable;
    QString m_ini;
    qint64 m_startupMs = 0;
    bool m_ready = false;
};

} // namespace Toffee::Test
