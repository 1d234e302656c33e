// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/machine/machinecontroller.h"

#include <cmath>

#include <QDateTime>
#include <QPointer>
#include <QTimer>

#include "model/clock.h"
#include "model/numberformat.h"
#include "model/toolvalidation.h"
#include "serial/machine/machinelink.h"
#include "serial/transport/linetransport.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// A tolerance as the operator typed it: "0.02", not "0.020"; in their own decimal mark.
QString toleranceText(double tolerance)
{
    return formatNumber(tolerance, NumberFormat::upTo(3).inLocale());
}

} // namespace

MachineController::~MachineController() = default;

HaltWords MachineController::neutralHaltWords(int reason)
{
    return { tr("halt %1").arg(reason), tr("The machine halted (reason %1).").arg(reason),
        tr("Check the machine, then Unlock ($X).") };
}

void MachineController::readToolTable(Done done)
{
    refuse(std::move(done),
        tr("%1 keeps no tool table of its own: its tools' TLOs are Toffee's table's alone.")
            .arg(firmware().description()));
}

void MachineController::writeToolTable(const QList<ControllerTool> &tools, Done done)
{
    Q_UNUSED(tools)
    readToolTable(std::move(done));
}

void MachineController::refuse(Done done, const QString &message)
{
    SessionResult result;
    result.outcome = SessionResult::Outcome::Refused;
    result.message = message;
    QTimer::singleShot(0, [done, result] { done(result); });
}

SessionResult MachineController::failure(const CommandReply &reply)
{
    SessionResult result;
    result.message = reply.message;
    switch (reply.status) {
    case CommandReply::Status::Timeout:
    case CommandReply::Status::LinkLost:
        result.outcome = SessionResult::Outcome::LinkFailure;
        break;
    default:
        result.outcome = SessionResult::Outcome::MachineError;
    }
    return result;
}

MachineController::Done MachineController::recording(Done done, RecordingKind kind)
{
    return [done = std::move(done), kind](const SessionResult &r) {
        if (!r.ok() || !r.tlo || !r.tool || *r.tool < 0)
            return done(r);
        // The one range, before anything records it: a reading beyond any tool is the machine's or the
        // setter's fault, never a TLO.
        if (!isMachineTlo(r.tlo->tlo())) {
            SessionResult beyond = SessionResult::failed(SessionResult::Outcome::MachineError,
                tr("The machine's reading makes T%1's TLO %2 mm, beyond any tool (%3 mm at most): nothing "
                   "was "
                   "recorded. Check the tool setter and the machine's reference, then probe again.")
                    .arg(*r.tool)
                    .arg(formatNumber(r.tlo->tlo(), NumberFormat::fixed(3)))
                    .arg(kMaxOffset));
            beyond.tool = r.tool;
            return done(beyond);
        }
        SessionResult recorded = r;
        const TloSource source = kind == RecordingKind::Probe ? TloSource::Probe : TloSource::Manual;
        recorded.recording = Recording { *r.tool, r.tlo->tlo(), source, r.tlo->knownReferenceMz(),
            std::nullopt, Clock::now(), kind, r.tlo->knownCurrentMz() };
        recorded.recording->touches = r.tlo->touches;
        done(recorded);
    };
}

MachineController::Done MachineController::recordingVerdict(Done done)
{
    return [done = std::move(done)](const SessionResult &r) {
        const bool broken = r.outcome == SessionResult::Outcome::ToolBroken;
        if (!r.breakTest || !r.tool || *r.tool < 0 || !(r.ok() || broken))
            return done(r);
        SessionResult recorded = r;
        recorded.recording = Recording { *r.tool, std::nullopt, TloSource::Probe, std::nullopt, broken,
            Clock::now(), RecordingKind::BreakTest, std::nullopt, r.tolerance, r.breakTest->oldTlo,
            r.breakTest->newTlo, r.breakTest->touches };
        done(recorded);
    };
}

QString MachineController::spreadFinding(int tool, const QList<double> &touches, const ProbePlan &plan)
{
    const double spread = spreadOf(touches);
    if (touches.size() < 2 || !plan.spreadLimit || spread <= *plan.spreadLimit + 1e-9)
        return {};
    const auto mm = [](double v) {
        return formatNumber(v, NumberFormat::fixed(3));
    };
    return tr(
        "T%1's edges differ by %2 mm (its limit %3 mm): runout or a chipped edge. Look at the cutter and "
        "how it sits in its holder before it cuts.")
        .arg(tool)
        .arg(mm(spread), mm(*plan.spreadLimit));
}

SessionResult MachineController::breakVerdict(int tool, double stored, double measured, double tolerance,
    const QString &keptIn, const QList<double> &touches) const
{
    SessionResult result;
    result.tool = tool;
    result.tolerance = tolerance;
    result.breakTest = BreakTestReading { stored, measured, touches.size() > 1 ? touches : QList<double> {} };
    const double difference = std::fabs(measured - stored);
    if (difference > tolerance) {
        const auto mm = [](double v) {
            return formatNumber(v, NumberFormat::fixed(3));
        };
        result.outcome = SessionResult::Outcome::ToolBroken;
        result.message
            = tr("T%1 measured %2 mm against its stored TLO %3 mm: %4 mm apart, more than the "
                 "tolerance %5 mm. It may be broken or worn. The spindle is stopped and lifted; its "
                 "stored TLO is kept in the table and in %6. Look at the tool and replace it before "
                 "you cut.")
                  .arg(tool)
                  .arg(mm(measured), mm(stored), mm(difference),
                      formatNumber(tolerance, NumberFormat::upTo(3)), keptIn);
    }
    if (const QString spread = spreadFinding(tool, touches, probePlan(tool)); !spread.isEmpty()) {
        result.outcome = SessionResult::Outcome::ToolBroken;
        result.message = QString(result.message + u' ' + spread).trimmed();
    }
    return result;
}

std::optional<double> MachineController::breakBaseline(const Done &done, int tool, bool hasReference,
    std::optional<double> storedTlo, const QList<ControllerTool> &table, const QString &controller)
{
    if (!hasReference) {
        refuse(done,
            tr("This machine has no reference tool yet, so a new length cannot be compared. Probe a tool "
               "first: the first one measured becomes the reference."));
        return std::nullopt;
    }
    constexpr double kEmpty = 0.0005; // what reads back as 0.000
    for (const ControllerTool &entry : table) {
        if (!storedTlo && entry.tool == tool && std::fabs(entry.tlo) >= kEmpty)
            storedTlo = entry.tlo;
    }
    if (!storedTlo)
        refuse(done,
            tr("T%1 has no stored TLO to compare with, in the table or in %2's own: probe it first.")
                .arg(tool)
                .arg(controller));
    return storedTlo;
}

void MachineController::writeEach(
    const QList<ControllerTool> &tools, WriteOne writeOne, std::function<void(Done)> verify, Done finished)
{
    auto remaining = std::make_shared<QList<ControllerTool>>(tools);
    auto written = std::make_shared<QStringList>();
    // A refusal half-way says exactly which entries changed before it and which did not.
    const Done done = [finished, remaining, written](const SessionResult &r) {
        if (r.ok() || (written->isEmpty() && remaining->isEmpty()))
            return finished(r);
        SessionResult partly = r;
        QStringList notWritten;
        for (const ControllerTool &t : std::as_const(*remaining))
            notWritten << u"T%1"_s.arg(t.tool);
        partly.message += u' '
            + tr("Written before it: %1; not written: %2.")
                  .arg(written->isEmpty() ? tr("nothing") : written->join(u", "_s),
                      notWritten.isEmpty() ? tr("nothing") : notWritten.join(u", "_s));
        finished(partly);
    };
    auto step = std::make_shared<std::function<void()>>();
    // Each write's answer holds the function; it holds itself only weakly, so it goes with the last.
    *step = [done, writeOne, verify, remaining, written, self = std::weak_ptr(step)] {
        if (remaining->isEmpty())
            return verify(done);
        writeOne(remaining->first(), done, [remaining, written, step = self.lock()] {
            *written << u"T%1"_s.arg(remaining->takeFirst().tool);
            (*step)();
        });
    };
    (*step)();
}

void MachineController::jog(const std::array<double, 3> &stepMm, double feed, Done done)
{
    Q_UNUSED(stepMm)
    Q_UNUSED(feed)
    refuse(std::move(done),
        tr("%1 keeps its tool setter itself: Toffee does not jog it. Use the machine's own controls.")
            .arg(firmware().description()));
}

void MachineController::awaitStatus(int timeoutMs, std::function<void(std::optional<MachineStatus>)> next)
{
    auto *timer = new QTimer(this);
    timer->setSingleShot(true);
    timer->setTimerType(Qt::PreciseTimer);
    auto connection = std::make_shared<QMetaObject::Connection>();
    auto finish = [timer, connection, next](std::optional<MachineStatus> status) {
        QObject::disconnect(*connection);
        timer->stop();
        timer->deleteLater();
        next(status);
    };
    *connection = connect(
        link(), &MachineLink::statusChanged, timer, [finish](const MachineStatus &s) { finish(s); });
    connect(timer, &QTimer::timeout, timer, [finish] { finish(std::nullopt); });
    timer->start(timeoutMs);
    link()->requestStatus();
}

void MachineController::openLink(Done done, std::function<void()> afterOpen)
{
    if (link()->isOpen()) {
        afterOpen();
        return;
    }
    auto opened = std::make_shared<QMetaObject::Connection>();
    auto failed = std::make_shared<QMetaObject::Connection>();
    auto *guard = new QTimer(this);
    guard->setSingleShot(true);
    auto cleanup = [opened, failed, guard] {
        QObject::disconnect(*opened);
        QObject::disconnect(*failed);
        guard->stop();
        guard->deleteLater();
    };
    *opened = connect(link(), &MachineLink::opened, guard, [cleanup, afterOpen] {
        cleanup();
        afterOpen();
    });
    auto fail = [cleanup, done](const QString &message) {
        cleanup();
        SessionResult result;
        result.outcome = SessionResult::Outcome::LinkFailure;
        result.message = message;
        done(result);
    };
    *failed = connect(link()->transport(), &LineTransport::errorOccurred, guard, fail);
    // A backstop: the transport says itself why it did not open, within its own limit.
    const int openLimitMs = link()->transport()->openLimitMs() + 1000;
    connect(guard, &QTimer::timeout, guard, [this, fail, openLimitMs] {
        fail(tr("The link to %1 did not open within %2 s. Check the machine and the connection, then try "
                "again.")
                 .arg(link()->transport()->description())
                 .arg(openLimitMs / 1000));
    });
    guard->setTimerType(Qt::PreciseTimer);
    guard->start(openLimitMs);
    link()->open();
}

int MachineController::operatorWaitMs() const
{
    const int limit = link() ? link()->timeoutOverride() : 0;
    return limit > 0 ? limit : kOperatorWaitMs;
}

void MachineController::changeTool(int tool, Done done, std::optional<double> storedTlo)
{
    if (m_change) {
        refuse(std::move(done), tr("A tool change is already under way."));
        return;
    }
    if (const QString byHand = changeByHand(tool); !byHand.isEmpty() && !m_operatorAbsent.isEmpty()) {
        refuse(std::move(done),
            tr("%1 on this machine: someone must be there to do it, but %2. Nothing was sent. Change the "
               "tool "
               "where someone can answer, or put it in by hand and select it.")
                .arg(byHand, m_operatorAbsent));
        return;
    }
    m_change.emplace();
    m_change->tool = tool;
    // Both families say state Tool while a manual change waits for the person.
    m_change->statusWatch
        = connect(link(), &MachineLink::statusChanged, this, [this](const MachineStatus &s) {
              if (m_change && !m_change->waiting && !m_change->ended && s.state == u"Tool")
                  operatorWaitBegan();
          });
    startToolChange(tool, finishingChange(std::move(done)), storedTlo);
}

void MachineController::operatorWaitBegan()
{
    m_change->waiting = true;
    m_change->waited.start();
    const int limitMs = operatorWaitMs();
    m_change->limit = new QTimer(this);
    m_change->limit->setSingleShot(true);
    const int tool = m_change->tool;
    connect(m_change->limit, &QTimer::timeout, this,
        [this, tool, limitMs] { endToolChange(waitedTooLong(tool, limitMs)); });
    m_change->limit->start(limitMs);
    // A change the machine runs as one command (the Carvera's M6) is not the link's to end meanwhile: the
    // person gets the wait's limit, and the change what it takes after it.
    link()->restartLimit(limitMs + MachineLink::kMotionTimeoutMs);
    Q_EMIT waitingForOperator(tool, limitMs);
}

QString MachineController::waitedTooLong(int tool, int limitMs)
{
    return tr("Nobody put T%1 in within the %2 s the change waits.").arg(tool).arg(limitMs / 1000);
}

void MachineController::resumeToolChange()
{
    if (isWaitingForOperator() && !m_change->ended && resumesFromHere())
        resumeWaitingChange();
}

void MachineController::endToolChange(const QString &why)
{
    if (!m_change || m_change->ended)
        return;
    m_change->ended = why;
    cancelWaitingChange();
}

MachineController::Done MachineController::finishingChange(Done done)
{
    return [this, done = std::move(done)](const SessionResult &r) {
        if (!m_change)
            return done(r);
        PendingToolChange change = std::move(*m_change);
        m_change.reset();
        disconnect(change.statusWatch);
        if (change.limit)
            change.limit->deleteLater();
        Q_EMIT toolChangeFinished();
        if (!change.ended && change.waiting && !r.ok()) {
            // The link gave up while the machine waited (its limit is the wait's, when --timeout set both):
            // the machine must not go on waiting for a person nobody told to come.
            cancelWaitingChange();
            const int limitMs = operatorWaitMs();
            change.ended
                = change.waited.elapsed() >= limitMs - 1000 ? waitedTooLong(change.tool, limitMs) : QString();
        }
        if (!change.ended)
            return done(r);
        SessionResult ended = r;
        ended.outcome = change.ended->isEmpty() && r.outcome == SessionResult::Outcome::LinkFailure
            ? SessionResult::Outcome::LinkFailure
            : SessionResult::Outcome::MachineError;
        ended.recording.reset();
        ended.tlo.reset();
        const QString stopped = tr("The change to T%1 was ended: nothing was measured or recorded. %2")
                                    .arg(change.tool)
                                    .arg(cancelledChangeNote());
        ended.message = change.ended->isEmpty() ? r.message + u' ' + stopped : *change.ended + u' ' + stopped;
        done(ended);
    };
}

Result<void> MachineController::validateTolerance(double tolerance)
{
    if (!std::isfinite(tolerance))
        return Error { tr("The break-test tolerance is not a number; enter a value such as 0.1 mm.") };
    if (tolerance < kMinTolerance)
        return Error {
            tr("A break-test tolerance of %1 mm is too small: the machine halts below %2 mm. Use %2 mm "
               "or more (%3 mm is the default).")
                .arg(toleranceText(tolerance), toleranceText(kMinTolerance), toleranceText(kDefaultTolerance))
        };
    if (tolerance > kMaxOffset)
        return Error {
            tr("A break-test tolerance of %1 mm is larger than any tool.").arg(toleranceText(tolerance))
        };
    return {};
}

Result<void> MachineController::validateOffset(const QString &what, double value)
{
    if (!isMachineTlo(value))
        return Error { tr("%1 must be a number from -%2 to %2 mm.").arg(what).arg(kMaxOffset) };
    return {};
}

Result<void> MachineController::validateToolNumber(int tool)
{
    if (tool < Limits::kEmptySpindle || tool > Limits::kMaxToolNumber)
        return Error { tr("Tool %1 is not a tool number; use %2 to %3 (%4 for an empty spindle).")
                           .arg(tool)
                           .arg(Limits::kMinToolNumber)
                           .arg(Limits::kMaxToolNumber)
                           .arg(Limits::kEmptySpindle) };
    return {};
}

} // namespace Toffee
