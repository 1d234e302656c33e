// SPDX-License-Identifier: GPL-3.0-or-later
#include "tlopanel.h"

#include <QFormLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

#include "appearance.h"
#include "machineconnection.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QLabel *valueLabel(QWidget *parent, const QString &name, const QString &accessible)
{
    auto *label = new QLabel(parent);
    label->setObjectName(name);
    label->setAccessibleName(accessible);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

} // namespace

TloPanel::TloPanel(MachineConnection *connection, QWidget *parent)
    : QWidget(parent)
    , m_connection(connection)
    , m_state(valueLabel(this, u"machineStateLabel"_s, tr("Machine state")))
    , m_tool(valueLabel(this, u"activeToolLabel"_s, tr("Active tool")))
    , m_reference(valueLabel(this, u"referenceMzLabel"_s, tr("Reference tool MCS Z")))
    , m_current(valueLabel(this, u"currentMzLabel"_s, tr("Current tool MCS Z")))
    , m_tlo(valueLabel(this, u"tloLabel"_s, tr("Tool length offset")))
    , m_unlock(new QPushButton(tr("Unlock"), this))
{
    QFont big = m_tlo->font();
    big.setPointSizeF(big.pointSizeF() * 1.6);
    big.setBold(true);
    m_tlo->setFont(big);
    m_unlock->setObjectName(u"unlockButton"_s);
    m_unlock->setIcon(themeIcon(u"unlock"_s));
    m_unlock->setAccessibleName(tr("Unlock the machine"));
    // Ctrl+Shift+U belongs to the Machine menu's Unlock, which runs this same unlock.
    m_unlock->setToolTip(tr("Clear the halt ($X) — Ctrl+Shift+U"));
    m_unlock->hide();

    auto *form = new QFormLayout(this);
    form->addRow(tr("State:"), m_state);
    form->addRow(tr("Active tool:"), m_tool);
    form->addRow(tr("Reference MCS Z:"), m_reference);
    form->addRow(tr("Current MCS Z:"), m_current);
    form->addRow(tr("TLO:"), m_tlo);
    form->addRow(m_unlock);

    connect(m_connection, &MachineConnection::statusChanged, this, &TloPanel::showStatus);
    connect(m_connection, &MachineConnection::offsetsChanged, this, &TloPanel::showOffsets);
    connect(m_connection, &MachineConnection::stateChanged, this, [this](MachineConnection::State s) {
        if (s != MachineConnection::State::Connected)
            clear();
    });
    connect(m_unlock, &QPushButton::clicked, this, &TloPanel::unlock);
    connect(&m_staleTimer, &QTimer::timeout, this, &TloPanel::checkStale);
    m_staleTimer.start(500);
    clear();
}

void TloPanel::clear()
{
    m_state->setText(m_connection->state() == MachineConnection::State::Connecting ? tr("Connecting…")
                                                                                   : tr("Not connected"));
    for (QLabel *l : { m_tool, m_reference, m_current, m_tlo })
        l->setText(u"—"_s);
    m_unlock->hide();
    m_stale = true;
}

void TloPanel::showStatus(const MachineStatus &status)
{
    m_stale = false;
    QString state = status.state;
    if (status.haltReason)
        state = tr("%1 — halted: %2").arg(status.state, haltReasonName(*status.haltReason));
    m_state->setText(state);
    QPalette palette = m_state->palette();
    palette.setColor(QPalette::WindowText,
        status.isAlarm() ? QColor(0xc0, 0x1c, 0x28) : this->palette().color(QPalette::WindowText));
    m_state->setPalette(palette);
    m_unlock->setVisible(status.isAlarm());
    if (status.tool)
        m_tool->setText(u"T"_s + QString::number(*status.tool));
    if (status.tlo)
        m_tlo->setText(millimetres(*status.tlo));
}

void TloPanel::showOffsets(const TloReading &offsets, int tool)
{
    m_reference->setText(millimetres(offsets.referenceMz));
    m_current->setText(millimetres(offsets.currentMz));
    m_tlo->setText(millimetres(offsets.tlo()));
    if (tool >= 0)
        m_tool->setText(u"T"_s + QString::number(tool));
}

void TloPanel::checkStale()
{
    if (m_connection->state() != MachineConnection::State::Connected)
        return;
    const bool stale = m_connection->isStatusStale();
    if (stale && !m_stale)
        m_state->setText(tr("%1 (stale: no status report)").arg(m_state->text()));
    m_stale = stale;
    for (QLabel *l : { m_state, m_tool, m_reference, m_current, m_tlo })
        l->setEnabled(!stale);
}

void TloPanel::unlock()
{
    if (!m_connection->beginOperation(tr("Unlock")))
        return;
    m_connection->session()->unlock([this](const SessionResult &r) {
        m_connection->endOperation(r);
        if (!r.ok())
            QMessageBox::warning(this, tr("Unlock failed"), r.message);
    });
}

} // namespace Toffee
