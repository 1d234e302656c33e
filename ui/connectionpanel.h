// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QComboBox;
class QPushButton;

namespace Toffee {

class MachineConnection;
struct ConnectionTarget;

// Which machine: a serial port (discovered, refreshable) at a baud rate, or the built-in emulator.
// Remembered.
class ConnectionPanel final : public QWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ConnectionPanel)

public:
    explicit ConnectionPanel(MachineConnection *connection, QWidget *parent = nullptr);

    [[nodiscard]] ConnectionTarget target() const;
    void setTarget(const ConnectionTarget &target);
    void refreshPorts();
    void toggleConnection();

private:
    void updateState();

    MachineConnection *m_connection;
    QComboBox *m_port;
    QComboBox *m_baud;
    // How the built-in emulator was asked for (toffee --emulator-firmware, --emulator): kept for a reconnect.
    bool m_emulatorStock = false;
    bool m_emulatorPaced = false;
    QPushButton *m_refresh;
    QPushButton *m_connect;
};

} // namespace Toffee
