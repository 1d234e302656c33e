// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The steps a window story waits on and answers with, written once: connected, idle with no dialog up, a
// screenshot when TOFFEE_SCREENSHOTS names a folder, the next dialog of a type acted on, the next message box
// answered.
#include <functional>

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QMessageBox>
#include <QTableWidget>
#include <QTest>
#include <QTimer>

#include "serial/machineconnection.h"
#include "tests/support/station.h"

namespace Toffee::Test {

// A table's rows as "T2|15.300|7.000|written" (an offset preview's, a report's).
inline QStringList rowsOf(QTableWidget *table)
{
    QStringList rows;
    for (int r = 0; r < table->rowCount(); ++r) {
        QStringList cells;
        for (int c = 0; c < table->columnCount(); ++c)
            cells << table->item(r, c)->text();
        rows << cells.join(u'|');
    }
    return rows;
}

inline bool waitConnected(Station &s, int ms = 20000)
{
    return QTest::qWaitFor(
        [&s] { return s.window.connection()->state() == MachineConnection::State::Connected; }, ms);
}

// Idle, and no dialog or question up.
inline bool waitIdle(Station &s, int ms = 30000)
{
    return QTest::qWaitFor([&s] { return s.idle() && !QApplication::activeModalWidget(); }, ms);
}

inline void screenshot(QWidget &widget, const QString &name)
{
    const QString folder = qEnvironmentVariable("TOFFEE_SCREENSHOTS");
    if (!folder.isEmpty() && QDir().mkpath(folder))
        QVERIFY(widget.grab().save(QDir(folder).filePath(name)));
}

// In the next modal dialog of type D: `act` on it (it accepts or rejects it).
template<typename D> void inNextDialog(std::function<void(D *)> act, int attempts = 2000)
{
    QTimer::singleShot(10, [=] {
        auto *dialog = qobject_cast<D *>(QApplication::activeModalWidget());
        if (!dialog) {
            if (attempts > 0)
                inNextDialog<D>(act, attempts - 1);
            return;
        }
        act(dialog);
    });
}

// Clicks the button named `button` (none: the default one, else its only one) in the next message box whose
// title is `title` (none: any), keeping its text.
inline void answerBoxTitled(const QString &title, const QString &button, QString *text, int attempts = 1000)
{
    QTimer::singleShot(10, [=] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box || (!title.isEmpty() && box->windowTitle() != title)) {
            if (attempts > 0)
                answerBoxTitled(title, button, text, attempts - 1);
            return;
        }
        *text = box->text() + u'\n' + box->informativeText();
        QAbstractButton *b = !button.isEmpty() ? box->findChild<QAbstractButton *>(button)
            : box->defaultButton()             ? box->defaultButton()
                                               : box->buttons().value(0);
        QVERIFY(b);
        b->click();
    });
}

// The next message box's text, answered with its default button (or its only one), once it is up.
inline void answerAnyBox(QString *text, int attempts = 1000)
{
    answerBoxTitled({}, {}, text, attempts);
}

} // namespace Toffee::Test
