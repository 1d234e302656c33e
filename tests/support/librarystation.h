// SPDX-License-Identifier: GPL-3.0-or-later
// A station of a shop that shares one library: the real window (offscreen) on a library given by its
// location, writing as its own station name, and the gestures of the shared-table stories (Save to Library,
// Open Machine Table, an edit, Save with the conflict dialog answered).
#pragma once

#include <functional>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QHash>
#include <QInputDialog>
#include <QListWidget>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include "model/document/tooldocument.h"
#include "model/library/historyrecorder.h"
#include "ui/library/conflictdialog.h"
#include "ui/library/machinetabledialog.h"
#include "ui/shell/mainwindow.h"
#include "ui/table/tooltablepanel.h"

namespace Toffee::Test {

// What the conflict dialog showed, row by row.
struct ConflictsSeen
{
    bool shown = false;
    QList<int> tools;
    QStringList theirs;
    QStringList mine;
};

// Does `act`, answering the modal dialog of type T that comes up while it runs with `answer`; nothing is left
// waiting for a dialog once `act` is done.
template<typename T> void answering(const std::function<void(T *)> &answer, const std::function<void()> &act)
{
    QTimer poll;
    poll.setInterval(10);
    QObject::connect(&poll, &QTimer::timeout, &poll, [&] {
        if (auto *dialog = qobject_cast<T *>(QApplication::activeModalWidget())) {
            poll.stop();
            answer(dialog);
        }
    });
    poll.start();
    act();
}

struct LibraryStation
{
    QTemporaryDir own; // the station's own library, where a shared one's changes wait: one per computer
    MainWindow window;

    LibraryStation(const LibraryLocation &location, const QString &station)
    {
        window.history()->setOutboxLocation({ .path = own.filePath(QStringLiteral("own.sqlite")) });
        window.setLibrary(location, station);
        window.show();
    }
    ToolDocument *document() const { return window.document(); }
    const ToolTable &table() const { return window.document()->table(); }
    const Tool &tool(int number) const { return *table().find(number); }
    QString status() const { return window.statusBar()->currentMessage(); }
    QAction *action(const QString &name) const { return window.findChild<QAction *>(name); }

    // File ▸ Save to Library…, typing the machine's name.
    void saveToLibrary(const QString &machine)
    {
        answering<QInputDialog>(
            [machine](QInputDialog *dialog) {
                dialog->setTextValue(machine);
                dialog->accept();
            },
            [this] { action(QStringLiteral("actionSaveToLibrary"))->trigger(); });
    }
    // File ▸ Open Machine Table…, choosing the machine; `listed` gets what the dialog offered.
    void openMachineTable(const QString &machine, QStringList *listed = nullptr)
    {
        answering<MachineTableDialog>(
            [machine, listed](MachineTableDialog *dialog) {
                if (listed) {
                    auto *list = dialog->findChild<QListWidget *>(QStringLiteral("machineTableList"));
                    for (int i = 0; list && i < list->count(); ++i)
                        listed->append(list->item(i)->text());
                }
                dialog->setMachine(machine);
                dialog->accept();
            },
            [this] { action(QStringLiteral("actionOpenMachineTable"))->trigger(); });
    }
    // An edit of one tool, as the table's cell editor makes it.
    void edit(int number, const std::function<void(Tool &)> &change)
    {
        Tool changed = tool(number);
        change(changed);
        QVERIFY(document()->editTool(number, changed));
    }
    // Save (Ctrl+S); a conflict dialog is answered per tool with `keepMine` (absent: keep mine).
    ConflictsSeen save(const QHash<int, bool> &keepMine = {})
    {
        ConflictsSeen seen;
        answering<ConflictDialog>(
            [&seen, &keepMine](ConflictDialog *dialog) { answer(dialog, keepMine, seen); },
            [this] { action(QStringLiteral("actionSave"))->trigger(); });
        return seen;
    }
    static void answer(ConflictDialog *dialog, const QHash<int, bool> &keepMine, ConflictsSeen &seen)
    {
        seen.shown = true;
        auto *rows = dialog->findChild<QTableWidget *>(QStringLiteral("conflictTable"));
        for (int row = 0; row < rows->rowCount(); ++row) {
            seen.tools << rows->item(row, ConflictDialog::ToolColumn)->text().mid(1).toInt();
            seen.theirs << rows->item(row, ConflictDialog::TheirsColumn)->text();
            seen.mine << rows->item(row, ConflictDialog::MineColumn)->text();
        }
        for (int number : std::as_const(seen.tools))
            dialog->setKeepsMine(number, keepMine.value(number, true));
        dialog->accept();
    }
};

} // namespace Toffee::Test
