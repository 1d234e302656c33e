// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QTimer>

#include "serial/machine/machinereplies.h"

namespace Toffee {

class LineTransport;

// The outcome of one command line: its terminator and everything it printed before it.
struct CommandReply
{
    enum class Status {
        Ok, // "ok", and no alarm on the way
        Refused, // "error:..."
        Halted, // an ALARM or halting ERROR line came with it
        Timeout, // no answer in time: the link is closed, since its replies can no longer be matched
        LinkLost, // the port closed or vanished
    };
    Status status = Status::Ok;
    QByteArray command;
    QList<QByteArray> lines; // the last MachineLink::kMaxReplyLines it printed
    QString message; // for an operator, on failure
    qint64 droppedLines = 0; // printed before `lines`, and not kept
    [[nodiscard]] bool ok() const { return status == Status::Ok; }
};

// How one controller's lines read, which MachineLink matches replies by: which line ends a command, which
// halts the machine, which is a status report and what it says. Each controller gives its own
// (carveraGrammar(), serial/carvera; GrblHal::grammar(), serial/grblhal); basic() knows only "ok", "error:",
// "ALARM:" and "<…>" without reading the report.
struct ReplyGrammar
{
    std::function<ReplyKind(QByteArrayView line)> classify;
    // A status report as the neutral status. `previous`: the last one, for fields a controller sends only
    // when they change (grblHAL's tool and offset).
    std::function<std::optional<MachineStatus>(
        QByteArrayView line, const std::optional<MachineStatus> &previous)>
        status;
    // The line that ends a script the controller runs (ReplyEnd::Script).
    std::function<bool(QByteArrayView line)> scriptDone;
    // What an "error:" or alarm line says, for people.
    std::function<QString(QByteArrayView line)> message;
    // What a halt the controller named means and what to do; empty when the message says it already.
    std::function<QString(QStringView message)> haltMeaning;
    // What a refusal ("error:N") means and what to do, when the controller says only a number; may be empty.
    std::function<QString(QStringView message)> refusalMeaning;

    [[nodiscard]] static ReplyGrammar basic();
};

// Sends command lines to the controller one at a time and matches each reply to its command (ReplyEnd:
// "ok" is the whole line, "error:" starts it, a script ends with "Done ATC"), polls the status report about
// every 200 ms as real-time traffic, and fails a command that gets no answer in its time limit. Never hangs:
// a stalled or closed link fails the pending commands with a message.
class MachineLink final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(MachineLink)

public:
    using ReplyHandler = std::function<void(const CommandReply &reply)>;
    static constexpr int kDefaultTimeoutMs = 5000;
    static constexpr int kMotionTimeoutMs = 120000; // a probing cycle takes tens of seconds
    static constexpr int kPollIntervalMs = 200;
    static constexpr int kAlarmGraceMs
        = 1000; // after an ALARM, how long to wait for the command's terminator
    // What a command's reply keeps: the results (probe, offsets, break test) come just before "ok", so a
    // tail is enough, and a machine that floods the link cannot grow memory without bound.
    static constexpr qsizetype kMaxReplyLines = 256;
    // ReplyEnd::Quiet: this long without a line ends the reply.
    static constexpr int kQuietMs = 400;

    explicit MachineLink(LineTransport *transport, QObject *parent = nullptr);

    [[nodiscard]] LineTransport *transport() const { return m_transport; }
    // The controller's words (the controller sets its own when it takes the link).
    void setGrammar(const ReplyGrammar &grammar) { m_grammar = grammar; }
    [[nodiscard]] const ReplyGrammar &grammar() const { return m_grammar; }
    [[nodiscard]] bool isOpen() const;
    void open();
    void close();

    // `maxLines`: the most reply lines kept (the last ones); a reply known to be longer than the usual bound
    // (grblHAL's $# of a large tool table) asks for more.
    void send(const QByteArray &line, int timeoutMs, ReplyHandler handler, ReplyEnd end = ReplyEnd::Ok,
        qsizetype maxLines = kMaxReplyLines);
    // A question the controller asks for its status (LinuxCNC's gets, every half second while idle): sent as
    // send() does, but not said as sent (lineSent), and isQuiet() while its answer comes, so that the console
    // is not drowned, as it is not by status reports.
    // `shownAs`: the line as every message and reply names it, when the line itself must not be shown (a
    // password in it).
    void sendQuietly(const QByteArray &line, int timeoutMs, ReplyHandler handler, ReplyEnd end = ReplyEnd::Ok,
        const QByteArray &shownAs = {});
    [[nodiscard]] bool isQuiet() const { return m_current && m_current->quiet; }
    void sendRealtime(char c);
    void requestStatus();
    // A status learned by asking (a controller with no status report of its own: LinuxCNC's gets), taken and
    // said as a report's would be.
    void reportStatus(const MachineStatus &status);
    void setPollInterval(int ms); // 0: no polling
    // Scales every time limit, for tests that inject silence (1.0 = as given).
    void setTimeoutScale(double scale) { m_timeoutScale = scale; }
    // Gives up on any command after `ms` whatever its own limit (0: each command's own limit).
    void setTimeoutOverride(int ms) { m_timeoutOverride = ms; }
    // The command in flight now waits for a person (a manual tool change): its limit starts again at `ms`,
    // since the wait's own limit (MachineController::operatorWaitMs) is what ends it.
    void restartLimit(int ms);
    [[nodiscard]] int timeoutOverride() const { return m_timeoutOverride; }

    [[nodiscard]] const std::optional<MachineStatus> &lastStatus() const { return m_status; }
    // Milliseconds since the last good status report, or -1 when there has been none.
    // A status query ('?') was sent and its report has not come yet.
    [[nodiscard]] bool isStatusRequested() const { return m_statusRequested; }
    [[nodiscard]] qint64 statusAgeMs() const
    {
        return m_statusClock.isValid() ? m_statusClock.elapsed() : -1;
    }
    [[nodiscard]] bool isBusy() const { return m_current.has_value() || !m_queue.isEmpty(); }
    // The command waiting for its answer, if any.
    [[nodiscard]] std::optional<QByteArray> currentCommand() const
    {
        return m_current ? std::optional(m_current->line) : std::nullopt;
    }

Q_SIGNALS:
    void opened();
    void closed(const QString &reason);
    void statusChanged(const Toffee::MachineStatus &status);
    void lineSent(const QByteArray &line);
    void lineReceived(const QByteArray &line);
    // An ALARM or a halting ERROR line, with or without a command in flight (a broken tool, an abort, a
    // limit switch): the machine is halted from this line on.
    void alarmRaised(const QString &message);

private:
    struct Pending
    {
        QByteArray line;
        int timeoutMs = kDefaultTimeoutMs;
        ReplyHandler handler;
        ReplyEnd end = ReplyEnd::Ok;
        qsizetype maxLines = kMaxReplyLines;
        bool quiet = false;
        QByteArray shown; // the line as messages name it, when not the line itself
        [[nodiscard]] QByteArray named() const { return shown.isEmpty() ? line : shown; }
    };

    void enqueue(Pending pending);
    void startNext();
    void handleLine(const QByteArray &line);
    // A line of the running command's reply, by how its reply ends.
    void handleReplyLine(const QByteArray &line, ReplyKind kind);
    void complete(CommandReply::Status status, const QString &message);
    void failAll(CommandReply::Status status, const QString &message);
    void handleClosed();
    void keep(const QByteArray &line);
    [[nodiscard]] QString floodNote() const;
    [[nodiscard]] QString haltedMessage() const;

    LineTransport *m_transport;
    ReplyGrammar m_grammar = ReplyGrammar::basic();
    QList<Pending> m_queue;
    std::optional<Pending> m_current;
    QList<QByteArray> m_lines;
    qint64 m_droppedLines = 0;
    QString m_alarm;
    QString m_lastError;
    QTimer m_timeout;
    QTimer m_grace;
    QTimer m_quiet; // ReplyEnd::Quiet: the silence that ends the reply
    bool m_scriptRunning = false; // ReplyEnd::Script: the firmware said it starts its script
    QTimer m_poll;
    double m_timeoutScale = 1.0;
    int m_timeoutOverride = 0;
    std::optional<MachineStatus> m_status;
    QElapsedTimer m_statusClock;
    bool m_statusRequested = false;
};

} // namespace Toffee
