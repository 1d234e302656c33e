// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

class QCoreApplication;

namespace Toffee {

// Installs the window's translation for `language` ("de", "zh_CN"; empty: the system's locale), and Qt's own
// for its dialogs' buttons. Returns the language installed, or empty for English.
// Toffee's own come from `directory` (the resources; tests give the build folder), Qt's from where Debian's
// qt6-translations-l10n puts them. The locale becomes the default, so numbers use its decimal separator.
QString installTranslations(
    QCoreApplication *app, const QString &language = {}, const QString &directory = QStringLiteral(":/i18n"));

} // namespace Toffee
