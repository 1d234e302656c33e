// SPDX-License-Identifier: GPL-3.0-or-later
// Other stations' changes reaching an open machine table: taken in at once where this station has no
// unsaved edit, put to the operator where both changed a tool; and the outbox's writes once the shared
// library is back.
#include "ui/shell/mainwindow.h"

#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>

#include "model/document/tooldocument.h"
#include "model/library/historyrecorder.h"
#include "ui/common/appsettings.h"
#include "ui/library/conflictdialog.h"
#include "ui/table/tooltablepanel.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QString stationOf(const ToolConflict &conflict)
{
    return conflict.theirStation.isEmpty() ? MainWindow::tr("another station") : conflict.theirStation;
}

// "T3 was changed on station B; your edit is kept — Save to choose." for the status bar.
QString conflictNotice(const QList<ToolConflict> &conflicts)
{
    QStringList parts;
    for (const ToolConflict &c : conflicts)
        parts << MainWindow::tr("T%1 was changed on %2").arg(c.number).arg(stationOf(c));
    return parts.join(u"; "_s) + u"; "_s
        + (conflicts.size() == 1 ? MainWindow::tr("your edit is kept — Save to choose.")
                                 : MainWindow::tr("your edits are kept — Save to choose."));
}

std::optional<Tool> toolIn(const ToolTable &table, int number)
{
    const Tool *tool = table.find(number);
    return tool ? std::optional(*tool) : std::nullopt;
}

} // namespace

void MainWindow::takeLibraryChange(const QString &machine)
{
    if (machine.isEmpty() || machine == machineName()) {
        showSelectedHistory(); // another station's measurements of this machine's tools
        refreshToolLife();
    }
    refreshLibraryTable(machine);
}

// The open machine table takes what the library holds now; the tools this station changed are merged.
void MainWindow::refreshLibraryTable(const QString &machine)
{
    if (!showsLibraryTable(machine) || !m_history->library())
        return;
    // The update resets the table, which would close a cell being typed into: it waits until it is left.
    if (m_tablePanel->isEditing()) {
        m_remoteRetry->start();
        return;
    }
    auto latest = m_history->library()->readTable(m_document->libraryMachine());
    if (!latest) {
        statusBar()->showMessage(latest.error().text(), 10000);
        return;
    }
    const QList<int> selected = m_tablePanel->selectedToolNumbers();
    const QList<ToolConflict> conflicts = m_document->takeRemote(latest.value());
    if (!selected.isEmpty() && m_tablePanel->selectedToolNumbers().isEmpty())
        m_tablePanel->selectTool(selected.front());
    // What the library holds is what is shown (this station's own probe, written with its event): saved.
    if (m_document->libraryWrites().writes.isEmpty())
        m_document->markWritten({}, {});
    // A table that may only be read offers no Undo back to what the library no longer holds.
    if (m_tableReadOnly && !m_document->isModified())
        m_document->undoStack()->clear();
    if (!conflicts.isEmpty())
        statusBar()->showMessage(conflictNotice(conflicts));
    updateTitle();
}

bool MainWindow::chooseConflicts(const QList<ToolConflict> &conflicts)
{
    ConflictDialog dialog(conflicts, m_document->table().units(), this);
    if (dialog.exec() != QDialog::Accepted) {
        statusBar()->showMessage(tr("Not saved: %1").arg(conflictNotice(conflicts)));
        return false;
    }
    bool keepAny = false;
    for (const ToolConflict &c : conflicts) {
        const bool keep = dialog.keepsMine(c.number);
        m_document->resolveConflict(c, keep);
        keepAny = keepAny || keep;
    }
    updateTitle();
    // Mine is now written over their version, unless yet another station wrote in between: asked again.
    return keepAny ? saveLibraryTable() : true;
}

void MainWindow::adoptReplayed(const QString &machine, const WriteOutcome &outcome)
{
    if (showsLibraryTable(machine)) {
        // Mine stays over their version at once: an update from the library before the operator has chosen
        // must not take theirs in silently.
        for (const ToolConflict &c : outcome.conflicts)
            m_document->resolveConflict(c, true);
        refreshLibraryTable(machine); // the written tools' new versions
    }
    if (outcome.conflicts.isEmpty())
        return;
    // Asked once the recorder has sent everything that waited, never from inside its replay.
    QTimer::singleShot(
        0, this, [this, machine, conflicts = outcome.conflicts] { chooseReplayed(machine, conflicts); });
}

// The outbox's writes met other stations' changes: the same choice as at Save. For a table no longer open,
// what the operator keeps is written directly.
void MainWindow::chooseReplayed(const QString &machine, QList<ToolConflict> conflicts)
{
    const bool shown = showsLibraryTable(machine);
    for (ToolConflict &c : conflicts) {
        if (shown)
            c.mine = toolIn(m_document->table(), c.number); // edits made since count as mine
    }
    Library *library = m_history->library();
    const auto stored = !shown && library ? library->readTable(machine) : Result<StoredTable>(Error {});
    const Units units = shown ? m_document->table().units()
        : stored              ? stored.value().units
                              : Units::Millimetre;
    ConflictDialog dialog(conflicts, units, this);
    dialog.setWindowTitle(tr("Changed on Another Station While the Library Was Offline"));
    if (dialog.exec() != QDialog::Accepted) {
        statusBar()->showMessage(shown ? tr("Not saved: %1").arg(conflictNotice(conflicts))
                                       : tr("%1's table keeps the other station's tools.").arg(machine));
        updateTitle();
        return;
    }
    ToolWrites keep { machine, units, {} };
    for (const ToolConflict &c : conflicts) {
        if (!dialog.keepsMine(c.number) && shown)
            m_document->resolveConflict(c, false);
        else if (dialog.keepsMine(c.number))
            keep.writes.append({ c.number, c.mine, c.theirVersion });
    }
    updateTitle();
    if (keep.writes.isEmpty())
        return;
    if (shown) {
        saveLibraryTable();
        return;
    }
    auto written = m_history->writeTools(keep);
    if (!written)
        showError(tr("Cannot save to the library"), written.error().text());
    else if (!written.value().conflicts.isEmpty())
        statusBar()->showMessage(conflictNotice(written.value().conflicts));
}

} // namespace Toffee
