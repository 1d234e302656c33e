// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/connection/connectionpanel.h"
#include "ui/common/askfirst.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QStackedWidget>

#include "serial/machineconnection.h"
#include "serial/transport/beaconlistener.h"
#include "ui/common/appearance.h"
#include "ui/common/appsettings.h"
#include "ui/connection/connectionpanelwifi.h"

using namespace Qt::StringLiterals;

namespace Toffee {

using namespace ConnectionPanelParts;

namespace {
const auto kEmulator = u"emulator"_s;
const auto kSerial = u"serial"_s;
const auto kWiFi = u"wifi"_s;
} // namespace

ConnectionPanel::ConnectionPanel(MachineConnection *connection, QWidget *parent)
    : QWidget(parent)
    , m_connection(connection)
    , m_kind(new QComboBox(this))
    , m_where(new QStackedWidget(this))
    , m_port(new QComboBox(this))
    , m_machine(new QComboBox(this))
    , m_emulatorLabel(new QLabel(tr("Toffee's own Carvera, for trying things out"), this))
    , m_baud(new QComboBox(this))
    , m_controller(new QComboBox(this))
    , m_hint(new QLabel(this))
    , m_listener(new BeaconListener(this))
    , m_refresh(new QPushButton(tr("Refresh"), this))
    , m_connect(new QPushButton(this))
{
    m_kind->setObjectName(u"linkCombo"_s);
    m_kind->setAccessibleName(tr("How to reach the machine"));
    m_kind->addItem(tr("Serial port (USB)"), kSerial);
    m_kind->addItem(tr("Wi-Fi"), kWiFi);
    m_kind->addItem(tr("Built-in emulator"), kEmulator);
    m_port->setObjectName(u"portCombo"_s);
    m_port->setAccessibleName(tr("Machine port"));
    m_port->setEditable(true); // a pty or a port the system does not list can be typed in
    m_port->setMinimumContentsLength(16);
    m_machine->setObjectName(u"wifiMachineCombo"_s);
    m_machine->setAccessibleName(tr("Machine on the network"));
    m_machine->setEditable(true); // an address typed in: a machine on another network sends no beacon here
    m_machine->setMinimumContentsLength(16);
    m_machine->setInsertPolicy(QComboBox::NoInsert);
    m_machine->lineEdit()->setPlaceholderText(tr("Address, such as 192.168.1.57"));
    m_emulatorLabel->setObjectName(u"emulatorLabel"_s);
    m_emulatorLabel->setWordWrap(true);
    m_where->addWidget(m_port);
    m_where->addWidget(m_machine);
    m_where->addWidget(m_emulatorLabel);
    m_baud->setObjectName(u"baudCombo"_s);
    m_baud->setAccessibleName(tr("Baud rate"));
    for (int baud : { 9600, 19200, 38400, 57600, 115200, 230400, 250000 })
        m_baud->addItem(QString::number(baud), baud);
    m_controller->setObjectName(u"controllerCombo"_s);
    m_controller->setAccessibleName(tr("Controller the machine runs"));
    for (const ControllerKind kind : controllerKinds())
        m_controller->addItem(controllerKindTitle(kind), controllerKindName(kind));
    m_controller->setToolTip(tr("Which controller the machine runs. Automatic asks it with questions that "
                                "change nothing on a Carvera or on grblHAL; a controller chosen is checked "
                                "all the same."));
    m_hint->setObjectName(u"connectionHint"_s);
    m_hint->setWordWrap(true);
    m_refresh->setObjectName(u"refreshPortsButton"_s);
    m_refresh->setAccessibleName(tr("Refresh the list of ports"));
    m_connect->setObjectName(u"connectButton"_s);
    m_connect->setIcon(themeIcon(u"connect"_s));

    // Rows, so that the panel stays narrow in every language: how, where, then the rest; a hint below.
    auto *layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_kind, 0, 0, 1, 3);
    layout->addWidget(m_where, 1, 0, 1, 3);
    layout->addWidget(m_controller, 2, 0, 1, 3);
    layout->addWidget(m_baud, 3, 0);
    layout->addWidget(m_refresh, 3, 1);
    layout->addWidget(m_connect, 3, 2);
    layout->addWidget(m_hint, 4, 0, 1, 3);
    layout->setColumnStretch(2, 1);

    connect(m_refresh, &QPushButton::clicked, this, &ConnectionPanel::refreshPorts);
    connect(m_connect, &QPushButton::clicked, this, &ConnectionPanel::toggleConnection);
    connect(m_kind, &QComboBox::currentIndexChanged, this, [this] {
        m_where->setCurrentIndex(m_kind->currentIndex());
        updateListening();
        updateState();
    });
    connect(m_machine, &QComboBox::currentIndexChanged, this, &ConnectionPanel::updateState);
    // Enter in a typed address or port connects, as the button does.
    for (QComboBox *typed : { m_machine, m_port }) {
        connect(typed->lineEdit(), &QLineEdit::returnPressed, this, [this] {
            if (m_connection->state() == MachineConnection::State::Disconnected)
                toggleConnection();
        });
    }
    connect(m_machine, &QComboBox::editTextChanged, this, &ConnectionPanel::updateState);
    connect(m_listener, &BeaconListener::machinesChanged, this, &ConnectionPanel::updateMachines);
    connect(m_connection, &MachineConnection::stateChanged, this, [this] {
        updateListening();
        updateState();
    });

    refreshPorts();
    AppSettings settings;
    QString kind = settings.connectionKind();
    if (kind.isEmpty()) // remembered before there was Wi-Fi
        kind = settings.connectionPort().isEmpty() || settings.connectionPort() == kEmulator ? kEmulator
                                                                                             : kSerial;
    ConnectionTarget remembered;
    remembered.emulator = kind == kEmulator;
    if (kind == kWiFi) {
        m_rememberedName = settings.connectionHostName();
        if (const auto address = TcpTransport::parseAddress(settings.connectionHost()); address.ok()) {
            m_rememberedAddress = addressText(address.value().host, address.value().port);
            remembered.host = address.value().host;
            remembered.tcpPort = address.value().port;
        }
    } else if (kind == kSerial) {
        remembered.port = settings.connectionPort() == kEmulator ? QString() : settings.connectionPort();
    }
    remembered.baud = settings.connectionBaud();
    remembered.controller
        = controllerKindFromName(settings.connectionController()).value_or(ControllerKind::Auto);
    setTarget(remembered);
    if (kind == kWiFi)
        setKind(Kind::WiFi); // even with no address remembered
    updateListening();
    updateState();
}

ConnectionPanel::Kind ConnectionPanel::kind() const
{
    return Kind(m_kind->currentIndex());
}

void ConnectionPanel::setKind(Kind kind)
{
    m_kind->setCurrentIndex(int(kind));
}

void ConnectionPanel::refreshPorts()
{
    const QString current = m_port->currentData().toString();
    m_port->clear();
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
    ConnectionTarget t;
    t.baud = m_baud->currentData().toInt();
    t.emulatorStock = m_emulatorStock;
    t.emulatorPaced = m_emulatorPaced;
    t.protocol = StreamTransport::Protocol(m_protocol);
    t.controller
        = controllerKindFromName(m_controller->currentData().toString()).value_or(ControllerKind::Auto);
    switch (kind()) {
    case Kind::Emulator:
        break;
    case Kind::Serial: {
        QString port = m_port->currentData().toString();
        if (m_port->currentIndex() < 0 || m_port->currentText() != m_port->itemText(m_port->currentIndex())
            || port.isEmpty())
            port = m_port->currentText().trimmed(); // typed in
        t.emulator = false;
        t.port = port;
        break;
    }
    case Kind::WiFi: {
        t.emulator = false;
        QString address = m_machine->currentText().trimmed();
        if (m_machine->currentIndex() >= 0 && address == m_machine->itemText(m_machine->currentIndex())) {
            address = m_machine->currentData().toString();
            t.controller = ControllerKind::Carvera; // heard by its beacon: a Carvera
        }
        if (const auto parsed = TcpTransport::parseAddress(address); parsed.ok()) {
            t.host = parsed.value().host;
            t.tcpPort = parsed.value().port;
        }
        break;
    }
    }
    return t;
}

void ConnectionPanel::setTarget(const ConnectionTarget &target)
{
    {
        // One update when all is set, not one per field (each would read a half-set target).
        const QSignalBlocker machine(m_machine);
        const QSignalBlocker kindBlocker(m_kind);
        setFields(target);
    }
    m_where->setCurrentIndex(m_kind->currentIndex());
    updateListening();
    updateState();
}

void ConnectionPanel::setFields(const ConnectionTarget &target)
{
    m_emulatorStock = target.emulatorStock;
    m_emulatorPaced = target.emulatorPaced;
    m_protocol = int(target.protocol);
    if (target.emulator) {
        setKind(Kind::Emulator);
    } else if (target.isNetwork()) {
        const QString address = addressText(target.host, target.tcpPort);
        const int index = m_machine->findData(address);
        m_machine->setCurrentIndex(index);
        if (index < 0)
            m_machine->setEditText(address);
        setKind(Kind::WiFi);
    } else {
        int index = m_port->findData(target.port);
        if (index < 0) {
            m_port->addItem(target.port, target.port);
            index = m_port->count() - 1;
        }
        m_port->setCurrentIndex(index);
        setKind(Kind::Serial);
    }
    if (!target.emulator)
        m_controller->setCurrentIndex(m_controller->findData(controllerKindName(target.controller)));
    const int baud = m_baud->findData(target.baud);
    m_baud->setCurrentIndex(baud < 0 ? m_baud->findData(115200) : baud);
}

void ConnectionPanel::toggleConnection()
{
    if (m_connection->state() != MachineConnection::State::Disconnected) {
        m_connection->disconnectFromMachine();
        return;
    }
    ConnectionTarget t = target();
    if (kind() == Kind::WiFi && !t.isNetwork()) {
        const auto parsed = TcpTransport::parseAddress(m_machine->currentText().trimmed());
        QMessageBox::warning(this, tr("Cannot connect to the machine"),
            m_machine->currentText().trimmed().isEmpty()
                ? tr("No machine chosen. Choose one of the machines heard on the network, or type the "
                     "machine's address as its screen shows it (such as 192.168.1.57).")
                : parsed.error().message);
        return;
    }
    if (t.isNetwork()) {
        if (const auto heard = heardAt(addressText(t.host, t.tcpPort)); heard && heard->busy) {
            const bool anyway = askFirst(this,
                { QMessageBox::Warning, tr("The machine is busy"),
                    tr("%1 says it is busy: another program is connected to it (Makera's controller, a "
                       "phone, "
                       "another computer).")
                        .arg(heard->name),
                    tr("Commands from two programs at once can interfere, and each sees the "
                       "other's replies. Disconnect the other program first, or connect "
                       "anyway."),
                    tr("Connect Anyway"), u"connectAnywayButton"_s });
            if (!anyway)
                return;
        }
    }
    AppSettings settings;
    const Kind k = kind();
    settings.setConnectionKind(k == Kind::Emulator ? kEmulator : k == Kind::WiFi ? kWiFi : kSerial);
    if (k == Kind::Serial)
        settings.setConnectionPort(t.port);
    if (k == Kind::WiFi) {
        const QString address = addressText(t.host, t.tcpPort);
        const auto heard = heardAt(address);
        // Not heard (yet): the name stays the one this address was heard by before.
        m_rememberedName = heard             ? heard->name
            : address == m_rememberedAddress ? m_rememberedName
                                             : QString();
        m_rememberedAddress = address;
        settings.setConnectionHost(address);
        settings.setConnectionHostName(m_rememberedName);
    }
    settings.setConnectionBaud(t.baud);
    if (k != Kind::Emulator)
        settings.setConnectionController(m_controller->currentData().toString());
    m_connection->connectTo(t);
}

void ConnectionPanel::updateState()
{
    const auto state = m_connection->state();
    const bool idle = state == MachineConnection::State::Disconnected;
    // The machine it is connected to, however the connection was made (the command line, a script).
    if (!idle) {
        const ConnectionTarget connected = m_connection->target();
        if (connected.name() != target().name() || connected.emulator != (kind() == Kind::Emulator)) {
            const QSignalBlocker machine(m_machine);
            const QSignalBlocker kindBlocker(m_kind);
            setFields(connected);
            m_where->setCurrentIndex(m_kind->currentIndex());
        }
    }
    m_kind->setEnabled(idle);
    m_port->setEnabled(idle);
    m_machine->setEnabled(idle);
    m_baud->setEnabled(idle && kind() == Kind::Serial);
    // A machine heard announcing itself is a Carvera; the emulator is one.
    const bool heard = kind() == Kind::WiFi && m_machine->currentIndex() >= 0
        && m_machine->currentText().trimmed() == m_machine->itemText(m_machine->currentIndex());
    m_controller->setVisible(kind() != Kind::Emulator);
    m_controller->setEnabled(idle && !heard);
    if (!idle)
        m_controller->setCurrentIndex(
            m_controller->findData(controllerKindName(m_connection->target().controller)));
    // Connected, Automatic says what it found: the controller and the machine's own name, or its link.
    const bool found = state == MachineConnection::State::Connected
        && m_connection->controllerKind() != ControllerKind::Auto;
    m_controller->setItemText(m_controller->findData(controllerKindName(ControllerKind::Auto)),
        found ? tr("Automatic: %1").arg(m_connection->identity().title())
              : controllerKindTitle(ControllerKind::Auto));
    m_baud->setVisible(kind() == Kind::Serial);
    m_refresh->setEnabled(idle);
    m_refresh->setVisible(kind() == Kind::Serial);
    m_connect->setText(state == MachineConnection::State::Connected ? tr("Disconnect")
            : state == MachineConnection::State::Connecting         ? tr("Connecting…")
                                                                    : tr("Connect"));
    m_connect->setAccessibleName(m_connect->text());
    m_connect->setEnabled(state != MachineConnection::State::Connecting);

    // What the Wi-Fi choice has heard, or why it cannot hear.
    QString hint;
    if (kind() == Kind::WiFi && idle) {
        const ConnectionTarget t = target();
        const auto heard = t.isNetwork() ? heardAt(addressText(t.host, t.tcpPort)) : std::nullopt;
        const int count = m_machine->count();
        if (!m_listenError.isEmpty())
            hint = tr("Cannot listen for machines on UDP port %1 (%2): type the machine's address.")
                       .arg(m_discoveryPort)
                       .arg(m_listenError);
        else if (heard && heard->busy)
            hint = tr("%1 is busy: another program is connected to it.").arg(heard->name);
        else if (count == 0)
            hint = tr("Listening for machines on the network… None heard yet: a Carvera announces itself "
                      "once a second when its Wi-Fi is on. Or type its address.");
        else if (count == 1)
            hint = tr("One machine heard on the network.");
        else
            hint = tr("%1 machines heard on the network.").arg(count);
        if (m_listener->dropped() > 0 && m_listenError.isEmpty())
            hint += u' '
                + tr("%1 announcements were not listed: a device announced many names (a flood, or a "
                     "misbehaving device). Every machine announcing itself from its own address is listed.")
                      .arg(m_listener->dropped());
    }
    m_hint->setText(hint);
    m_hint->setVisible(!hint.isEmpty());
}

} // namespace Toffee
