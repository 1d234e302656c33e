// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/result.h"

#include <QCoreApplication>

namespace Toffee {

QString Error::text() const
{
    const QString located = line <= 0
        ? message
        : QCoreApplication::translate("Toffee::Error", "line %1: %2").arg(line).arg(message);
    return file.isEmpty() ? located : file + QStringLiteral(": ") + located;
}

} // namespace Toffee
