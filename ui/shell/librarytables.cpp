// SPDX-License-Identifier: GPL-3.0-or-later
// The window's machine tables in the library: File ▸ Open Machine Table…, Save to Library…, Save of such a
// table (tool by tool over the versions read), and a table that may only be read.
#include "ui/shell/mainwindow.h"

#include <QDockWidget>

#include "serial/machineconnection.h"
#include "ui/machine/machinedock.h"
#include "ui/rack/rackpanel.h"

#include <algorithm>

#include <QAction>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>
#include <QTimer>

#include "model/document/filewatcher.h"
#include "model/document/tooldocument.h"
#include "model/library/historyrecorder.h"
#include "ui/common/appsettings.h"
#include "ui/library/librarystatuslabel.h"
#include "ui/library/machinetabledialog.h"
#include "ui/table/tooltablepanel.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// An update from another station waits this long for a cell being edited to be left, and tries again.
constexpr int kEditingRetryMs = 150;

} // namespace

void MainWindow::createLibraryActions(QMenu *file)
{
    file->addSeparator();
    auto add = [this, file](const QString &name, const QString &text, const QKeySequence &shortcut) {
        auto *action = file->addAction(text);
        action->setObjectName(name);
        action->setShortcut(shortcut);
        return action;
    };
    connect(add(u"actionOpenMachineTable"_s, tr("Open &Machine Table…"),
                QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_O)),
        &QAction::triggered, this, &MainWindow::chooseMachineTable);
    connect(
        add(u"actionSaveToLibrary"_s, tr("Save to &Library…"), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_S)),
        &QAction::triggered, this, &MainWindow::askSaveToLibrary);
}

void MainWindow::connectLibrary()
{
    m_libraryLabel = new LibraryStatusLabel(m_history, this);
    statusBar()->addPermanentWidget(m_libraryLabel);
    connect(m_libraryLabel, &LibraryStatusLabel::announced, this,
        [this](const QString &message) { statusBar()->showMessage(message, 10000); });
    connect(m_history, &HistoryRecorder::libraryChanged, this, &MainWindow::takeLibraryChange);
    connect(m_history, &HistoryRecorder::replayed, this, &MainWindow::adoptReplayed);
    // Announcements made while the link was down never arrived: the table is read again.
    connect(m_history, &HistoryRecorder::available, this, [this] { takeLibraryChange({}); });
    // This station's own measurement updated its tool's row in the library too: the table takes the row's
    // version once the document has recorded it (it tells the history first), so that Save finds no conflict.
    connect(m_history, &HistoryRecorder::recorded, this, [this](const QList<HistoryEvent> &events) {
        if (std::any_of(events.cbegin(), events.cend(),
                [this](const HistoryEvent &e) { return showsLibraryTable(e.machine); }))
            QTimer::singleShot(0, this, [this] { refreshLibraryTable(m_document->libraryMachine()); });
    });
    m_remoteRetry = new QTimer(this);
    m_remoteRetry->setSingleShot(true);
    m_remoteRetry->setInterval(kEditingRetryMs);
    connect(
        m_remoteRetry, &QTimer::timeout, this, [this] { takeLibraryChange(m_document->libraryMachine()); });
}

void MainWindow::chooseMachineTable()
{
    const Library *library = m_history->library();
    const QString title = tr("Open Machine Table");
    if (!library)
        return showError(title,
            tr("The library (%1) is not open, so its machine tables cannot be listed: %2")
                .arg(m_history->location().displayName(), m_history->lastError()));
    auto machines = library->tableMachines();
    if (!machines)
        return showError(title, machines.error().text());
    if (machines.value().isEmpty()) {
        QMessageBox::information(this, title,
            tr("The library (%1) holds no machine tables yet. File ▸ Save to Library… puts the open table "
               "there as a machine's table.")
                .arg(library->location().displayName()));
        return;
    }
    MachineTableDialog dialog(machines.value(), library->location().displayName(), this);
    dialog.setMachine(machineName());
    if (dialog.exec() != QDialog::Accepted || dialog.machine().isEmpty() || !maybeSave())
        return;
    openMachineTable(dialog.machine());
}

QString MainWindow::machineName() const
{
    if (m_document->isLibraryTable())
        return m_document->libraryMachine();
    // A machine nobody named is called after its kind once known (Emulator, Carvera, grblHAL).
    const QString chosen = AppSettings().chosenMachineName();
    if (chosen.isEmpty() && m_connection->identity().isKnown())
        return m_connection->identity().defaultName();
    return AppSettings().machineName();
}

bool MainWindow::openMachineTable(const QString &machine)
{
    Library *library = m_history->library();
    auto stored = library ? library->readTable(machine)
                          : Result<StoredTable>(Error {
                              tr("The library (%1) is not open: %2")
                                  .arg(m_history->location().displayName(), m_history->lastError()) });
    if (!stored) {
        showError(tr("Cannot open the machine's table"),
            stored.error().text() + u"\n\n"_s + tr("The table on screen has not been changed."));
        return false;
    }
    showLibraryTable(*library, stored.value());
    statusBar()->showMessage(
        tr("Opened %1's table from %2").arg(machine, m_tableLibrary.displayName()), 5000);
    return true;
}

// The document becomes the library's table, no file behind it.
void MainWindow::showLibraryTable(const Library &library, const StoredTable &stored)
{
    m_tableLibrary = library.location();
    m_tableReadOnly = library.isReadOnly();
    m_document->openLibraryTable(stored);
    m_fileWatcher->watch({});
    updateTitle();
    showSelectedHistory(); // the table's machine's history now
    refreshToolLife();
}

void MainWindow::askSaveToLibrary()
{
    if (!m_history->library())
        return showError(tr("Cannot save to the library"),
            tr("The library (%1) is not open: %2")
                .arg(m_history->location().displayName(), m_history->lastError()));
    QInputDialog dialog(this);
    dialog.setObjectName(u"machineNameDialog"_s);
    dialog.setAccessibleName(tr("The machine's name in the library"));
    dialog.setWindowTitle(tr("Save to Library"));
    dialog.setLabelText(tr("Save this table in %1 as the table of the machine:")
                            .arg(m_history->library()->location().displayName()));
    dialog.setTextValue(AppSettings().machineName());
    if (dialog.exec() != QDialog::Accepted || dialog.textValue().trimmed().isEmpty())
        return;
    saveToLibrary(dialog.textValue().trimmed());
}

bool MainWindow::saveToLibrary(const QString &machine)
{
    Library *library = m_history->library();
    auto stored = library ? library->createTable(machine, m_document->table())
                          : Result<StoredTable>(Error { m_history->lastError() });
    if (!stored) {
        showError(tr("Cannot save to the library"),
            stored.error().text() + u"\n\n"_s + tr("Nothing was written to the library."));
        return false;
    }
    showLibraryTable(*library, stored.value());
    statusBar()->showMessage(
        tr("Saved as %1's table in %2").arg(machine, m_tableLibrary.displayName()), 5000);
    return true;
}

// Only the tools changed here are written, each over the version it was read at: what another station
// changed meanwhile is refused tool by tool and put to the operator; everything else is saved.
bool MainWindow::saveLibraryTable()
{
    if (m_tableLibrary != m_history->location()) {
        showError(tr("Cannot save to the library"),
            tr("This table came from %1, and the window now works with %2. Use Save As to keep it in a "
               "file, or choose %1 again in Machine ▸ History Library….")
                .arg(m_tableLibrary.displayName(), m_history->location().displayName()));
        return false;
    }
    const ToolWrites writes = m_document->libraryWrites();
    auto outcome
        = writes.writes.isEmpty() ? Result<WriteOutcome>(WriteOutcome {}) : m_history->writeTools(writes);
    if (!outcome) {
        showError(tr("Cannot save to the library"),
            outcome.error().text() + u"\n\n"_s
                + tr("Nothing was written: the table on screen keeps your changes."));
        return false;
    }
    m_document->markWritten(writes, outcome.value());
    updateTitle();
    if (outcome.value().queued) {
        statusBar()->showMessage(
            tr("The library cannot be reached: your changes are kept on this station and "
               "written when it is back."));
        return true;
    }
    if (!outcome.value().conflicts.isEmpty())
        return chooseConflicts(outcome.value().conflicts);
    const auto count = outcome.value().written.size();
    const QString where = m_tableLibrary.displayName();
    statusBar()->showMessage(count == 1
            ? tr("Saved 1 tool to %1's table in %2").arg(writes.machine, where)
            : tr("Saved %1 tools to %2's table in %3").arg(count).arg(writes.machine, where),
        5000);
    return true;
}

bool MainWindow::showsLibraryTable(const QString &machine) const
{
    return m_document->isLibraryTable() && m_tableLibrary == m_history->location()
        && (machine.isEmpty() || machine == m_document->libraryMachine());
}

// A tool left for the operator to choose (its edit kept over their version) leaves the undo stack clean:
// it still has to be written.
bool MainWindow::hasUnsavedEdits() const
{
    return m_document->isModified()
        || (m_document->isLibraryTable() && !m_document->libraryWrites().writes.isEmpty());
}

QString MainWindow::libraryTableTitle() const
{
    const QString title = tr("%1 — %2").arg(m_document->libraryMachine(), m_tableLibrary.displayName());
    return m_tableReadOnly ? tr("%1 (read-only)").arg(title) : title;
}

void MainWindow::updateLibraryState()
{
    const bool readOnly = m_document->isLibraryTable() && m_tableReadOnly;
    QString banner;
    if (readOnly)
        banner = m_tableLibrary.isShared()
            ? tr("Read-only: your role may read this library but not change it. Whoever runs the server "
                 "can give it write rights.")
            : tr("Read-only: the library file %1 cannot be written, so this table can be read but not "
                 "changed.")
                  .arg(m_tableLibrary.path);
    m_tablePanel->setReadOnly(banner);
    for (const QString &name : { u"actionSave"_s, u"actionAddTool"_s, u"actionRemoveTool"_s,
             u"actionImport"_s, u"actionNewCutter"_s }) {
        if (auto *action = findChild<QAction *>(name))
            action->setEnabled(!readOnly);
    }
    // Probing into a table that can never be saved would lose the measurement: the machine is not moved.
    if (!m_machineDock || !m_rackPanel)
        return; // still being built
    m_machineDock->setRecordingBlocked(
        readOnly ? tr(
            "This table is read-only here, so a measurement could not be kept in it. Open a table you may "
            "change to probe, set or test tools.")
                 : QString());
    if (m_rackDock && m_rackDock->widget())
        m_rackDock->widget()->setEnabled(!readOnly);
    updateMachineStatus();
    Q_EMIT m_rackPanel->stateChanged();
}

bool MainWindow::recordingBlocked() const
{
    return m_document->isLibraryTable() && m_tableReadOnly;
}

} // namespace Toffee
