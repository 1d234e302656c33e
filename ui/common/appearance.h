// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QIcon>

#include "model/numberformat.h" // millimetres(), which every panel uses with these

class QLabel;
class QPalette;
class QWidget;

namespace Toffee {

// Toffee's own icons, from the resources (":/icons/<name>.svg").
[[nodiscard]] QIcon themeIcon(const QString &name);
// Light is the platform's own palette; dark is Fusion with a dark palette.
void applyPalette(bool dark);
// The widget's font, monospaced: for G-code and the console.
void useMonospace(QWidget *widget);
// Scrolling a panel must never change a value under the pointer: `field` (a spin box, a combo box) takes the
// mouse wheel only once it has focus (clicked or tabbed into).
void takeWheelOnlyWhenFocused(QWidget *field);
// Shows `why` as the tooltip of a widget that cannot act now, and its own tooltip again once it can.
void explainDisabled(QWidget *widget, const QString &why);
// A word-wrapped label given the height its words need at `width` (a panel in a scroll area otherwise clips
// it); call it when the text or the width changes.
void fitWrappedLabel(QLabel *label, int width);
// The red that reads as an alarm on this palette, light or dark.
[[nodiscard]] QColor alarmColor(const QPalette &palette);

} // namespace Toffee
