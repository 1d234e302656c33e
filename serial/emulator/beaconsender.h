// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QHostAddress>
#include <QObject>
#include <QTimer>
#include <QUdpSocket>

#include "serial/wire/beacon.h"

namespace Toffee {

// Announces a machine as a Carvera does: its beacon ("NAME,IP,TCPPORT,BUSY") to a UDP port once a second.
class BeaconSender final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BeaconSender)

public:
    static constexpr int kIntervalMs = 1000;

    BeaconSender(const Beacon &beacon, const QHostAddress &to, quint16 port, QObject *parent = nullptr);

    void start();
    void setBusy(bool busy);
    [[nodiscard]] const Beacon &beacon() const { return m_beacon; }

private:
    void send();

    Beacon m_beacon;
    QHostAddress m_to;
    quint16 m_port;
    QUdpSocket m_socket;
    QTimer m_timer;
};

} // namespace Toffee
