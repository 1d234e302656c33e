// SPDX-License-Identifier: GPL-3.0-or-later
// Answering the window's modal questions in tests, as a person would: click a button once the box is up.
#pragma once

#include <QAbstractButton>
#include <QApplication>
#include <QMessageBox>
#include <QTest>
#include <QTimer>

namespace Toffee::Test {

// Clicks `button`, or the button named `buttonName`, in the next message box, keeping its text in `text`.
// Waits up to about 5 s for the box; gives up quietly after that.
inline void answerNextBox(QMessageBox::StandardButton button, QString *text = nullptr,
    const QString &buttonName = {}, int attempts = 500)
{
    QTimer::singleShot(attempts == 500 ? 0 : 10, [=] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box) {
            if (attempts > 0)
                answerNextBox(button, text, buttonName, attempts - 1);
            return;
        }
        if (text)
            *text = box->text() + u'\n' + box->informativeText();
        QAbstractButton *b
            = buttonName.isEmpty() ? box->button(button) : box->findChild<QAbstractButton *>(buttonName);
        QVERIFY(b);
        b->click();
    });
}

} // namespace Toffee::Test
