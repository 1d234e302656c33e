// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/machine/breaktestpanel.h"

#include <cmath>

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>

#include "model/document/tooldocument.h"
#include "serial/machineconnection.h"
#include "ui/common/appearance.h"
#include "ui/common/appsettings.h"
#include "ui/machine/brokentool.h"

using namespace Qt::StringLiterals;

namespace Toffee {

BreakTestPanel::BreakTestPanel(MachineConnection *connection, ToolDocument *document, QWidget *parent)
    : QWidget(parent)
    , m_connection(connection)
    , m_document(document)
    , m_tolerance(new QDoubleSpinBox(this))
    , m_run(new QPushButton(tr("Run Break Test"), this))
    , m_old(new QLabel(u"—"_s, this))
    , m_new(new QLabel(u"—"_s, this))
    , m_difference(new QLabel(u"—"_s, this))
    , m_verdict(new QLabel(this))
{
    // The firmware halts under 0.02 mm: the field cannot hold less, so such a value is never sent.
    m_tolerance->setObjectName(u"toleranceSpin"_s);
    m_tolerance->setAccessibleName(tr("Break-test tolerance in millimetres"));
    // Below the machine's minimum the field still takes what is typed, so that Run can refuse it with the
    // reason; a field that quietly turned 0.01 into 0.02 tested against a tolerance nobody chose.
    m_tolerance->setRange(0.001, MachineController::kMaxOffset);
    m_tolerance->setDecimals(3);
    m_tolerance->setSingleStep(0.01);
    m_tolerance->setSuffix(u" mm"_s);
    m_tolerance->setCorrectionMode(QAbstractSpinBox::CorrectToNearestValue);
    takeWheelOnlyWhenFocused(m_tolerance);
    m_tolerance->setToolTip(tr("How far the new measurement may differ from the stored TLO; at least %1 mm, "
                               "%2 mm by default.")
                                .arg(MachineController::kMinTolerance)
                                .arg(MachineController::kDefaultTolerance));
    const double remembered = AppSettings().breakTestTolerance();
    m_tolerance->setValue(
        MachineController::validateTolerance(remembered) ? remembered : MachineController::kDefaultTolerance);
    m_run->setObjectName(u"runBreakTestButton"_s);
    m_run->setIcon(themeIcon(u"breaktest"_s));
    m_run->setAccessibleName(tr("Run the tool break test"));
    // F6 belongs to the Machine menu's Break Test, which runs this same test.
    m_run->setToolTip(tr("Re-measure the tool and compare it with its stored TLO (M491.1) — F6"));
    for (auto [label, name] : { std::pair { m_old, u"breakOldLabel"_s },
             std::pair { m_new, u"breakNewLabel"_s }, std::pair { m_difference, u"breakDifferenceLabel"_s },
             std::pair { m_verdict, u"breakVerdictLabel"_s } }) {
        label->setObjectName(name);
        label->setAccessibleName(name);
    }
    m_verdict->setWordWrap(true);

    auto *form = new QFormLayout(this);
    form->addRow(tr("Tolerance:"), m_tolerance);
    form->addRow(m_run);
    form->addRow(tr("Stored TLO:"), m_old);
    form->addRow(tr("Measured TLO:"), m_new);
    form->addRow(tr("Difference:"), m_difference);
    form->addRow(m_verdict);

    connect(m_run, &QPushButton::clicked, this, [this] { run(); });
    connect(m_tolerance, &QDoubleSpinBox::valueChanged, this, [](double v) {
        if (MachineController::validateTolerance(v)) // only a tolerance the machine takes is remembered
            AppSettings().setBreakTestTolerance(v);
    });
    connect(m_connection, &MachineConnection::stateChanged, this, &BreakTestPanel::updateState);
    connect(m_connection, &MachineConnection::busyChanged, this, &BreakTestPanel::updateState);
    connect(m_connection, &MachineConnection::haltedChanged, this, &BreakTestPanel::updateState);
    connect(m_connection, &MachineConnection::statusChanged, this, &BreakTestPanel::updateState);
    // A verdict is about one tool: it goes when another is in the spindle or the tool is measured again.
    connect(m_connection, &MachineConnection::statusChanged, this, [this](const MachineStatus &status) {
        if (status.tool && m_testedTool >= 0 && *status.tool != m_testedTool)
            clearResult();
    });
    connect(m_connection, &MachineConnection::stateChanged, this, &BreakTestPanel::clearResult);
    updateState(); // disabled until connected, from the first picture
}

void BreakTestPanel::clearResult()
{
    for (QLabel *label : { m_old, m_new, m_difference })
        label->setText(u"—"_s);
    m_verdict->clear();
    m_verdict->setStyleSheet({});
}

double BreakTestPanel::tolerance() const
{
    return m_tolerance->value();
}

void BreakTestPanel::updateState()
{
    const bool empty = m_connection->activeTool() == Limits::kEmptySpindle;
    m_run->setEnabled(m_connection->canOperate() && !empty);
    explainDisabled(m_run, empty ? tr("The spindle is empty: load a tool first (Rack ▸ Load).") : QString());
}

QString BreakTestPanel::referenceWarning() const
{
    const auto tool = m_connection->activeTool();
    if (!tool || *tool < 0)
        return tr("The machine reports no tool in the spindle.");
    const auto stored = m_document->table().storedTlo(*tool); // in millimetres, as the machine's
    const auto &offsets = m_connection->lastOffsets();
    const std::optional<double> machine = offsets ? std::optional(offsets->tlo()) : std::nullopt;
    if (!stored)
        return tr("T%1 has no TLO in the table: the test compares against whatever TLO the machine holds%2, "
                  "which may not be T%1's.")
            .arg(*tool)
            .arg(machine ? u" ("_s + millimetres(*machine) + u')' : QString());
    if (machine && std::fabs(*machine - stored->tlo) > stored->sameWithin)
        return tr(
            "The machine holds TLO %1 but the table holds %2 for T%3: Toffee sets the table's %2 first, "
            "and the machine compares the tool with it.")
            .arg(millimetres(*machine), millimetres(stored->tlo))
            .arg(*tool);
    if (stored->source == TloSource::Pulled)
        return tr(
            "T%1's TLO %2 was read from the controller's table (%3), not measured: if that value is not "
            "the tool's real length, the test reports the tool broken.")
            .arg(*tool)
            .arg(millimetres(stored->tlo),
                QLocale().toString(stored->measuredAt.toLocalTime(), QLocale::ShortFormat));
    if (stored->source == TloSource::Manual)
        return tr("T%1's TLO %2 was set by hand (%3), not measured: if that value is not the tool's real "
                  "length, the test reports the tool broken and halts the machine.")
            .arg(*tool)
            .arg(millimetres(stored->tlo),
                QLocale().toString(stored->measuredAt.toLocalTime(), QLocale::ShortFormat));
    return {};
}

void BreakTestPanel::run(bool confirm)
{
    if (!m_connection->canOperate() || m_connection->activeTool() == Limits::kEmptySpindle)
        return;
    m_tolerance->interpretText(); // what is typed counts
    const double tolerance = m_tolerance->value();
    if (auto valid = MachineController::validateTolerance(tolerance); !valid) {
        QMessageBox::warning(this, tr("The break test did not run"), valid.error().message);
        m_tolerance->setFocus();
        m_tolerance->selectAll();
        return;
    }
    const auto tool = m_connection->activeTool();
    const QString name = m_connection->activeToolName();
    if (confirm) {
        QMessageBox box(QMessageBox::Question, tr("Break-test %1?").arg(name),
            tr("The machine will move to the tool setter and measure %1 again, then compare it with its "
               "TLO (tolerance %2). Keep hands clear.")
                .arg(name, millimetres(tolerance)),
            QMessageBox::Yes | QMessageBox::Cancel, this);
        box.setObjectName(u"breakTestConfirmation"_s);
        box.setDefaultButton(QMessageBox::Cancel);
        // Told before the machine moves, not after it halts.
        QStringList warnings;
        for (const QString &w : { brokenToolWarning(m_document, m_connection, BrokenToolAction::BreakTest),
                 referenceWarning() }) {
            if (!w.isEmpty())
                warnings << w;
        }
        if (!warnings.isEmpty()) {
            box.setIcon(QMessageBox::Warning);
            box.setInformativeText(warnings.join(u"\n\n"_s));
        }
        if (box.exec() != QMessageBox::Yes)
            return;
    }
    // Whether the TLO compared against was set by hand, as it was before the verdict is recorded.
    const auto stored = tool ? m_document->table().storedTlo(*tool) : std::nullopt;
    const bool handSet = stored && stored->source == TloSource::Manual;
    // The firmware compares with the TLO in force: the table's for this tool (in millimetres), set first
    // when the machine has another (after selecting a tool it still has the previous tool's).
    const std::optional<double> storedTlo = stored ? std::optional(stored->tlo) : std::nullopt;
    const bool started = m_connection->breakTest(
        tolerance,
        [this](const SessionResult &r) {
            // A broken tool is marked in the table (and its file, once saved) until it is probed again.
            if (r.recording)
                (void)m_document->record(*r.recording);
            showResult(r);
            Q_EMIT finished(r);
        },
        storedTlo);
    if (started) {
        m_verdict->clear();
        m_comparedWithHandSet = handSet;
        m_testedTool = tool.value_or(-1);
    }
}

void BreakTestPanel::showResult(const SessionResult &r)
{
    if (r.breakTest) {
        m_old->setText(millimetres(r.breakTest->oldTlo));
        m_new->setText(millimetres(r.breakTest->newTlo));
        m_difference->setText(millimetres(std::fabs(r.breakTest->newTlo - r.breakTest->oldTlo)));
    }
    if (r.outcome == SessionResult::Outcome::ToolBroken) {
        m_verdict->setText(r.tool && *r.tool >= 0 ? tr("T%1: BROKEN TOOL").arg(*r.tool) : tr("BROKEN TOOL"));
        m_verdict->setStyleSheet(u"color: white; background: #c01c28; font-weight: bold; padding: 4px;"_s);
        raiseBrokenAlarm(r);
        return;
    }
    m_verdict->setStyleSheet({});
    if (r.ok()) {
        m_verdict->setText(r.tool && *r.tool >= 0
                ? tr("T%1 OK: within %2.").arg(*r.tool).arg(millimetres(r.tolerance))
                : tr("Tool OK: within %1.").arg(millimetres(r.tolerance)));
        return;
    }
    m_verdict->setText(r.message);
    // Not after the operator stopped it to quit; nor when the link went, which the window says itself and
    // offers to reconnect.
    if (window()->isVisible() && !m_connection->linkLostDuringOperation())
        QMessageBox::warning(this, tr("The break test did not run"), r.message);
}

void BreakTestPanel::raiseBrokenAlarm(const SessionResult &r)
{
    const QString name = r.tool && *r.tool >= 0 ? u"T"_s + QString::number(*r.tool) : tr("The tool");
    // The Carvera's firmware halts on a broken tool; grblHAL, whose test is Toffee's, is left stopped and
    // lifted but not halted: the box says what the machine did, and offers Unlock only when there is a halt.
    const bool halted = m_connection->isHalted();
    QMessageBox box(QMessageBox::Critical, tr("Broken tool"),
        halted
            ? tr("%1 may be broken. The machine has halted, and the table marks %1 until it is probed again.")
                  .arg(name)
            : tr("%1 may be broken. The machine is stopped and lifted (not halted), and the table marks %1 "
                 "until it is probed again.")
                  .arg(name),
        QMessageBox::NoButton, this);
    box.setObjectName(u"brokenToolAlarm"_s);
    // A TLO set by hand that was not the tool's length looks exactly like a broken tool: say which it may be.
    box.setInformativeText(m_comparedWithHandSet ? r.message + u"\n\n"_s
                + tr(
                    "The TLO it was compared against was set by hand, not measured: if that value was not "
                    "the "
                    "tool's real length, the tool may be whole. Look at the tool before you replace it, then "
                    "probe it.")
                                                 : r.message);
    if (!halted) {
        box.addButton(QMessageBox::Ok);
        box.exec();
        return;
    }
    QPushButton *unlock = box.addButton(tr("Unlock"), QMessageBox::AcceptRole);
    unlock->setObjectName(u"alarmUnlockButton"_s);
    QPushButton *leave = box.addButton(tr("Leave Halted"), QMessageBox::RejectRole);
    leave->setObjectName(u"alarmLeaveHaltedButton"_s);
    // Releasing a halted machine with a suspect tool in the spindle is never what a reflex Enter or Esc does.
    box.setDefaultButton(leave);
    box.setEscapeButton(leave);
    box.exec();
    if (box.clickedButton() == unlock)
        Q_EMIT unlockRequested(); // the one unlock flow, the strip's
}

} // namespace Toffee
