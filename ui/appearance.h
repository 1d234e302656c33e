// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QIcon>

class QPalette;

namespace Toffee {

// Toffee's own icons, from the resources (":/icons/<name>.svg").
[[nodiscard]] QIcon themeIcon(const QString &name);
// Light is the platform's own palette; dark is Fusion with a dark palette.
void applyPalette(bool dark);
// The red that reads as an alarm on this palette, light or dark.
[[nodiscard]] QColor alarmColor(const QPalette &palette);

} // namespace Toffee
