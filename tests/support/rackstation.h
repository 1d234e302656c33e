// SPDX-License-Identifier: GPL-3.0-or-later
// The operator's station with the Rack dock in front: its table read as the operator reads it, its buttons,
// and what the history library holds.
#pragma once

#include <QDockWidget>
#include <QPushButton>
#include <QTableWidget>

#include "model/library/historyrecorder.h"
#include "model/library/library.h"
#include "tests/support/station.h"

namespace Toffee::Test {

struct RackStation : Station
{
    RackStation()
    {
        // The rack's own tab: the operator looks at it, and its buttons take clicks.
        find<QDockWidget>(u"rackDock"_s)->raise();
    }
    QTableWidget *rackTable() const { return find<QTableWidget>(u"rackTable"_s); }
    QString rackCell(int row, int column) const
    {
        const QTableWidgetItem *item = rackTable()->item(row, column);
        return item ? item->text() : QString();
    }
    QStringList column(int column) const
    {
        QStringList texts;
        for (int row = 0; row < rackTable()->rowCount(); ++row)
            texts << rackCell(row, column);
        return texts;
    }
    void click(const QString &button) { QTest::mouseClick(find<QPushButton>(button), Qt::LeftButton); }
    QList<HistoryEvent> events(EventKind kind) const
    {
        QList<HistoryEvent> found;
        const auto all = window.history()->library()->history({});
        for (const HistoryEvent &e : all.value()) {
            if (e.kind == kind)
                found.append(e);
        }
        return found;
    }
};

// Clicks `button` in the message box named `name` once it is up, keeping its text in `text`.
inline void answerBoxNamed(
    const QString &name, QMessageBox::StandardButton button, QString *text, int attempts = 3000)
{
    QTimer::singleShot(10, [=] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box || box->objectName() != name) {
            if (attempts > 0)
                answerBoxNamed(name, button, text, attempts - 1);
            return;
        }
        *text = box->text() + u'\n' + box->informativeText();
        box->button(button)->click();
    });
}

} // namespace Toffee::Test
