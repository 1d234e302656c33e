// SPDX-License-Identifier: GPL-3.0-or-later
// Load Tool: a change to one tool (asked about first, naming what moves), measured or given its stored TLO,
// and recorded; its Cancel, and the sequence's.
#include "model/clock.h"
#include "ui/rack/rackpanel.h"

#include <QCheckBox>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>

#include "model/document/tooldocument.h"
#include "model/job/toolfacts.h"
#include "model/numberformat.h"
#include "model/timetext.h"
#include "serial/machineconnection.h"
#include "ui/common/appsettings.h"

using namespace Qt::StringLiterals;

namespace Toffee {

std::optional<double> RackPanel::machineReference() const
{
    // The stock firmware reports no MCS Z.
    const auto &offsets = m_connection->lastOffsets();
    if (!offsets || !offsets->referenceMz || *offsets->referenceMz == 0.0)
        return std::nullopt;
    return offsets->referenceMz;
}

QString RackPanel::loadQuestion(int tool, const std::optional<double> &stored, const QString &why) const
{
    const auto spindle = m_connection->activeTool();
    const bool fromRack = spindle && *spindle >= 0 && m_rack->contains(*spindle);
    const bool toRack = m_rack->contains(tool);
    QStringList text;
    if (tool == Limits::kEmptySpindle) {
        text << (fromRack
                ? tr("The machine puts T%1 back in the rack; the spindle stays empty.").arg(*spindle)
                : tr("Take the tool out of the spindle when the machine asks; the spindle stays "
                     "empty."));
    } else if (spindle == tool) {
        text << tr("T%1 is in the spindle already: the machine measures it again on the tool setter.")
                    .arg(tool);
    } else if (fromRack && toRack) {
        text << tr("The machine puts T%1 back in the rack, picks T%2 and measures it on the tool setter.")
                    .arg(*spindle)
                    .arg(tool);
    } else {
        if (fromRack)
            text << tr("The machine puts T%1 back in the rack.").arg(*spindle);
        else if (spindle && *spindle >= 0)
            text << tr("T%1 has no slot in the rack: take it out of the spindle when the machine asks.")
                        .arg(*spindle);
        if (toRack)
            text << tr("The machine picks T%1 from the rack and measures it on the tool setter.").arg(tool);
        else if (stored)
            text << tr(
                "T%1 has no slot in the rack: put it in the spindle when the machine asks. The machine "
                "then takes its stored TLO %2 (measured %3) and does not probe it.")
                        .arg(tool)
                        .arg(millimetres(*stored), ageText(m_document->table().find(tool)->measuredAt));
        else
            text << tr(
                "T%1 has no slot in the rack: put it in the spindle when the machine asks. The machine "
                "then measures it on the tool setter.")
                        .arg(tool);
    }
    if (!why.isEmpty())
        text << tr("The stored TLO is not used: %1").arg(why);
    text << tr("Keep clear of the machine.");
    return text.join(u"\n\n"_s);
}

void RackPanel::loadTool(int tool, bool confirm)
{
    if (!m_connection->canOperate() || !m_rack || m_sequence || m_loading)
        return;
    std::optional<double> stored;
    QString why;
    // A rack tool is always measured: the firmware calibrates it at every change, whatever it is told.
    if (tool >= 0 && m_useStored->isChecked() && !m_rack->contains(tool)
        && m_connection->activeTool() != tool) {
        const auto facts = factsFromTable(m_document->table());
        const auto restorable = restorableTlo(tool, facts.value(tool), Clock::now(),
            AppSettings().staleAfterDays(), machineReference(), ReferenceCheck::Required);
        if (restorable)
            stored = restorable.value();
        else
            why = restorable.error().message;
    }
    const QString title
        = tool == Limits::kEmptySpindle ? tr("Empty the spindle?") : tr("Load T%1?").arg(tool);
    if (confirm
        && QMessageBox::question(this, title, loadQuestion(tool, stored, why),
               QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
            != QMessageBox::Yes)
        return;
    const QString age = stored ? ageText(m_document->table().find(tool)->measuredAt) : QString();
    m_result->clear();
    m_loading = true;
    showProgress(true);
    m_progress->setRange(0, 0);
    QPointer<RackPanel> self(this);
    const bool started = m_connection->changeTool(
        tool,
        [self, tool, stored, age](const SessionResult &r) {
            if (!self)
                return;
            self->m_loading = false;
            self->showProgress(false);
            self->loadFinished(r, tool, stored ? std::optional(age) : std::nullopt);
        },
        stored);
    if (!started) {
        m_loading = false;
        showProgress(false);
    }
}

void RackPanel::loadFinished(const SessionResult &r, int tool, const std::optional<QString> &storedAge)
{
    if (!r.ok()) {
        m_result->setText(r.message);
        QMessageBox::warning(this, tr("Loading T%1 failed").arg(tool),
            r.message + u"\n\n"_s + tr("Nothing was written to the tool table."));
        return;
    }
    // The last sequence's word on this tool no longer holds: it was changed to and measured (or given a TLO).
    m_results.remove(tool);
    refreshTable();
    const auto recorded = r.recording ? m_document->record(*r.recording) : Result<void> {};
    const QString tlo = r.tlo ? millimetres(r.tlo->tlo()) : tr("unknown");
    if (!recorded)
        m_result->setText(tr("T%1 is in the spindle with TLO %2, but it could not be recorded: %3")
                              .arg(tool)
                              .arg(tlo, recorded.error().message));
    else if (tool == Limits::kEmptySpindle)
        m_result->setText(tr("The spindle is empty."));
    else if (storedAge)
        m_result->setText(
            tr("T%1 takes its stored TLO %2 (measured %3); not probed.").arg(tool).arg(tlo, *storedAge));
    else
        m_result->setText(tr("T%1 measured: TLO %2, recorded in the table.").arg(tool).arg(tlo));
}

void RackPanel::cancel()
{
    if (m_sequence) {
        // The tool being changed or measured finishes: a machine stopped halfway through a change holds a
        // tool in neither the rack nor a known state.
        m_sequence->cancel();
        m_cancel->setText(tr("Stopping after this tool…"));
        m_cancel->setEnabled(false);
        return;
    }
    if (m_loading
        && QMessageBox::question(this, tr("Stop the machine?"),
               tr("Stop the machine now? It halts; Unlock afterwards."),
               QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
            == QMessageBox::Yes)
        m_connection->stop();
}

} // namespace Toffee
