// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/machine/machinedock.h"

#include <QGroupBox>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>

#include "serial/machine/machinecontroller.h"
#include "serial/machineconnection.h"
#include "ui/connection/connectionpanel.h"
#include "ui/machine/breaktestpanel.h"
#include "ui/machine/offseteditor.h"
#include "ui/machine/probepanel.h"
#include "ui/machine/tlopanel.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QGroupBox *group(const QString &title, QWidget *content)
{
    auto *box = new QGroupBox(title);
    auto *layout = new QVBoxLayout(box);
    // The box's margins only, not the panel's as well: at 1280×720 the break test's numbers are in view
    // without scrolling.
    if (content->layout())
        content->layout()->setContentsMargins(0, 0, 0, 0);
    layout->setContentsMargins(8, 6, 8, 6);
    layout->addWidget(content);
    return box;
}

} // namespace

MachineDock::MachineDock(MachineConnection *connection, ToolDocument *document, QWidget *parent)
    : QDockWidget(tr("Machine"), parent)
    , m_machine(connection)
    , m_connection(new ConnectionPanel(connection))
    , m_tlo(new TloPanel(connection, document))
    , m_probe(new ProbePanel(connection, document))
    , m_offsets(new OffsetEditor(connection, document))
    , m_breakTest(new BreakTestPanel(connection, document))
    , m_limits(new QLabel)
{
    setObjectName(u"machineDock"_s);
    auto *body = new QWidget;
    auto *layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    m_limits->setObjectName(u"firmwareLimitsLabel"_s);
    m_limits->setAccessibleName(tr("What the machine's firmware cannot do"));
    m_limits->setWordWrap(true);
    m_offsetsGroup = group(tr("Set the offset by hand"), m_offsets);
    m_breakTestGroup = group(tr("Tool break test"), m_breakTest);
    m_offsetsGroup->setObjectName(u"offsetsGroup"_s);
    m_breakTestGroup->setObjectName(u"breakTestGroup"_s);
    layout->addWidget(group(tr("Connection"), m_connection));
    layout->addWidget(m_limits);
    m_probeGroup = group(tr("Probe"), m_probe);
    layout->addWidget(m_probeGroup);
    layout->addWidget(m_offsetsGroup);
    layout->addWidget(m_breakTestGroup);
    layout->addStretch(1);
    connect(m_breakTest, &BreakTestPanel::unlockRequested, m_tlo, [this] { m_tlo->unlock(false); });
    // A probe measures the tool again: the last break test's verdict no longer holds.
    connect(m_probe, &ProbePanel::finished, m_breakTest, [this](const SessionResult &r) {
        if (r.ok())
            m_breakTest->clearResult();
    });
    auto *scroll = new QScrollArea;
    scroll->setWidget(body);
    // Wide enough for every panel's controls; only the height scrolls.
    scroll->setMinimumWidth(body->sizeHint().width() + scroll->verticalScrollBar()->sizeHint().width() + 4);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    setWidget(scroll);
    connect(connection, &MachineConnection::stateChanged, this, &MachineDock::showFirmwareLimits);
    showFirmwareLimits();
}

void MachineDock::setRecordingBlocked(const QString &why)
{
    for (QGroupBox *box : { m_probeGroup, m_offsetsGroup, m_breakTestGroup }) {
        box->setEnabled(why.isEmpty());
        box->setToolTip(why);
    }
}

void MachineDock::showFirmwareLimits()
{
    // Disconnected, nothing is known of the firmware: every panel shows, disabled.
    const bool connected = m_machine->state() == MachineConnection::State::Connected;
    const FirmwareInfo firmware = m_machine->firmware();
    const bool breakTest = !connected || firmware.hasBreakTest();
    const bool manualOffset = !connected || firmware.hasManualOffset();
    m_breakTestGroup->setVisible(breakTest);
    m_offsetsGroup->setVisible(manualOffset);
    if (!breakTest && !manualOffset)
        m_limits->setText(
            tr("%1: no break test (its M491.1 only re-measures) and no manual offset (it ignores "
               "M493.3).")
                .arg(firmware.description()));
    else if (!breakTest)
        m_limits->setText(tr("%1: no break test (Toffee cannot tell whether its M491.1 compares a tool with "
                             "its TLO).")
                              .arg(firmware.description()));
    else
        m_limits->clear();
    m_limits->setVisible(!breakTest || !manualOffset);
}

} // namespace Toffee
