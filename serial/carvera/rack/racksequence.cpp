// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/carvera/rack/racksequence.h"

#include <algorithm>
#include <cmath>

#include <QPointer>
#include <QStringList>

#include "model/breaktestrule.h"
#include "model/numberformat.h"
#include "model/tooltable.h"
#include "serial/machineconnection.h"

using namespace Qt::StringLiterals;

namespace Toffee {

QString RackSequence::toolNames(const QList<int> &tools)
{
    QStringList names;
    for (int t : tools)
        names << u"T"_s + QString::number(t);
    return names.join(u", "_s);
}

RackSequence::Plan RackSequence::plan(
    Mode mode, const QList<int> &rack, const ToolTable &table, double tolerance)
{
    Plan p;
    p.mode = mode;
    p.tolerance = tolerance;
    for (int tool : rack) {
        RackStep step;
        step.tool = tool;
        if (const auto stored = table.storedTlo(tool)) { // in millimetres, as the machine's
            step.storedTlo = stored->tlo;
            step.storedReferenceMz = stored->referenceMz;
        }
        p.steps.append(step);
    }
    return p;
}

std::optional<QString> RackSequence::refusal(const Plan &plan, const FirmwareInfo &firmware)
{
    if (plan.steps.isEmpty())
        return tr("The rack holds no tools: say which tools it holds (1-6 on a C1) first.");
    if (plan.mode == Mode::Measure)
        return std::nullopt;
    if (!firmware.hasBreakTest()) {
        return firmware.kind == FirmwareInfo::Kind::Stock
            ? tr("The machine runs %1, whose M491.1 only measures a tool again without comparing: a rack "
                 "check there would pass a broken tool. Install the community firmware to check the rack.")
                  .arg(firmware.description())
            : tr("The machine did not say which firmware it runs, so Toffee cannot tell whether its M491.1 "
                 "compares a tool with its TLO. The rack was not checked.");
    }
    if (auto r = MachineController::validateTolerance(plan.tolerance); !r)
        return r.error().message;
    QList<int> unmeasured;
    for (const RackStep &step : plan.steps) {
        if (!step.storedTlo && !breakTestExclusion(step.tool)) // a tool skipped needs none
            unmeasured.append(step.tool);
    }
    if (!unmeasured.isEmpty())
        return tr("%1 have no stored TLO to compare with. Measure them first (Measure Rack); nothing moved.")
            .arg(toolNames(unmeasured));
    return std::nullopt;
}

RackSequence::RackSequence(MachineConnection *connection, Plan plan, QObject *parent)
    : QObject(parent)
    , m_connection(connection)
    , m_plan(std::move(plan))
{ }

bool RackSequence::start()
{
    m_outcome = SessionResult {};
    if (auto why = refusal(m_plan, m_connection->firmware())) {
        m_outcome.outcome = SessionResult::Outcome::Refused;
        m_outcome.message = *why;
        return false;
    }
    const QString what = m_plan.mode == Mode::Measure ? tr("Measuring the rack…") : tr("Checking the rack…");
    if (!m_connection->canOperate() || !m_connection->beginOperation(what)) {
        m_outcome.outcome = SessionResult::Outcome::MachineError;
        m_outcome.message = m_connection->isHalted() ? m_connection->haltedMessage()
                                                     : tr("The machine is busy or not connected.");
        return false;
    }
    m_running = true;
    m_current = -1;
    next();
    return true;
}

void RackSequence::cancel()
{
    m_cancelled = m_running;
}

QString RackSequence::progressText(int index) const
{
    const int tool = m_plan.steps.at(index).tool;
    const int of = int(m_plan.steps.size());
    return m_plan.mode == Mode::Measure ? tr("Measuring T%1 (%2 of %3)…").arg(tool).arg(index + 1).arg(of)
                                        : tr("Checking T%1 (%2 of %3)…").arg(tool).arg(index + 1).arg(of);
}

void RackSequence::next()
{
    ++m_current;
    if (!m_connection->session()) {
        SessionResult lost;
        lost.outcome = SessionResult::Outcome::LinkFailure;
        lost.message = tr("The connection to the machine was closed; the rack was not finished.");
        return finish(lost);
    }
    const bool done = m_current == m_plan.steps.size();
    if (m_cancelled) {
        SessionResult stopped;
        stopped.message = done
            ? tr("Cancelled after the last tool: every tool was done, and T%1 stays in the "
                 "spindle.")
                  .arg(m_plan.steps.last().tool)
            : tr("Cancelled: the rack was stopped after T%1, which is in the spindle.")
                  .arg(m_plan.steps.at(m_current - 1).tool);
        return finish(stopped);
    }
    // A check that tested nothing (every tool skipped) changed no tool: there is none to put back.
    const bool tested = std::any_of(m_plan.steps.cbegin(), m_plan.steps.cend(),
        [](const RackStep &s) { return s.state == RackStep::State::Passed; });
    if (done)
        return m_plan.mode == Mode::Check && tested ? putBack() : finish(SessionResult {});
    m_plan.steps[m_current].state = RackStep::State::Running;
    m_connection->updateOperation(progressText(m_current));
    Q_EMIT stepChanged(m_current);
    if (m_plan.mode == Mode::Measure)
        measure(m_current);
    else
        check(m_current);
}

// A step's callback: nothing once the sequence is gone; the offsets a result reports are announced first.
template<typename Next> MachineController::Done RackSequence::step(Next next)
{
    QPointer<RackSequence> self(this);
    return [self, next](const SessionResult &r) {
        if (!self)
            return;
        self->m_connection->announce(r);
        next(r);
    };
}

void RackSequence::measure(int index)
{
    m_connection->session()->changeTool(
        m_plan.steps.at(index).tool, step([this, index](const SessionResult &r) {
            if (!r.ok() || !r.recording)
                return settle(index, RackStep::State::Failed, r);
            m_plan.steps[index].measuredTlo = r.recording->tlo;
            Q_EMIT recorded(r);
            settle(index, RackStep::State::Measured, r);
        }));
}

void RackSequence::check(int index)
{
    const int tool = m_plan.steps.at(index).tool;
    // A tool the firmware takes for its wireless probe is skipped, as Prepare skips it, and said why; the
    // rack goes on with the next (and the check is incomplete). A stored TLO of 0.000 is tested as every
    // other (comparableTlo).
    if (const auto why = breakTestExclusion(tool)) {
        RackStep &skipped = m_plan.steps[index];
        skipped.state = RackStep::State::Skipped;
        skipped.message = breakTestExclusionText(*why, tool);
        Q_EMIT stepChanged(index);
        return next();
    }
    const auto &offsets = m_connection->lastOffsets();
    const bool hasReference = offsets && (!offsets->referenceMz || *offsets->referenceMz != 0.0);
    if (m_connection->activeTool() == tool && hasReference)
        return testInSpindle(index);
    // The change measures the tool too (and a tool already in the spindle is measured where it is when the
    // machine reports an uncalibrated reference of 0); that measurement is not stored: a broken tool's would
    // replace the TLO it is about to be compared with.
    m_connection->session()->changeTool(tool, step([this, index](const SessionResult &r) {
        if (!r.ok())
            return settle(index, RackStep::State::Failed, r);
        testInSpindle(index);
    }));
}

void RackSequence::testInSpindle(int index)
{
    const RackStep &current = m_plan.steps.at(index);
    const auto machineReference = m_connection->lastOffsets();
    // A tool setter scatters by a few micrometres from one start to the next: a reference that moved by less
    // than a quarter of the tolerance shifts every comparison by that little, and the check goes on.
    const double moved = current.storedReferenceMz && machineReference && machineReference->referenceMz
        ? std::fabs(*current.storedReferenceMz - *machineReference->referenceMz)
        : 0.0;
    if (moved > m_plan.tolerance / 4) {
        SessionResult refused;
        refused.outcome = SessionResult::Outcome::MachineError;
        refused.message
            = tr("T%1's stored TLO was measured against reference MCS Z %2, but the machine's reference is "
                 "at %3 now, %4 away: every comparison would be off by that much. Check the machine's "
                 "calibration and the tool setter; if they are sound, measure the rack again (Measure "
                 "Rack).")
                  .arg(current.tool)
                  .arg(millimetres(*current.storedReferenceMz, false))
                  .arg(millimetres(*machineReference->referenceMz, false))
                  .arg(millimetres(moved));
        return settle(index, RackStep::State::Failed, refused);
    }
    // The machine keeps one TLO, the spindle tool's, and M491.1 compares with it: the stored one goes in
    // first (breakTest sets it when the machine has another).
    m_connection->session()->breakTest(m_plan.tolerance, step([this, index](const SessionResult &r) {
        if (r.breakTest)
            m_plan.steps[index].measuredTlo = r.breakTest->newTlo;
        if (r.recording)
            Q_EMIT recorded(r);
        const bool broken = r.outcome == SessionResult::Outcome::ToolBroken;
        settle(index,
            r.ok()       ? RackStep::State::Passed
                : broken ? RackStep::State::Broken
                         : RackStep::State::Failed,
            r);
    }),
        *current.storedTlo);
}

void RackSequence::putBack()
{
    m_connection->updateOperation(tr("Putting T%1 back in the rack…").arg(m_plan.steps.last().tool));
    m_connection->session()->changeTool(Limits::kEmptySpindle, step([this](const SessionResult &r) {
        if (!r.ok()) {
            SessionResult failed = r;
            failed.message
                = tr("Every tool passed, but the last one could not be put back: %1").arg(r.message);
            return finish(failed);
        }
        finish(SessionResult {});
    }));
}

void RackSequence::settle(int index, RackStep::State state, const SessionResult &result)
{
    RackStep &step = m_plan.steps[index];
    step.state = state;
    if (!result.ok())
        step.message = result.message;
    Q_EMIT stepChanged(index);
    if (!result.ok())
        return finish(result);
    next();
}

void RackSequence::finish(const SessionResult &result)
{
    for (qsizetype i = 0; i < m_plan.steps.size(); ++i) {
        if (m_plan.steps.at(i).state == RackStep::State::Waiting) {
            m_plan.steps[i].state = RackStep::State::NotRun;
            Q_EMIT stepChanged(int(i));
        }
    }
    m_outcome = result;
    m_running = false;
    m_connection->endOperation(result);
    Q_EMIT finished(m_outcome);
}

} // namespace Toffee
