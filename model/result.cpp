// SPDX-License-Identifier: GPL-3.0-or-later
#include "result.h"

#include <QCoreApplication>

namespace Toffee {

QString Error::text() const
{
    if (line <= 0)
        return message;
    return QCoreApplication::translate("Toffee::Error", "line %1: %2").arg(line).arg(message);
}

} // namespace Toffee
