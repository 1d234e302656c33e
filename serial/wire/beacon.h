// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

#include <optional>

namespace Toffee {

// The datagram a Carvera sends once a second to UDP port 3333 of each of its networks (docs/CARVERA.md § 11):
// "NAME,IP,TCPPORT,BUSY", e.g. "Carvera_01234,192.168.1.57,2222,0", BUSY 1 while a client is connected.
struct Beacon
{
    static constexpr quint16 kDiscoveryPort = 3333;
    static constexpr quint16 kDefaultTcpPort = 2222;
    static constexpr qsizetype kMaxBytes = 256; // a real one is some 40
    static constexpr qsizetype kMaxNameLength = 64;

    QString name;
    QString address; // dotted IPv4, as the machine announces itself
    quint16 port = kDefaultTcpPort;
    bool busy = false;

    // A well-formed beacon, or nothing: four fields; a name of printable characters; an IPv4 address; a port
    // 1-65535; busy 0 or 1. Trailing line ends and NULs are allowed, nothing else.
    [[nodiscard]] static std::optional<Beacon> parse(QByteArrayView datagram);
    [[nodiscard]] QByteArray format() const;
    friend bool operator==(const Beacon &, const Beacon &) = default;
};

} // namespace Toffee
