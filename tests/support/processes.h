// SPDX-License-Identifier: GPL-3.0-or-later
// Running toffee-cli and toffee-emulator as a user or a script runs them.
#pragma once

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTest>

#include "tests/support/terminal.h"

namespace Toffee::Test {

struct Run
{
    int exitCode = -1;
    QByteArray out;
    QByteArray err;
};

// toffee-cli run as a script runs it (its input a pipe: nobody counts as at the machine), or with
// `atTerminal` as an operator types it at the machine (its input a terminal nobody types on).
inline Run cli(const QStringList &arguments, int timeoutMs = 60000, bool atTerminal = false)
{
    QProcess process;
    Terminal terminal;
    if (atTerminal)
        terminal.attach(process);
    process.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"), arguments);
    Run run;
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished();
        run.err = "TEST: toffee-cli did not finish";
        return run;
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

// toffee-cli run with its output thrown away (`keepOutput` false) or kept, and its peak resident memory read
// from the kernel while it runs (/proc/PID/status, VmHWM: the largest it has been, so polling misses nothing
// but the last few milliseconds before it exits).
struct MeasuredRun : Run
{
    long peakKb = 0;
};

inline MeasuredRun cliWithPeak(const QStringList &arguments, bool keepOutput = true, int timeoutMs = 300000)
{
    QProcess process;
    if (!keepOutput)
        process.setStandardOutputFile(QProcess::nullDevice());
    process.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"), arguments);
    MeasuredRun run;
    if (!process.waitForStarted()) {
        run.err = "TEST: toffee-cli did not start";
        return run;
    }
    QFile status(QStringLiteral("/proc/%1/status").arg(process.processId()));
    // Until exec() the child is a copy of this test: its memory is not toffee-cli's.
    const QString exe = QStringLiteral("/proc/%1/exe").arg(process.processId());
    const QString program = QFileInfo(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli")).canonicalFilePath();
    QElapsedTimer clock;
    clock.start();
    while (!process.waitForFinished(2)) {
        if (clock.elapsed() > timeoutMs) {
            process.kill();
            process.waitForFinished();
            run.err = "TEST: toffee-cli did not finish";
            return run;
        }
        if (QFileInfo(exe).symLinkTarget() == program && status.open(QIODevice::ReadOnly)) {
            for (const QByteArray &line : status.readAll().split('\n')) {
                if (line.startsWith("VmHWM:"))
                    run.peakKb = std::max(run.peakKb, line.mid(6).trimmed().split(' ').value(0).toLong());
            }
            status.close();
        }
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    if (keepOutput)
        run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

// toffee-emulator serving on a pseudo-terminal, with a link at `link`; stopped when destroyed.
class Emulator
{
public:
    Emulator(const QString &link, QStringList arguments)
    {
        arguments << QStringLiteral("--link") << link;
        if (!arguments.contains(QStringLiteral("--probe-ms")))
            arguments << QStringLiteral("--probe-ms") << QStringLiteral("0");
        if (!arguments.contains(QStringLiteral("--change-ms")))
            arguments << QStringLiteral("--change-ms") << QStringLiteral("0");
        m_process.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-emulator"), arguments);
        const bool listens = arguments.contains(QStringLiteral("--listen"));
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < 10000 && (m_device.isEmpty() || (listens && m_tcp.isEmpty()))) {
            if (!m_process.canReadLine() && !m_process.waitForReadyRead(200))
                continue;
            while (m_process.canReadLine()) {
                const QString line = QString::fromUtf8(m_process.readLine()).trimmed();
                if (line.startsWith(QStringLiteral("tcp ")))
                    m_tcp = line.mid(4);
                else if (m_device.isEmpty())
                    m_device = line;
            }
        }
    }
    ~Emulator()
    {
        m_process.terminate();
        if (!m_process.waitForFinished(3000))
            m_process.kill();
    }
    [[nodiscard]] bool started() const { return m_device.startsWith(QStringLiteral("/dev/")); }
    [[nodiscard]] QString device() const { return m_device; }
    // With --listen: "127.0.0.1:PORT".
    [[nodiscard]] QString tcp() const { return m_tcp; }
    QProcess &process() { return m_process; }

private:
    QProcess m_process;
    QString m_device;
    QString m_tcp;
};

inline QByteArray readFile(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace Toffee::Test
