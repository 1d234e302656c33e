// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

class QCoreApplication;

namespace Toffee {

// Installs the window's translation for `language` ("de", "zh_CN"; empty: the system's locale), and Qt's own
// for its dialogs' buttons. Returns the language installed, or empty for English.
QString installTranslations(QCoreApplication *app, const QString &language = {});

} // namespace Toffee
