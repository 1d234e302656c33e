// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QMessageBox>
#include <QString>

namespace Toffee {

// A question the operator answers before something happens: one button that says what it does (named, for
// tests and screen readers), and Cancel, the default (a reflex Enter does nothing).
struct AskFirst
{
    QMessageBox::Icon icon = QMessageBox::Question;
    QString title;
    QString text;
    QString details; // the informative text: what happens, and what to do instead
    QString accept; // the button's words: "Same Machine", "Connect Anyway"
    QString acceptName; // its object name
    QString boxName = {}; // the box's object name, when tests look for it
};

// True when the operator chose the named button.
[[nodiscard]] bool askFirst(QWidget *parent, const AskFirst &ask);

} // namespace Toffee
