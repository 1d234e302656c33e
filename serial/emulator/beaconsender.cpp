// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/emulator/beaconsender.h"

namespace Toffee {

BeaconSender::BeaconSender(const Beacon &beacon, const QHostAddress &to, quint16 port, QObject *parent)
    : QObject(parent)
    , m_beacon(beacon)
    , m_to(to)
    , m_port(port)
{
    m_timer.setInterval(kIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &BeaconSender::send);
}

void BeaconSender::start()
{
    send();
    m_timer.start();
}

void BeaconSender::setBusy(bool busy)
{
    if (m_beacon.busy == busy)
        return;
    m_beacon.busy = busy;
    send(); // at once, as a machine's next beacon would say it within a second
}

void BeaconSender::send()
{
    m_socket.writeDatagram(m_beacon.format(), m_to, m_port);
}

} // namespace Toffee
