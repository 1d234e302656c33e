// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// toffee-cli's machine commands: one connection, one operation, one result (MachineRun), in three files:
// machinecommands.cpp (connecting, the operation, its printing), machinerunrecording.cpp (the table and the
// history), machinerunoffsets.cpp (push, pull and restore).

#include <array>
#include <functional>
#include <optional>

#include <QElapsedTimer>
#include <QEventLoop>
#include <QJsonArray>
#include <QTimer>

#include "app/cli/cli.h"
#include "app/cli/machineoptions.h"
#include "model/recording.h"
#include "serial/machine/machinelink.h"
#include "serial/machineconnection.h"

namespace Toffee {
struct HistoryEvent;
}

namespace Toffee::Cli::Machine {

// What the machine commands share: the exit code of an outcome, a length as printed, and the printers.
[[nodiscard]] ExitCode exitCodeFor(SessionResult::Outcome outcome);
[[nodiscard]] QString mm(double v);
[[nodiscard]] QJsonArray axes(const std::array<double, 3> &a);
void printTlo(
    Invocation &call, const SessionResult &r, const QString &trendWarning = {}, const QString &history = {});
void printStatus(
    Invocation &call, const MachineStatus &s, const MachineConnection &connection, const QString &machine);
void printBreakTest(Invocation &call, const SessionResult &r);
void printSelected(Invocation &call, const SessionResult &r);
void printLinkTimes(Invocation &call, QList<double> times, const QString &link);

// One machine command: one connection, one named operation of it, one result and its exit code.
class MachineRun
{
public:
    MachineRun(Invocation &call, MachineOptions options)
        : m_call(call)
        , m_options(std::move(options))
    { }

    int exec()
    {
        QObject::connect(&m_connection, &MachineConnection::connectFailed, &m_loop,
            [this] { finishWith(m_connection.connectResult()); });
        m_connection.setPreparer([this](const MachineIdentity &identity, ConnectionTarget &target) {
            if (auto prepared = prepareForController(m_call, m_options, identity); !prepared)
                return prepared.error().message;
            target.setter = m_options.target.setter;
            target.reference = m_options.target.reference;
            return QString();
        });
        m_connection.setProbePlans([this](int tool) { return m_options.probePlan(tool); });
        QObject::connect(
            &m_connection, &MachineConnection::stateChanged, &m_loop, [this](MachineConnection::State state) {
                if (state == MachineConnection::State::Connected && !std::exchange(m_started, true))
                    operate();
            });
        // Started from inside the loop, so that a failure reported at once still ends it.
        QTimer::singleShot(0, &m_loop, [this] { m_connection.connectTo(m_options.target); });
        m_loop.exec();
        closeQuietly();
        m_connection.disconnectFromMachine();
        return m_exitCode;
    }

private:
    using Done = MachineConnection::Done;

    // No more status queries, and the answer to one already sent is let in (at most 200 ms) before the link
    // closes: a controller that writes its report to a client already gone may take it badly (grblHAL's
    // simulator exits), and a closing socket with unread data resets the connection.
    void closeQuietly()
    {
        MachineLink *link = m_connection.link();
        if (!link || m_connection.state() != MachineConnection::State::Connected)
            return;
        link->setPollInterval(0);
        if (!link->isStatusRequested())
            return;
        QEventLoop quiet;
        QTimer::singleShot(200, &quiet, &QEventLoop::quit);
        QObject::connect(link, &MachineLink::statusChanged, &quiet, &QEventLoop::quit);
        quiet.exec();
    }

    void operate();
    // push-offsets: the table's TLOs into the controller's own table; pull-offsets: back into the file.
    bool pushOffsets();
    void pulled(const SessionResult &r);
    void linkTest();
    // Sets the table's TLO for the tool back on the machine, when it was measured against the machine's
    // reference.
    bool restore();
    [[nodiscard]] std::optional<double> storedTloInSpindle() const;
    [[nodiscard]] std::optional<double> brokenToolTloInSpindle() const;
    void roundTrip();
    // `reported`: the command printed the failure itself (a rack's summary holds it).
    void finishWith(const SessionResult &r, bool reported = false);
    [[nodiscard]] bool record(const SessionResult &r);
    [[nodiscard]] bool recordTable(const SessionResult &r);
    void recordHistory(const QList<HistoryEvent> &events, const Result<QString> &kept);
    // Several recordings at once (a pull): the table file and the history take all of them, or none.
    [[nodiscard]] bool recordAll(const QList<Recording> &recordings);
    // A result printed by `print` when the operation got that far (a broken tool's verdict included).
    [[nodiscard]] Done printed(std::function<void(const SessionResult &)> print);
    // A probe or a manual offset: recorded, then printed.
    [[nodiscard]] Done recorded();
    // measure-repeatability: the tool in the spindle touched K times on one edge, probed and recorded as a
    // probe, and the setter's spread kept for the machine (machinerunrecording.cpp).
    [[nodiscard]] bool measureRepeatability();
    // break-test: a tolerance finer than the machine's setter repeats (its kept repeatability) is said.
    void warnBelowRepeatability();

    Invocation &m_call;
    MachineOptions m_options;
    MachineConnection m_connection;
    QEventLoop m_loop;
    int m_exitCode = Success;
    bool m_started = false;
    QString m_trendWarning; // a probe off its tool's wear trend
    QString m_history; // what became of the event: recorded, kept (on this computer), not_recorded
    QList<double> m_times; // link-test: each round trip's milliseconds
    QElapsedTimer m_clock;
    bool m_recordFailed = false; // then the exit code says so (unless the tool is broken, which says more)
};

} // namespace Toffee::Cli::Machine
