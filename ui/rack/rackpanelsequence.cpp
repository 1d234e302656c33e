// SPDX-License-Identifier: GPL-3.0-or-later
// Measure Rack and Check Rack: a RackSequence asked about first, followed step by step, each measurement and
// verdict recorded as it comes, and its end told in words.
#include "ui/rack/rackpanel.h"

#include <algorithm>

#include <QDoubleSpinBox>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>

#include "model/document/tooldocument.h"
#include "model/numberformat.h"
#include "serial/machineconnection.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// A machine's message ends without a full stop ("The machine halted: Abort during cycle"); more follows it.
QString sentence(const QString &message)
{
    return message.isEmpty() || message.endsWith(u'.') || message.endsWith(u'!') ? message : message + u'.';
}

QList<int> toolsIn(const QList<RackStep> &steps, RackStep::State state)
{
    QList<int> tools;
    for (const RackStep &step : steps) {
        if (step.state == state)
            tools.append(step.tool);
    }
    return tools;
}

} // namespace

void RackPanel::measureRack(bool confirm)
{
    runSequence(RackSequence::Mode::Measure, confirm);
}

void RackPanel::checkRack(bool confirm)
{
    runSequence(RackSequence::Mode::Check, confirm);
}

void RackPanel::runSequence(RackSequence::Mode mode, bool confirm)
{
    if (!m_connection->canOperate() || !m_rack || m_sequence || m_loading)
        return;
    m_tolerance->interpretText(); // what is typed counts
    const bool check = mode == RackSequence::Mode::Check;
    auto plan = RackSequence::plan(mode, *m_rack, m_document->table(), m_tolerance->value());
    const QString title = check ? tr("Check the rack?") : tr("Measure the rack?");
    if (auto why = RackSequence::refusal(plan, m_connection->firmware())) {
        QMessageBox::warning(this, title, *why);
        return;
    }
    const QString tools = RackSequence::toolNames(*m_rack);
    const QString question = check
        ? tr(
            "The machine changes to %1 in turn and break-tests each against its stored TLO (tolerance %2). A "
            "broken tool halts the machine and stops the check. After the last, T%3 goes back in the rack.")
              .arg(tools, millimetres(plan.tolerance))
              .arg(m_rack->last())
        : tr("The machine changes to %1 in turn, putting the tool in the spindle back in the rack first, and "
             "measures each on the tool setter; each TLO is recorded in the table. T%2 stays in the spindle.")
              .arg(tools)
              .arg(m_rack->last());
    if (confirm
        && QMessageBox::question(this, title, question + u"\n\n"_s + tr("Keep clear of the machine."),
               QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
            != QMessageBox::Yes)
        return;
    m_results.clear();
    m_recordFailure.clear();
    m_result->clear();
    auto *sequence = new RackSequence(m_connection, std::move(plan), this);
    m_sequence = sequence;
    for (const RackStep &step : sequence->steps())
        m_results.insert(step.tool, step);
    connect(sequence, &RackSequence::stepChanged, this, &RackPanel::stepChanged);
    connect(sequence, &RackSequence::recorded, this, &RackPanel::stepRecorded);
    connect(sequence, &RackSequence::finished, this, &RackPanel::sequenceFinished);
    showProgress(true);
    m_progress->setRange(0, int(sequence->steps().size()));
    m_progress->setValue(0);
    if (!sequence->start()) {
        const QString why = sequence->outcome().message;
        m_sequence = nullptr;
        sequence->deleteLater();
        m_results.clear();
        showProgress(false);
        refreshTable();
        QMessageBox::warning(this, title, why);
    }
}

void RackPanel::stepChanged(int index)
{
    if (!m_sequence)
        return;
    const QList<RackStep> &steps = m_sequence->steps();
    m_results.insert(steps.at(index).tool, steps.at(index));
    const auto settled = std::count_if(steps.cbegin(), steps.cend(), [](const RackStep &s) {
        return s.state != RackStep::State::Waiting && s.state != RackStep::State::Running;
    });
    m_progress->setValue(int(settled));
    refreshTable();
}

void RackPanel::stepRecorded(const SessionResult &r)
{
    if (!r.recording)
        return;
    const auto stored = m_document->record(*r.recording);
    // What the machine measured but the table cannot hold must not be measured over: stop after this tool.
    if (!stored && m_recordFailure.isEmpty()) {
        m_recordFailure = tr("T%1: %2").arg(r.recording->tool).arg(stored.error().message);
        if (m_sequence)
            m_sequence->cancel();
    }
}

void RackPanel::sequenceFinished(const SessionResult &outcome)
{
    RackSequence *sequence = m_sequence;
    m_sequence = nullptr;
    sequence->deleteLater();
    showProgress(false);
    refreshTable();
    const QList<RackStep> &steps = sequence->steps();
    const QList<int> notRun = toolsIn(steps, RackStep::State::NotRun);
    QString notDone
        = notRun.isEmpty() ? QString() : u" "_s + tr("Not run: %1.").arg(RackSequence::toolNames(notRun));
    // Which tools the check skipped, and why: the firmware's break test cannot test them.
    for (const RackStep &step : steps) {
        if (step.state == RackStep::State::Skipped)
            notDone += u" "_s + step.message;
    }
    const bool check = sequence->mode() == RackSequence::Mode::Check;
    if (!m_recordFailure.isEmpty()) {
        const QString text = tr("A measurement could not be stored in the table, so the rack was stopped: %1")
                                 .arg(m_recordFailure)
            + notDone;
        m_result->setText(text);
        QMessageBox::warning(this, tr("The rack was stopped"), text);
    } else if (outcome.outcome == SessionResult::Outcome::ToolBroken) {
        warnBroken(outcome, notDone);
    } else if (!outcome.ok()) {
        // Stopped or failed in the middle of a tool's step, a change may be half done: the machine's word on
        // which tool it holds is not enough.
        const QList<int> failed = toolsIn(steps, RackStep::State::Failed);
        const QString look = failed.isEmpty() || !m_connection->isHalted() ? QString()
                                                                           : u"\n\n"_s
                + tr("The machine stopped during T%1's step: look which tool is in the spindle and that the "
                     "rack "
                     "holds the others before you Unlock, then measure the tool in the spindle.")
                      .arg(failed.first());
        m_result->setText(sentence(outcome.message) + notDone);
        QMessageBox::warning(this, check ? tr("The rack check failed") : tr("Measuring the rack failed"),
            sentence(outcome.message) + notDone + look);
    } else if (sequence->isCancelled()) {
        m_result->setText(sentence(outcome.message) + notDone);
    } else {
        const auto done = toolsIn(steps, check ? RackStep::State::Passed : RackStep::State::Measured).size();
        m_result->setText(check ? (done == 1 ? tr("Rack checked: 1 tool passed.")
                                             : tr("Rack checked: %1 tools passed.").arg(done))
                : done == 1     ? tr("Rack measured: 1 tool, its TLO recorded in the table.")
                                : tr("Rack measured: %1 tools, each TLO recorded in the table.").arg(done));
    }
}

void RackPanel::warnBroken(const SessionResult &outcome, const QString &notDone)
{
    const QString name
        = outcome.tool && *outcome.tool >= 0 ? u"T"_s + QString::number(*outcome.tool) : tr("The tool");
    m_result->setText(tr("%1 may be broken: the check stopped and the machine halted.").arg(name) + notDone);
    QMessageBox box(QMessageBox::Warning, tr("%1 may be broken").arg(name),
        tr("%1 may be broken. The rack check stopped there, and the machine has halted.").arg(name),
        QMessageBox::Ok, this);
    box.setObjectName(u"rackBrokenWarning"_s);
    // The machine's message says what it measured and to check the tool; what follows is the table's side.
    box.setInformativeText(outcome.message + u"\n\n"_s
        + tr("The table marks %1 until it is measured again: once it is checked or replaced and the machine "
             "unlocked (the strip's Unlock, Ctrl+Shift+U), measure it with Load Tool or Measure Rack.")
              .arg(name)
        + notDone);
    box.exec();
}

} // namespace Toffee
