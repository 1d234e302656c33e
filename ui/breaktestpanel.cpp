// SPDX-License-Identifier: GPL-3.0-or-later
#include "breaktestpanel.h"

#include <cmath>

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

#include "appearance.h"
#include "appsettings.h"
#include "machineconnection.h"

using namespace Qt::StringLiterals;

namespace Toffee {

BreakTestPanel::BreakTestPanel(MachineConnection *connection, QWidget *parent)
    : QWidget(parent)
    , m_connection(connection)
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
    m_tolerance->setRange(0.001, 5.0);
    m_tolerance->setDecimals(3);
    m_tolerance->setSingleStep(0.01);
    m_tolerance->setSuffix(u" mm"_s);
    m_tolerance->setCorrectionMode(QAbstractSpinBox::CorrectToNearestValue);
    m_tolerance->setToolTip(tr("How far the new measurement may differ from the stored TLO; at least %1 mm, "
                               "%2 mm by default.")
                                .arg(MachineSession::kMinTolerance)
                                .arg(MachineSession::kDefaultTolerance));
    const double remembered = AppSettings().breakTestTolerance();
    m_tolerance->setValue(
        MachineSession::validateTolerance(remembered) ? remembered : MachineSession::kDefaultTolerance);
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
        if (MachineSession::validateTolerance(v)) // only a tolerance the machine takes is remembered
            AppSettings().setBreakTestTolerance(v);
    });
    connect(m_connection, &MachineConnection::stateChanged, this, &BreakTestPanel::updateState);
    connect(m_connection, &MachineConnection::busyChanged, this, &BreakTestPanel::updateState);
    updateState();
}

double BreakTestPanel::tolerance() const
{
    return m_tolerance->value();
}

void BreakTestPanel::updateState()
{
    m_run->setEnabled(
        m_connection->state() == MachineConnection::State::Connected && !m_connection->isBusy());
}

void BreakTestPanel::run(bool confirm)
{
    if (m_connection->state() != MachineConnection::State::Connected || m_connection->isBusy())
        return;
    m_tolerance->interpretText(); // what is typed counts
    const double tolerance = m_tolerance->value();
    if (auto valid = MachineSession::validateTolerance(tolerance); !valid) {
        QMessageBox::warning(this, tr("The break test did not run"), valid.error().message);
        m_tolerance->setFocus();
        m_tolerance->selectAll();
        return;
    }
    if (confirm
        && QMessageBox::question(this, tr("Run the break test?"),
               tr("The machine will move to the tool setter and measure the tool again, then "
                  "compare it with its stored TLO (tolerance %1 mm). Keep hands clear.")
                   .arg(tolerance),
               QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
            != QMessageBox::Yes)
        return;
    if (!m_connection->beginOperation(tr("Break test…")))
        return;
    m_verdict->clear();
    m_connection->session()->breakTest(tolerance, [this](const SessionResult &r) {
        m_connection->endOperation(r);
        showResult(r);
        Q_EMIT finished(r);
    });
}

void BreakTestPanel::showResult(const SessionResult &r)
{
    if (r.breakTest) {
        m_old->setText(millimetres(r.breakTest->oldTlo));
        m_new->setText(millimetres(r.breakTest->newTlo));
        m_difference->setText(millimetres(std::fabs(r.breakTest->newTlo - r.breakTest->oldTlo)));
    }
    if (r.outcome == SessionResult::Outcome::ToolBroken) {
        m_verdict->setText(tr("BROKEN TOOL"));
        m_verdict->setStyleSheet(u"color: white; background: #c01c28; font-weight: bold; padding: 4px;"_s);
        raiseBrokenAlarm(r);
        return;
    }
    m_verdict->setStyleSheet({});
    if (r.ok()) {
        m_verdict->setText(tr("Tool OK: within %1 mm.").arg(r.tolerance));
        return;
    }
    m_verdict->setText(r.message);
    QMessageBox::warning(this, tr("The break test did not run"), r.message);
}

void BreakTestPanel::raiseBrokenAlarm(const SessionResult &r)
{
    QMessageBox box(QMessageBox::Critical, tr("Broken tool"),
        tr("The tool may be broken. The machine has halted."), QMessageBox::NoButton, this);
    box.setObjectName(u"brokenToolAlarm"_s);
    box.setInformativeText(r.message);
    QPushButton *unlock = box.addButton(tr("Unlock"), QMessageBox::AcceptRole);
    unlock->setObjectName(u"alarmUnlockButton"_s);
    QPushButton *leave = box.addButton(tr("Leave Halted"), QMessageBox::RejectRole);
    leave->setObjectName(u"alarmLeaveHaltedButton"_s);
    // Releasing a halted machine with a suspect tool in the spindle is never what a reflex Enter or Esc does.
    box.setDefaultButton(leave);
    box.setEscapeButton(leave);
    box.exec();
    if (box.clickedButton() != unlock || !m_connection->beginOperation(tr("Unlock")))
        return;
    m_connection->session()->unlock([this](const SessionResult &u) {
        m_connection->endOperation(u);
        if (!u.ok())
            QMessageBox::warning(this, tr("Unlock failed"), u.message);
    });
}

} // namespace Toffee
