// SPDX-License-Identifier: GPL-3.0-or-later
// The Carvera's real firmware (the community firmware in its simulator, ../shared/peers/carvera) as a test
// peer: started from the script TOFFEE_CARVERA_PEER names, with its SD card (config and EEPROM: the reference
// and the TLO) in a folder of the test's, stopped (SIGTERM to the script, which kills the simulator) when it
// goes. Without TOFFEE_CARVERA_PEER a test skips and says so: a bare clone still passes `make test`; .ci/run
// sets it from ../shared.
#pragma once

#include <csignal>

#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace Toffee::Test {

class CarveraPeer
{
    Q_DISABLE_COPY_MOVE(CarveraPeer)

public:
    // The script, or empty when the environment does not name one.
    static QString script() { return qEnvironmentVariable("TOFFEE_CARVERA_PEER"); }
    static QString skipReason()
    {
        return QStringLiteral("TOFFEE_CARVERA_PEER is not set (.ci/run sets it to ../shared/peers/carvera/"
                              "start): the tests against the Carvera's real firmware are skipped");
    }

    // `state`: the SD card's folder, kept between starts (a machine switched off and on); empty: a fresh
    // one of this peer's own. `protocol`: "smoothie" (plain text) or "makera" (framed).
    explicit CarveraPeer(QString state = {}, const QString &protocol = QStringLiteral("smoothie"))
        : m_state(state.isEmpty() ? m_ownState.path() : std::move(state))
    {
        if (script().isEmpty())
            return;
        m_process.setProgram(script());
        m_process.setArguments(
            { QStringLiteral("--state"), m_state, QStringLiteral("--protocol"), protocol });
        m_process.setProcessChannelMode(QProcess::SeparateChannels);
        m_process.start();
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < 15000 && (m_uart.isEmpty() || m_wifi.isEmpty())) {
            if (!m_process.waitForReadyRead(200) && m_process.state() != QProcess::Running)
                break;
            while (m_process.canReadLine()) {
                const QString line = QString::fromUtf8(m_process.readLine()).trimmed();
                if (line.startsWith(QStringLiteral("UART ")))
                    m_uart = line.mid(5).trimmed();
                else if (line.startsWith(QStringLiteral("WIFI ")))
                    m_wifi = line.mid(5).trimmed();
            }
        }
        // The firmware boots in about a second after its endpoints are up ("version = …", "ok" on the UART).
        if (started())
            QTest::qWait(1500);
    }
    ~CarveraPeer() { stop(); }

    [[nodiscard]] bool started() const
    {
        return !m_uart.isEmpty() && !m_wifi.isEmpty() && m_process.state() == QProcess::Running;
    }
    [[nodiscard]] QString uart() const { return m_uart; } // /dev/pts/N
    [[nodiscard]] QString wifi() const { return m_wifi; } // 127.0.0.1:PORT
    [[nodiscard]] QString state() const { return m_state; }
    [[nodiscard]] QString errors() { return QString::fromUtf8(m_process.readAllStandardError()); }

    void stop()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        ::kill(pid_t(m_process.processId()), SIGTERM); // never SIGKILL the script: the simulator would stay
        if (!m_process.waitForFinished(10000))
            m_process.kill();
        m_process.waitForFinished(2000);
    }

private:
    QTemporaryDir m_ownState;
    QString m_state;
    QProcess m_process;
    QString m_uart;
    QString m_wifi;
};

} // namespace Toffee::Test
