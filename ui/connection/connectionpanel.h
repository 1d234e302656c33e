// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include <QWidget>

#include "serial/wire/beacon.h"

class QComboBox;
class QLabel;
class QPushButton;
class QStackedWidget;

namespace Toffee {

class BeaconListener;
class MachineConnection;
struct ConnectionTarget;

// Which machine: a serial port (discovered, refreshable) at a baud rate; a Carvera on the network (Wi-Fi),
// one of those heard announcing themselves or an address typed in; or the built-in emulator. On a port or a
// typed address, which controller it runs: the Carvera or grblHAL (a machine heard is a Carvera, the
// emulator is one). The last one is remembered. Machines are listened for only while the Wi-Fi choice is
// shown and nothing is connected.
class ConnectionPanel final : public QWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ConnectionPanel)

public:
    enum class Kind { Serial, WiFi, Emulator };

    explicit ConnectionPanel(MachineConnection *connection, QWidget *parent = nullptr);

    [[nodiscard]] ConnectionTarget target() const;
    void setTarget(const ConnectionTarget &target);
    [[nodiscard]] Kind kind() const;
    void setKind(Kind kind);
    void refreshPorts();
    // Connects to target() or disconnects. A machine heard busy is named first, and connected to only when
    // the operator says so.
    void toggleConnection();

    // Where beacons are listened for (Beacon::kDiscoveryPort; tests give their own); listening starts again
    // there.
    void setDiscoveryPort(quint16 port);
    [[nodiscard]] const BeaconListener *listener() const { return m_listener; }

private:
    // The widgets only, without a signal.
    void setFields(const ConnectionTarget &target);
    void updateState();
    void updateListening();
    void updateMachines();
    // The machine heard at `address` (HOST:PORT), if any.
    [[nodiscard]] std::optional<Beacon> heardAt(const QString &address) const;

    MachineConnection *m_connection;
    QComboBox *m_kind;
    QStackedWidget *m_where;
    QComboBox *m_port;
    QComboBox *m_machine;
    QLabel *m_emulatorLabel;
    QComboBox *m_baud;
    QComboBox *m_controller; // automatic, Carvera or grblHAL, for a serial port or an address typed in
    QLabel *m_hint;
    BeaconListener *m_listener;
    quint16 m_discoveryPort = Beacon::kDiscoveryPort;
    QString m_listenError;
    // The last machine connected to over the network: found again by its name when it moved.
    QString m_rememberedAddress;
    QString m_rememberedName;
    // How the built-in emulator was asked for (toffee --emulator-firmware, --emulator): kept for a reconnect.
    bool m_emulatorStock = false;
    bool m_emulatorPaced = false;
    // Forced by toffee --protocol or a script; the panel itself always lets Toffee find it.
    int m_protocol = 0;
    QPushButton *m_refresh;
    QPushButton *m_connect;
};

} // namespace Toffee
