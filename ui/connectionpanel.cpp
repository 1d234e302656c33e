// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/connectionpanel.h"

#include <QComboBox>
#include <QGridLayout>
#include <QPushButton>
#include <QSerialPortInfo>

#include "serial/machineconnection.h"
#include "ui/appearance.h"
#include "ui/appsettings.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {
const auto kEmulator = u"emulator"_s;
}

ConnectionPanel::ConnectionPanel(MachineConnection *connection, QWidget *parent)
    : QWidget(parent)
    , m_connection(connection)
    , m_port(new QComboBox(this))
    , m_baud(new QComboBox(this))
    , m_refresh(new QPushButton(tr("Refresh"), this))
    , m_connect(new QPushButton(this))
{
    m_port->setObjectName(u"portCombo"_s);
    m_port->setAccessibleName(tr("Machine port"));
    m_port->setEditable(true); // a pty or a port the system does not list can be typed in
    m_port->setMinimumContentsLength(16);
    m_baud->setObjectName(u"baudCombo"_s);
    m_baud->setAccessibleName(tr("Baud rate"));
    for (int baud : { 9600, 19200, 38400, 57600, 115200, 230400, 250000 })
        m_baud->addItem(QString::number(baud), baud);
    m_refresh->setObjectName(u"refreshPortsButton"_s);
    m_refresh->setAccessibleName(tr("Refresh the list of ports"));
    m_connect->setObjectName(u"connectButton"_s);
    m_connect->setIcon(themeIcon(u"connect"_s));

    // Two rows, so that the panel stays narrow in every language: the port, then the rest.
    auto *layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_port, 0, 0, 1, 3);
    layout->addWidget(m_baud, 1, 0);
    layout->addWidget(m_refresh, 1, 1);
    layout->addWidget(m_connect, 1, 2);
    layout->setColumnStretch(2, 1);

    connect(m_refresh, &QPushButton::clicked, this, &ConnectionPanel::refreshPorts);
    connect(m_connect, &QPushButton::clicked, this, &ConnectionPanel::toggleConnection);
    connect(m_port, &QComboBox::currentIndexChanged, this, &ConnectionPanel::updateState);
    connect(m_connection, &MachineConnection::stateChanged, this, &ConnectionPanel::updateState);

    refreshPorts();
    AppSettings settings;
    ConnectionTarget remembered;
    remembered.emulator = settings.connectionPort().isEmpty() || settings.connectionPort() == kEmulator;
    remembered.port = remembered.emulator ? QString() : settings.connectionPort();
    remembered.baud = settings.connectionBaud();
    setTarget(remembered);
    updateState();
}

void ConnectionPanel::refreshPorts()
{
    const QString current = m_port->currentData().toString();
    m_port->clear();
    m_port->addItem(tr("Built-in emulator"), kEmulator);
    const auto ports = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo &info : ports) {
        const QString label = info.description().isEmpty()
            ? info.systemLocation()
            : info.systemLocation() + u" — "_s + info.description();
        m_port->addItem(label, info.systemLocation());
    }
    const int index = m_port->findData(current);
    m_port->setCurrentIndex(index < 0 ? 0 : index);
}

ConnectionTarget ConnectionPanel::target() const
{
    QString port = m_port->currentData().toString();
    if (m_port->currentText() != m_port->itemText(m_port->currentIndex()) || port.isEmpty())
        port = m_port->currentText().trimmed(); // typed in
    ConnectionTarget t;
    t.emulator = port == kEmulator;
    t.port = t.emulator ? QString() : port;
    t.baud = m_baud->currentData().toInt();
    t.emulatorStock = m_emulatorStock;
    t.emulatorPaced = m_emulatorPaced;
    return t;
}

void ConnectionPanel::setTarget(const ConnectionTarget &target)
{
    const QString port = target.emulator ? kEmulator : target.port;
    m_emulatorStock = target.emulatorStock;
    m_emulatorPaced = target.emulatorPaced;
    int index = m_port->findData(port);
    if (index < 0) {
        m_port->addItem(port, port);
        index = m_port->count() - 1;
    }
    m_port->setCurrentIndex(index);
    const int baud = m_baud->findData(target.baud);
    m_baud->setCurrentIndex(baud < 0 ? m_baud->findData(115200) : baud);
}

void ConnectionPanel::toggleConnection()
{
    if (m_connection->state() != MachineConnection::State::Disconnected) {
        m_connection->disconnectFromMachine();
        return;
    }
    const ConnectionTarget t = target();
    AppSettings settings;
    settings.setConnectionPort(t.emulator ? kEmulator : t.port);
    settings.setConnectionBaud(t.baud);
    m_connection->connectTo(t);
}

void ConnectionPanel::updateState()
{
    const auto state = m_connection->state();
    const bool idle = state == MachineConnection::State::Disconnected;
    // The machine it is connected to, however the connection was made (the command line, a script).
    if (!idle)
        setTarget(m_connection->target());
    m_port->setEnabled(idle);
    m_baud->setEnabled(idle && m_port->currentData().toString() != kEmulator);
    m_refresh->setEnabled(idle);
    m_connect->setText(state == MachineConnection::State::Connected ? tr("Disconnect")
            : state == MachineConnection::State::Connecting         ? tr("Connecting…")
                                                                    : tr("Connect"));
    m_connect->setAccessibleName(m_connect->text());
    m_connect->setEnabled(state != MachineConnection::State::Connecting);
}

} // namespace Toffee
