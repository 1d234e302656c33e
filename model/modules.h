// SPDX-License-Identifier: GPL-3.0-or-later
// Toffee's own modules: parts loaded when first used rather than at every start (the zip reader with libzip,
// the History chart with Qt Charts), so that the window and the CLI start with fewer libraries. They live in
// lib/<multiarch>/toffee beside the program's bin/, installed and in the build tree alike; the user's guide
// in share/doc/toffee/guide, found the same way.
#pragma once

#include <QFunctionPointer>
#include <QString>

#include "model/result.h"

namespace Toffee {

// The module file's full path.
[[nodiscard]] QString modulePath(QLatin1StringView file);
// `symbol` in the module `file`, which stays loaded. An error's `file` is the module's path; its code is
// kModuleMissing when there is no such file, and its message is then empty, else the loader's reason: the
// caller says which part of Toffee is missing, in its own words.
[[nodiscard]] Result<QFunctionPointer> resolveInModule(QLatin1StringView file, const char *symbol);
inline const QString kModuleMissing = QStringLiteral("module-missing");
// The user's guide (GUIDE.md, and the screenshots it shows beside it): its full path.
[[nodiscard]] QString guidePath();
// For tests: where modules are looked for instead (empty: beside the program again).
void setModuleDirectory(const QString &directory);

} // namespace Toffee
