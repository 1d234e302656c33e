// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/machine/probepanel.h"

#include <cmath>

#include <QGridLayout>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>

#include "model/clock.h"
#include "model/document/tooldocument.h"
#include "serial/machineconnection.h"
#include "ui/common/appearance.h"
#include "ui/common/appsettings.h"
#include "ui/machine/brokentool.h"

using namespace Qt::StringLiterals;

namespace Toffee {

ProbePanel::ProbePanel(MachineConnection *connection, ToolDocument *document, QWidget *parent)
    : QWidget(parent)
    , m_connection(connection)
    , m_document(document)
    , m_probe(new QPushButton(tr("Probe Current Tool"), this))
    , m_restore(new QPushButton(tr("Restore Known TLO"), this))
    , m_progress(new QProgressBar(this))
    , m_cancel(new QPushButton(tr("Cancel"), this))
    , m_result(new QLabel(this))
{
    m_probe->setObjectName(u"probeButton"_s);
    m_probe->setIcon(themeIcon(u"probe"_s));
    m_probe->setAccessibleName(tr("Probe the current tool on the tool setter"));
    // F5 belongs to the Machine menu's action, which runs this same probe: one key, one command.
    m_probe->setToolTip(tr("Measure the tool in the spindle on the tool setter (M491) — F5"));
    m_restore->setObjectName(u"restoreButton"_s);
    m_restore->setAccessibleName(tr("Restore the selected tool's known TLO"));
    m_restore->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_restore->setToolTip(
        tr("Make the selected tool active with the TLO measured before, without probing — Ctrl+R"));
    m_progress->setObjectName(u"probeProgress"_s);
    m_progress->setAccessibleName(tr("Machine busy"));
    m_progress->setRange(0, 0);
    m_progress->hide();
    m_cancel->setObjectName(u"cancelButton"_s);
    m_cancel->setIcon(themeIcon(u"stop"_s));
    m_cancel->setAccessibleName(tr("Stop the machine"));
    m_cancel->setShortcut(QKeySequence(Qt::Key_Escape));
    m_cancel->setToolTip(tr("Stop the machine now (Ctrl-X to the controller) — Esc"));
    m_cancel->hide();
    m_result->setObjectName(u"probeResultLabel"_s);
    m_result->setWordWrap(true);

    auto *grid = new QGridLayout(this);
    grid->addWidget(m_probe, 0, 0, 1, 2);
    grid->addWidget(m_restore, 1, 0, 1, 2);
    grid->addWidget(m_progress, 2, 0);
    grid->addWidget(m_cancel, 2, 1);
    grid->addWidget(m_result, 3, 0, 1, 2);

    connect(m_probe, &QPushButton::clicked, this, [this] { probe(); });
    connect(m_restore, &QPushButton::clicked, this, [this] { restore(); });
    connect(m_cancel, &QPushButton::clicked, this, &ProbePanel::cancel);
    connect(m_connection, &MachineConnection::stateChanged, this, &ProbePanel::updateState);
    // A result belongs to the connection it came on: connected again, the window says what became of it.
    connect(m_connection, &MachineConnection::stateChanged, this, [this](MachineConnection::State state) {
        if (state == MachineConnection::State::Connecting)
            setResult({});
    });
    connect(m_connection, &MachineConnection::busyChanged, this, &ProbePanel::updateState);
    connect(m_connection, &MachineConnection::haltedChanged, this, &ProbePanel::updateState);
    connect(m_connection, &MachineConnection::statusChanged, this, &ProbePanel::updateState);
    // The last probe's line is only true until the next operation changes the offsets.
    connect(m_connection, &MachineConnection::busyChanged, this, [this](bool busy) {
        if (busy)
            setResult({});
    });
    connect(m_document->model(), &QAbstractItemModel::dataChanged, this, &ProbePanel::updateState);
    updateState();
}

void ProbePanel::setSelectedTool(int number)
{
    m_selectedTool = number;
    updateState();
}

void ProbePanel::updateState()
{
    // An empty spindle: a probe would drive the spindle nose at the setter, and a restore would tell a tool
    // changer that a tool sitting in its slot is in the spindle.
    const bool empty = m_connection->activeTool() == Limits::kEmptySpindle;
    const bool ready = m_connection->canOperate() && !empty;
    m_probe->setEnabled(ready);
    const Tool *tool = m_document->table().find(m_selectedTool);
    m_restore->setEnabled(ready && tool && tool->measuredTlo);
    const QString emptyNote
        = empty ? tr("The spindle is empty: load a tool first (Rack ▸ Load).") : QString();
    explainDisabled(m_probe, emptyNote);
    explainDisabled(m_restore, emptyNote);
    m_restore->setText(
        tool && tool->measuredTlo ? tr("Restore T%1 TLO").arg(m_selectedTool) : tr("Restore Known TLO"));
    // A button's setText() replaces its shortcut with the text's mnemonic (none here): Ctrl+R goes back on.
    m_restore->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    const bool busy = m_connection->isBusy();
    m_progress->setVisible(busy);
    m_cancel->setVisible(busy);
    if (busy)
        m_progress->setFormat(m_connection->operation());
}

void ProbePanel::report(const SessionResult &result, const QString &title)
{
    if (result.ok())
        return;
    setResult(result.message);
    // Stopped because the operator quit: the window is gone, and no box pops up after it. The link went: the
    // window says so itself, and offers to reconnect.
    if (!window()->isVisible() || m_connection->linkLostDuringOperation())
        return;
    QMessageBox::warning(
        this, title, result.message + u"\n\n"_s + tr("Nothing was written to the tool table."));
}

void ProbePanel::probe(bool confirm)
{
    if (!m_connection->canOperate())
        return;
    // Pressed with nothing to measure (F5 with an empty spindle): said, not silently ignored.
    if (m_connection->activeTool() == Limits::kEmptySpindle)
        return report(SessionResult::failed(SessionResult::Outcome::Refused,
                          tr("The machine says no tool is in the spindle (T0), so there is nothing to probe. "
                             "Say which tool is in first (the table's context menu: Make Active).")),
            tr("Nothing to probe"));
    const QString name = m_connection->activeToolName();
    // A controller that keeps no reference (grblHAL): the first tool measured on this machine becomes it.
    const QString reference = m_connection->probeMakesReference() ? u"\n\n"_s
            + tr("This machine has no reference tool yet: %1 becomes it (TLO 0.000), and every tool measured "
                 "after it gets its length against %1's. Probe the tool you mean to keep as the reference.")
                  .arg(name)
                                                                  : QString();
    // A tool measured its own way (the table's Probing column) says how, before anything moves.
    const ProbePlan plan = m_connection->activeTool()
        ? m_document->table().probePlan(*m_connection->activeTool())
        : ProbePlan {};
    const QString how
        = plan.isPlain() ? QString() : u"\n\n"_s + tr("As its settings say: %1.").arg(plan.summary());
    if (confirm
        && QMessageBox::question(this, tr("Probe %1?").arg(name),
               tr("The machine will move: up to clearance, over the tool setter, then down until "
                  "%1 touches it. Keep hands clear.\n\nThe machine says %1 is in the spindle: the "
                  "measurement is recorded as %1's TLO.\n\nProbe now?")
                       .arg(name)
                   + how + reference
                   + brokenParagraph(brokenToolWarning(m_document, m_connection, BrokenToolAction::Probe)),
               QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
            != QMessageBox::Yes)
        return;
    setResult({});
    m_connection->probe([this](const SessionResult &r) {
        if (r.ok()) {
            const int number = r.tool.value_or(-1);
            auto recorded = r.recording ? m_document->record(*r.recording)
                                        : Result<void>(Error { tr("there is no tool in the spindle.") });
            // What the controller adds (grblHAL: "T1 is this machine's reference tool…") is said too.
            const QString said = r.message.isEmpty() ? QString() : u" "_s + r.message;
            setResult(recorded ? tr("T%1 measured: TLO %2, recorded in the table.")
                                     .arg(number)
                                     .arg(millimetres(r.tlo->tlo()))
                        + said
                               : tr("Measured TLO %1, but it could not be recorded: %2")
                                     .arg(millimetres(r.tlo->tlo()), recorded.error().message));
        }
        report(r, tr("Probing failed"));
        Q_EMIT finished(r);
    });
}

void ProbePanel::restore(bool confirm)
{
    if (!m_connection->canOperate() || m_connection->activeTool() == Limits::kEmptySpindle)
        return;
    // The table's TLO as the machine takes it: in millimetres, whatever the table's units.
    const auto tool = m_document->table().storedTlo(m_selectedTool);
    if (!tool)
        return;
    const int number = m_selectedTool;
    const double tlo = tool->tlo;
    const auto &offsets = m_connection->lastOffsets();
    // A TLO is the difference to the reference tool it was measured against: on a machine whose reference is
    // another (another machine, or one calibrated again since) it is simply wrong.
    const std::optional<double> machineReference
        = offsets && offsets->referenceMz && *offsets->referenceMz != 0.0 ? offsets->referenceMz
                                                                          : std::nullopt;
    if (tool->referenceMz && machineReference
        && std::fabs(*tool->referenceMz - *machineReference) > tool->sameWithin) {
        QMessageBox::warning(this, tr("T%1's TLO does not fit this machine's reference").arg(number),
            tr("T%1's TLO %2 was measured against a reference tool at MCS Z %3, but the machine's reference "
               "is now at MCS Z %4 (another machine's TLO, or the machine was calibrated again since). "
               "Restored, it would be off by %5.\n\nProbe T%1 instead.")
                .arg(number)
                .arg(millimetres(tlo), millimetres(*tool->referenceMz), millimetres(*machineReference),
                    millimetres(std::fabs(*tool->referenceMz - *machineReference))));
        return;
    }
    if (confirm) {
        // Restore trusts the operator about which tool is in the spindle: ask, by name, and say what the
        // machine does not know.
        QMessageBox box(QMessageBox::Question, tr("Restore T%1?").arg(number),
            tr("Is T%1 in the spindle now?").arg(number), QMessageBox::NoButton, this);
        box.setObjectName(u"restoreConfirmation"_s);
        QStringList details;
        details << tr("The machine will use T%1's TLO %2 (%3, %4) without probing. If another tool is in the "
                      "spindle, the next cut is off by the difference.")
                       .arg(number)
                       .arg(millimetres(tlo),
                           tool->source == TloSource::Manual       ? tr("set by hand")
                               : tool->source == TloSource::Pulled ? tr("read from the controller")
                                                                   : tr("measured"),
                           QLocale().toString(tool->measuredAt.toLocalTime(), QLocale::ShortFormat));
        if (!tool->referenceMz)
            details << tr("The table does not say which reference tool T%1's TLO was measured against: make "
                          "sure it is the reference the machine has now.")
                           .arg(number);
        if (offsets && !machineReference)
            details << tr(
                "The machine reports no reference tool MCS Z: a stored TLO is only right against the "
                "reference it was measured from.");
        // What makes a stored TLO doubtful, each named (the job preparation refuses all of them).
        if (tool->source == TloSource::Manual)
            details << tr("T%1's TLO was set by hand, not measured on the tool setter.").arg(number);
        if (tool->source == TloSource::Pulled)
            details << tr("T%1's TLO was read from the controller's table, not measured on the tool setter.")
                           .arg(number);
        if (tool->breakTestFailed)
            details << tr("T%1 failed its last break test.").arg(number);
        const QDateTime now = Clock::now();
        const int staleDays = AppSettings().staleAfterDays();
        if (Clock::isInFuture(tool->measuredAt, now))
            details << tr(
                "T%1's TLO is dated in the future (%2): a clock was wrong, and when it was measured "
                "is not known.")
                           .arg(number)
                           .arg(tool->measuredAt.toUTC().toString(Qt::ISODate));
        else if (tool->measuredAt.isValid() && tool->measuredAt.secsTo(now) > qint64(staleDays) * 24 * 3600)
            details << tr("T%1's TLO is %2 days old, older than the stale limit (%3 d): the cutter may have "
                          "worn or been changed since.")
                           .arg(number)
                           .arg(tool->measuredAt.secsTo(now) / (24 * 3600))
                           .arg(staleDays);
        details << tr("Sends: %1").arg(m_connection->session()->restoreCommand(number, tlo));
        box.setInformativeText(details.join(u"\n\n"_s));
        if (details.size() > 2)
            box.setIcon(QMessageBox::Warning);
        QPushButton *yes = box.addButton(tr("T%1 Is in the Spindle").arg(number), QMessageBox::AcceptRole);
        yes->setObjectName(u"restoreYesButton"_s);
        QPushButton *no = box.addButton(QMessageBox::Cancel);
        box.setDefaultButton(no);
        box.exec();
        if (box.clickedButton() != yes)
            return;
    }
    m_connection->restoreTlo(number, tlo, [this, number](const SessionResult &r) {
        if (r.recording)
            (void)m_document->record(*r.recording); // the history's restore; the table already holds the TLO
        if (r.ok())
            setResult(tr("T%1 is active with TLO %2.").arg(number).arg(millimetres(r.tlo->tlo())));
        report(r, tr("Restoring failed"));
        Q_EMIT finished(r);
    });
}

void ProbePanel::cancel()
{
    m_connection->stop();
}

void ProbePanel::setResult(const QString &text)
{
    m_result->setText(text);
    fitWrappedLabel(m_result, m_result->width());
}

void ProbePanel::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    const QMargins margins = layout() ? layout()->contentsMargins() : QMargins();
    fitWrappedLabel(m_result, width() - margins.left() - margins.right());
}

} // namespace Toffee
