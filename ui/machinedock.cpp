// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/machinedock.h"

#include <QGroupBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>

#include "serial/machinesession.h"
#include "ui/breaktestpanel.h"
#include "ui/connectionpanel.h"
#include "ui/offseteditor.h"
#include "ui/probepanel.h"
#include "ui/tlopanel.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QGroupBox *group(const QString &title, QWidget *content)
{
    auto *box = new QGroupBox(title);
    auto *layout = new QVBoxLayout(box);
    layout->addWidget(content);
    return box;
}

} // namespace

MachineDock::MachineDock(MachineConnection *connection, ToolDocument *document, QWidget *parent)
    : QDockWidget(tr("Machine"), parent)
    , m_connection(new ConnectionPanel(connection))
    , m_tlo(new TloPanel(connection, document))
    , m_probe(new ProbePanel(connection, document))
    , m_offsets(new OffsetEditor(connection, document))
    , m_breakTest(new BreakTestPanel(connection, document))
{
    setObjectName(u"machineDock"_s);
    auto *body = new QWidget;
    auto *layout = new QVBoxLayout(body);
    layout->addWidget(group(tr("Connection"), m_connection));
    layout->addWidget(group(tr("Probe"), m_probe));
    layout->addWidget(group(tr("Set the offset by hand"), m_offsets));
    layout->addWidget(group(tr("Tool break test"), m_breakTest));
    layout->addStretch(1);
    connect(m_breakTest, &BreakTestPanel::unlockRequested, m_tlo, &TloPanel::unlock);
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
}

} // namespace Toffee
