// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/machine/toolchangewait.h"

#include <QMessageBox>
#include <QPushButton>

#include "serial/machineconnection.h"

using namespace Qt::StringLiterals;

namespace Toffee {

ToolChangeWait::ToolChangeWait(MachineConnection *connection, QWidget *window)
    : QObject(window)
    , m_connection(connection)
    , m_window(window)
{
    connect(m_connection, &MachineConnection::waitingForOperator, this, &ToolChangeWait::waiting);
    connect(m_connection, &MachineConnection::toolChangeFinished, this, [this] {
        if (m_box)
            m_box->deleteLater();
    });
}

void ToolChangeWait::waiting(int tool, int limitMs)
{
    if (m_box)
        m_box->deleteLater();
    const bool here = m_connection->resumesFromHere();
    const int minutes = std::max(1, limitMs / 60000);
    m_box = new QMessageBox(QMessageBox::Information, tr("Put T%1 in the Spindle").arg(tool),
        here
            ? tr("The machine waits for T%1. Put it in the spindle, then press cycle start on the machine or "
                 "Continue here; it is then measured.")
                  .arg(tool)
            : tr("The machine waits for T%1. Put it in the spindle, then press the machine's button; it is "
                 "then measured.")
                  .arg(tool),
        QMessageBox::NoButton, m_window);
    m_box->setObjectName(u"toolChangeWaitBox"_s);
    m_box->setInformativeText(
        tr("The change waits up to %1 min; End the Change stops it on the machine and records nothing.")
            .arg(minutes));
    if (here) {
        QPushButton *go = m_box->addButton(tr("Continue"), QMessageBox::AcceptRole);
        go->setObjectName(u"toolChangeContinueButton"_s);
        connect(go, &QPushButton::clicked, m_connection, &MachineConnection::resumeToolChange);
    }
    QPushButton *end = m_box->addButton(tr("End the Change"), QMessageBox::RejectRole);
    end->setObjectName(u"toolChangeEndButton"_s);
    connect(end, &QPushButton::clicked, m_connection,
        [this] { m_connection->endToolChange(tr("The operator ended the change in the window.")); });
    m_box->setWindowModality(Qt::WindowModal);
    m_box->open();
}

} // namespace Toffee
