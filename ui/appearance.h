// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QIcon>

class QPalette;
class QWidget;

namespace Toffee {

// Toffee's own icons, from the resources (":/icons/<name>.svg").
[[nodiscard]] QIcon themeIcon(const QString &name);
// Light is the platform's own palette; dark is Fusion with a dark palette.
void applyPalette(bool dark);
// A length for people, in the locale's decimals: "-33.388 mm" (`withUnit` false: "-33.388").
[[nodiscard]] QString millimetres(double value, bool withUnit = true);
// The widget's font, monospaced: for G-code and the console.
void useMonospace(QWidget *widget);
// Scrolling a panel must never change a value under the pointer: `field` (a spin box, a combo box) takes the
// mouse wheel only once it has focus (clicked or tabbed into).
void takeWheelOnlyWhenFocused(QWidget *field);
// A number for people in this locale's decimal separator ("-33,388" in German), never grouped.
[[nodiscard]] QString localNumber(double value, int decimals);
// The red that reads as an alarm on this palette, light or dark.
[[nodiscard]] QColor alarmColor(const QPalette &palette);

} // namespace Toffee
