// SPDX-License-Identifier: GPL-3.0-or-later
// The connection panel's Wi-Fi list: what discovery hears (the machines' beacons), kept by address, and the
// listening that fills it.
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>

#include "serial/machineconnection.h"
#include "serial/transport/beaconlistener.h"
#include "ui/connection/connectionpanel.h"
#include "ui/connection/connectionpanelwifi.h"

using namespace Qt::StringLiterals;

namespace Toffee {

using namespace ConnectionPanelParts;

void ConnectionPanel::setDiscoveryPort(quint16 port)
{
    m_discoveryPort = port;
    m_listener->close();
    updateListening();
}

void ConnectionPanel::updateListening()
{
    const bool wanted
        = kind() == Kind::WiFi && m_connection->state() == MachineConnection::State::Disconnected;
    if (!wanted) {
        m_listener->close(); // no port held, and no beacon of our own connection's machine read as "busy"
        // Connected: the machine is busy with us now, which is not what "(busy)" warned of.
        const QSignalBlocker blocker(m_machine);
        for (int i = 0; i < m_machine->count(); ++i) {
            if (m_machine->itemData(i, kBusyRole).toBool()) {
                m_machine->setItemText(i,
                    tr("%1 — %2").arg(
                        m_machine->itemData(i, kNameRole).toString(), m_machine->itemData(i).toString()));
                m_machine->setItemData(i, false, kBusyRole);
            }
        }
        return;
    }
    if (m_listener->isListening())
        return;
    m_listenError.clear();
    if (!m_listener->listen(m_discoveryPort))
        m_listenError = m_listener->errorString();
    updateMachines();
}

void ConnectionPanel::updateMachines()
{
    // Rebuilt from what is heard, keeping the choice, or what was typed, as it was.
    const QString text = m_machine->currentText().trimmed();
    const bool onItem
        = m_machine->currentIndex() >= 0 && text == m_machine->itemText(m_machine->currentIndex());
    const QString chosen = onItem ? m_machine->currentData().toString() : text; // HOST:PORT, or as typed
    const QSignalBlocker blocker(m_machine);
    m_machine->clear();
    for (const BeaconListener::Machine &heard : m_listener->machines()) {
        const Beacon &b = heard.beacon;
        const QString address = addressText(b.address, b.port);
        const QString label
            = b.busy ? tr("%1 — %2 (busy)").arg(b.name, address) : tr("%1 — %2").arg(b.name, address);
        m_machine->addItem(label, address);
        m_machine->setItemData(m_machine->count() - 1, b.name, kNameRole);
        m_machine->setItemData(m_machine->count() - 1, b.busy, kBusyRole);
    }
    // The same machine heard; or the last one, by its name, at a new address; or, nothing chosen yet, the
    // first.
    int index = m_machine->findData(chosen);
    if (index < 0 && !m_rememberedName.isEmpty() && (chosen.isEmpty() || chosen == m_rememberedAddress))
        index = m_machine->findData(m_rememberedName, kNameRole);
    if (index < 0 && chosen.isEmpty() && m_machine->count() > 0)
        index = 0;
    m_machine->setCurrentIndex(index);
    if (index < 0)
        m_machine->setEditText(chosen); // a machine no longer heard stays, as an address
    updateState();
}

std::optional<Beacon> ConnectionPanel::heardAt(const QString &address) const
{
    for (const BeaconListener::Machine &heard : m_listener->machines()) {
        if (addressText(heard.beacon.address, heard.beacon.port) == address)
            return heard.beacon;
    }
    return std::nullopt;
}

} // namespace Toffee
