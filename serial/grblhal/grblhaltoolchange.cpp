// SPDX-License-Identifier: GPL-3.0-or-later
// grblHAL's manual tool change: M6 T<n> holds the machine in state Tool until the person at it presses cycle
// start (or says so here: `~`); then the tool is measured, or takes its stored TLO. Whether anyone is there,
// and how long the wait may last, is the neutral layer's (MachineController::changeTool); ending the wait is
// grblHAL's soft reset.
#include "serial/grblhal/grblhalcontroller.h"

#include <memory>

#include <QTimer>

namespace Toffee {

QString GrblHalController::changeByHand(int tool) const
{
    // Every M6 of grblHAL's manual tool change ($341 = 0, the default) waits for cycle start.
    return tool > 0 ? tr("T%1 is put in by hand (grblHAL's manual tool change)").arg(tool) : QString();
}

void GrblHalController::startToolChange(int tool, Done done, std::optional<double> storedTlo)
{
    if (auto valid = validateToolNumber(tool); !valid) {
        refuse(done, valid.error().message);
        return;
    }
    if (tool <= 0) {
        refuse(done, tr("grblHAL changes to a tool, not to an empty spindle: use Select Tool with T0."));
        return;
    }
    run("M6 T" + QByteArray::number(tool), MachineLink::kDefaultTimeoutMs, done,
        [this, done, tool, storedTlo](const CommandReply &) {
            auto waitChanged = std::make_shared<std::function<void()>>();
            // Each poll holds the function; it holds itself only weakly, so it goes with the last poll.
            *waitChanged = [this, done, tool, storedTlo, self = std::weak_ptr(waitChanged)] {
                awaitStatus(2000,
                    [this, done, tool, storedTlo, waitChanged = self.lock()](std::optional<MachineStatus> s) {
                        if (toolChangeEnded()) {
                            // Ended while it waited (changeTool says why): nothing is measured, once grblHAL
                            // has said it restarted (its greeting): nothing goes to a controller mid-reset.
                            awaitGreeting([done] {
                                done(SessionResult::failed(SessionResult::Outcome::MachineError, {}));
                            });
                            return;
                        }
                        if (!s) {
                            done(SessionResult::failed(SessionResult::Outcome::LinkFailure,
                                tr("grblHAL stopped reporting its state during the change to T%1.")
                                    .arg(tool)));
                            return;
                        }
                        if (s->state == u"Tool") {
                            QTimer::singleShot(
                                MachineLink::kPollIntervalMs, this, [waitChanged] { (*waitChanged)(); });
                            return;
                        }
                        if (s->isAlarm()) {
                            done(SessionResult::failed(SessionResult::Outcome::MachineError,
                                tr("grblHAL went into alarm during the change to T%1: nothing was measured.")
                                    .arg(tool)));
                            return;
                        }
                        m_tool = tool;
                        if (storedTlo)
                            restoreTlo(tool, *storedTlo, done);
                        else
                            probe(done);
                    });
            };
            (*waitChanged)();
        });
}

void GrblHalController::awaitGreeting(std::function<void()> next)
{
    auto *timer = new QTimer(this);
    timer->setSingleShot(true);
    auto connection = std::make_shared<QMetaObject::Connection>();
    auto finish = [timer, connection, next] {
        QObject::disconnect(*connection);
        timer->stop();
        timer->deleteLater();
        next();
    };
    *connection = connect(m_link, &MachineLink::lineReceived, timer, [finish](const QByteArray &line) {
        if (GrblHal::classifyReply(line).kind == GrblHal::ReplyKind::Greeting)
            finish();
    });
    connect(timer, &QTimer::timeout, timer, finish);
    timer->start(kGreetingWaitMs);
}

void GrblHalController::resumeWaitingChange()
{
    m_link->sendRealtime('~');
}

void GrblHalController::cancelWaitingChange()
{
    m_link->sendRealtime('\x18');
}

QString GrblHalController::cancelledChangeNote() const
{
    return tr("grblHAL was reset to end it: its tool is still T%1, with no offset in force. Check what is in "
              "the spindle, then select it and restore or probe its TLO before cutting.")
        .arg(m_tool.value_or(0));
}

} // namespace Toffee
