// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

namespace Toffee {

// tr() for free functions: they translate in the context lupdate gives them, the namespace "Toffee". A class
// with Q_OBJECT or Q_DECLARE_TR_FUNCTIONS uses its own tr() and its own context.
inline QString tr(const char *text)
{
    return QCoreApplication::translate("Toffee", text);
}

} // namespace Toffee
