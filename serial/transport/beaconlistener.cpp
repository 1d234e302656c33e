// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/transport/beaconlistener.h"

#include <algorithm>

#include <QNetworkDatagram>

namespace Toffee {

BeaconListener::BeaconListener(QObject *parent)
    : QObject(parent)
{
    m_clock.start();
    connect(&m_socket, &QUdpSocket::readyRead, this, &BeaconListener::readPending);
}

bool BeaconListener::listen(quint16 port)
{
    return m_socket.bind(
        QHostAddress::AnyIPv4, port, QUdpSocket::ShareAddress | QUdpSocket::ReuseAddressHint);
}

void BeaconListener::close()
{
    m_socket.close();
}

void BeaconListener::readPending()
{
    while (m_socket.hasPendingDatagrams()) {
        // Read whole (a datagram is one beacon), but only what a beacon can be: the rest is dropped by the
        // socket, not kept.
        const QNetworkDatagram datagram = m_socket.receiveDatagram(Beacon::kMaxBytes + 1);
        take(datagram.data(), datagram.senderAddress().toString());
    }
}

void BeaconListener::take(QByteArrayView datagram, const QString &from)
{
    const auto beacon = Beacon::parse(datagram);
    if (!beacon) {
        ++m_ignored;
        return;
    }
    forgetSilent();
    const qint64 now = m_clock.elapsed();
    const auto known = std::find_if(m_machines.begin(), m_machines.end(),
        [&beacon](const Machine &m) { return m.beacon.name == beacon->name; });
    if (known != m_machines.end()) {
        const bool changed = known->beacon != *beacon || known->from != from;
        *known = { *beacon, from, now };
        if (changed)
            Q_EMIT machinesChanged();
        return;
    }
    // A sender with its share of names already gives up its oldest for the new one.
    const auto fromSender = [&from](const Machine &m) {
        return m.from == from;
    };
    if (std::count_if(m_machines.cbegin(), m_machines.cend(), fromSender) >= kMaxNamesPerSender) {
        auto oldest = m_machines.end();
        for (auto it = m_machines.begin(); it != m_machines.end(); ++it) {
            if (it->from == from && (oldest == m_machines.end() || it->heardMs < oldest->heardMs))
                oldest = it;
        }
        m_machines.erase(oldest);
        ++m_dropped;
    } else if (m_machines.size() >= kMaxMachines) {
        ++m_dropped;
        return;
    }
    const auto at = std::lower_bound(m_machines.begin(), m_machines.end(), beacon->name,
        [](const Machine &m, const QString &name) { return m.beacon.name < name; });
    m_machines.insert(at, { *beacon, from, now });
    Q_EMIT machinesChanged();
}

void BeaconListener::forgetSilent()
{
    const qint64 now = m_clock.elapsed();
    const qsizetype before = m_machines.size();
    m_machines.removeIf([now](const Machine &m) { return now - m.heardMs > kForgetAfterMs; });
    if (m_machines.size() != before)
        Q_EMIT machinesChanged();
}

QList<BeaconListener::Machine> BeaconListener::machines() const
{
    const qint64 now = m_clock.elapsed();
    QList<Machine> heard;
    for (const Machine &m : m_machines) {
        if (now - m.heardMs <= kForgetAfterMs)
            heard.append(m);
    }
    return heard;
}

} // namespace Toffee
