// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/wire/beacon.h"

#include <algorithm>

namespace Toffee {

namespace {

// 1 to `max` decimal digits and no sign, as the firmware prints numbers.
std::optional<quint32> digits(QByteArrayView text, qsizetype maxDigits)
{
    if (text.isEmpty() || text.size() > maxDigits)
        return std::nullopt;
    quint32 value = 0;
    for (const char c : text) {
        if (c < '0' || c > '9')
            return std::nullopt;
        value = value * 10 + quint32(c - '0');
    }
    return value;
}

bool isIpv4(QByteArrayView text)
{
    int parts = 0;
    for (QByteArrayView rest = text;; ++parts) {
        const qsizetype dot = rest.indexOf('.');
        const auto octet = digits(dot < 0 ? rest : rest.first(dot), 3);
        if (!octet || *octet > 255)
            return false;
        if (dot < 0)
            return parts == 3;
        rest = rest.sliced(dot + 1);
    }
}

} // namespace

std::optional<Beacon> Beacon::parse(QByteArrayView datagram)
{
    if (datagram.size() > kMaxBytes)
        return std::nullopt;
    while (!datagram.isEmpty()
        && (datagram.back() == '\n' || datagram.back() == '\r' || datagram.back() == '\0'))
        datagram.chop(1);
    QByteArrayView fields[4];
    qsizetype count = 0;
    for (QByteArrayView rest = datagram;;) {
        if (count == 4)
            return std::nullopt; // a fifth field
        const qsizetype comma = rest.indexOf(',');
        fields[count++] = comma < 0 ? rest : rest.first(comma);
        if (comma < 0)
            break;
        rest = rest.sliced(comma + 1);
    }
    if (count != 4)
        return std::nullopt;
    const QByteArrayView name = fields[0];
    if (name.isEmpty() || name.size() > kMaxNameLength
        || !std::all_of(name.begin(), name.end(), [](char c) { return c >= 0x20 && c < 0x7f; }))
        return std::nullopt;
    if (!isIpv4(fields[1]))
        return std::nullopt;
    const auto port = digits(fields[2], 5);
    if (!port || *port < 1 || *port > 65535)
        return std::nullopt;
    if (fields[3] != "0" && fields[3] != "1")
        return std::nullopt;
    return Beacon { QString::fromLatin1(name), QString::fromLatin1(fields[1]), quint16(*port),
        fields[3] == "1" };
}

QByteArray Beacon::format() const
{
    return name.toLatin1() + ',' + address.toLatin1() + ',' + QByteArray::number(port) + ','
        + (busy ? '1' : '0');
}

} // namespace Toffee
