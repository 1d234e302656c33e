// SPDX-License-Identifier: GPL-3.0-or-later
// What the connection panel's two files share: how the Wi-Fi list keeps a machine heard, and how an address
// is written.
#pragma once

#include <QString>

#include "serial/transport/tcptransport.h"

namespace Toffee::ConnectionPanelParts {

// The Wi-Fi list's items: the machine's name and whether it said it is busy, beside its HOST:PORT (the data).
constexpr int kNameRole = Qt::UserRole + 1;
constexpr int kBusyRole = Qt::UserRole + 2;

inline QString addressText(const QString &host, quint16 port)
{
    return TcpTransport::Address { host, port }.text();
}

} // namespace Toffee::ConnectionPanelParts
