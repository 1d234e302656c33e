// SPDX-License-Identifier: GPL-3.0-or-later
// Connecting: open the link, flush the controller, wait out a machine still busy with an earlier command,
// read the status and the offsets, each within its time limit.
#include "serial/carvera/machinesession.h"

#include <QDeadlineTimer>
#include <QPointer>
#include <QTimer>

#include "model/numberformat.h"
#include "serial/transport/linetransport.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

bool isBusyState(const QString &state)
{
    return state == u"Run" || state == u"Home" || state == u"Tool";
}

QString seconds(qint64 ms)
{
    return formatNumber(double(ms) / 1000.0, NumberFormat::upTo(1));
}

} // namespace

void MachineSession::awaitIdle(QDeadlineTimer deadline, std::function<void(bool, const QString &)> next)
{
    awaitStatus(2000, [this, deadline, next](std::optional<MachineStatus> status) {
        const QString state = status ? status->state : QString();
        if (!isBusyState(state)) {
            QTimer::singleShot(150, this, [next, state] { next(true, state); });
            return;
        }
        if (deadline.hasExpired() || !m_link->isOpen()) {
            next(false, state);
            return;
        }
        QTimer::singleShot(
            MachineLink::kPollIntervalMs, this, [this, deadline, next] { awaitIdle(deadline, next); });
    });
}

void MachineSession::connectToMachine(Done done)
{
    // With a time limit set (toffee-cli --timeout), the whole connect obeys it, waiting for a busy machine
    // included; without one, a running probe is given the time a probe may take.
    const int limitMs = m_link->timeoutOverride();
    if (limitMs > 0)
        done = withDeadline(limitMs, std::move(done));
    const qint64 idleWaitMs = limitMs > 0 ? limitMs : MachineLink::kMotionTimeoutMs + 10000;
    const QDeadlineTimer idleDeadline(idleWaitMs);
    auto afterOpen = [this, done, idleDeadline, idleWaitMs] {
        awaitIdle(idleDeadline, [this, done, idleWaitMs](bool idle, const QString &state) {
            if (!idle) {
                done(stayedBusy(state, idleWaitMs));
                return;
            }
            // The controller app sends "\n;\n" on opening to flush whatever the machine had
            // half-received.
            run("", MachineLink::kDefaultTimeoutMs, done, [this, done](const CommandReply &) {
                run(";", MachineLink::kDefaultTimeoutMs, done, [this, done](const CommandReply &) {
                    readVersion(done, [this, done] { readStatusAfterConnect(done); });
                });
            });
        });
    };
    openLink(done, afterOpen);
}

void MachineSession::readStatusAfterConnect(Done done)
{
    awaitStatus(2000, [this, done](std::optional<MachineStatus> status) {
        if (!status) {
            SessionResult result;
            result.outcome = SessionResult::Outcome::LinkFailure;
            result.message = tr("The machine answered but sent no status report; is this a Carvera?");
            done(result);
            return;
        }
        SessionResult result;
        result.status = status;
        result.tool = status->tool;
        if (status->isAlarm()) {
            // Reachable while halted, so that it can be unlocked; M493.4 would get "Alarm lock".
            done(result);
            return;
        }
        readOffsets(done, result);
    });
}

MachineSession::Done MachineSession::withDeadline(int limitMs, Done done)
{
    auto finished = std::make_shared<bool>(false);
    QPointer<QTimer> timer = new QTimer(this);
    timer->setSingleShot(true);
    timer->setTimerType(Qt::PreciseTimer);
    Done once = [finished, timer, done](const SessionResult &result) {
        if (std::exchange(*finished, true))
            return;
        if (timer) {
            timer->stop();
            timer->deleteLater();
        }
        done(result);
    };
    connect(timer, &QTimer::timeout, this, [this, once, limitMs] {
        const std::optional<MachineStatus> &status = m_link->lastStatus();
        SessionResult late;
        if (status && isBusyState(status->state)) {
            late = stayedBusy(status->state, limitMs);
        } else if (const auto command = m_link->currentCommand(); command && command->size() > 1) {
            // (not the opening flush, "" or ";", which would say nothing to an operator)
            late.outcome = SessionResult::Outcome::LinkFailure;
            late.message
                = tr("The machine did not answer \"%1\" within the %2 s allowed for connecting. "
                     "Check that it is on, and the cable or the Wi-Fi, then connect again (or allow longer).")
                      .arg(QString::fromUtf8(*command), seconds(limitMs));
        } else {
            late.outcome = SessionResult::Outcome::LinkFailure;
            late.message = tr(
                "The machine did not finish connecting within the %1 s allowed: it answered "
                "too slowly, or not at all. Check that it is on, and the cable or the Wi-Fi, then connect "
                "again (or allow longer).")
                               .arg(seconds(limitMs));
        }
        once(late);
        m_link->close(); // whatever is still in flight could be answered late, and mismatched
    });
    timer->start(limitMs);
    return once;
}

SessionResult MachineSession::stayedBusy(const QString &state, qint64 waitedMs)
{
    SessionResult result;
    result.outcome = SessionResult::Outcome::LinkFailure;
    result.message = tr("The machine stayed busy (%1) for the %2 s allowed for connecting. Wait for it to "
                        "finish, or stop it, then connect again.")
                         .arg(state, seconds(waitedMs));
    return result;
}

} // namespace Toffee
