// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QUdpSocket>

#include "serial/wire/beacon.h"

namespace Toffee {

// Hears the Carveras on this computer's networks: their beacons on UDP port 3333 (docs/CARVERA.md § 11). One
// entry per machine name, the last beacon's; a malformed datagram is counted and ignored. Memory is bounded
// whatever arrives: at most kMaxMachines names, a machine silent for kForgetAfterMs forgotten. A flood cannot
// hide a real machine: one sender holds at most kMaxNamesPerSender names (a new one takes the place of its
// oldest), so a machine announcing itself from its own address keeps its place; what is not listed is counted
// (dropped()), and said.
class BeaconListener final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BeaconListener)

public:
    static constexpr int kMaxMachines = 256;
    static constexpr int kMaxNamesPerSender = 4;
    static constexpr int kForgetAfterMs = 5000;

    struct Machine
    {
        Beacon beacon;
        QString from; // the address the datagram came from
        qint64 heardMs = 0; // on elapsed()'s clock
    };

    explicit BeaconListener(QObject *parent = nullptr);

    // Binds UDP `port` on every address, shared with other listeners; false, with errorString(), when it
    // cannot.
    bool listen(quint16 port = Beacon::kDiscoveryPort);
    [[nodiscard]] bool isListening() const { return m_socket.state() == QAbstractSocket::BoundState; }
    // Stops listening; the machines heard are forgotten as ever, kForgetAfterMs after their last beacon.
    void close();
    [[nodiscard]] QString errorString() const { return m_socket.errorString(); }
    [[nodiscard]] quint16 port() const { return m_socket.localPort(); }
    // By name; those silent for longer than kForgetAfterMs are left out.
    [[nodiscard]] QList<Machine> machines() const;
    [[nodiscard]] qint64 ignored() const { return m_ignored; }
    // Names heard but not listed: beyond a sender's kMaxNamesPerSender (its oldest given up), or beyond the
    // kMaxMachines already held.
    [[nodiscard]] qint64 dropped() const { return m_dropped; }
    [[nodiscard]] qint64 elapsed() const { return m_clock.elapsed(); }

    // One datagram, as if it had arrived (the socket's path, and the tests').
    void take(QByteArrayView datagram, const QString &from);

Q_SIGNALS:
    // A machine was heard for the first time, or its address, port or busy changed.
    void machinesChanged();

private:
    void readPending();
    void forgetSilent();

    QUdpSocket m_socket;
    QElapsedTimer m_clock;
    QList<Machine> m_machines;
    qint64 m_ignored = 0;
    qint64 m_dropped = 0;
};

} // namespace Toffee
