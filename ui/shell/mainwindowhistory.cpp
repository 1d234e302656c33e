// SPDX-License-Identifier: GPL-3.0-or-later
// The window's history side: every recording goes to the history library, a probe off its tool's trend is
// pointed out, and a library that cannot be written is told once while the measurements wait.
#include "ui/shell/mainwindow.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QItemSelectionModel>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QTableView>
#include <QTimer>

#include "model/document/tooldocument.h"
#include "model/document/tooltablemodel.h"
#include "model/formats/fileio.h"
#include "model/gcode/gcodeinterpreter.h"
#include "model/library/historyrecorder.h"
#include "model/library/programuse.h"
#include "model/library/weartrend.h"
#include "serial/machineconnection.h"
#include "ui/common/appsettings.h"
#include "ui/history/historydock.h"
#include "ui/history/historysettingsdialog.h"
#include "ui/library/librarystatuslabel.h"
#include "ui/table/tooltablepanel.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// A write waits this long for another program's lock (SQLite's busy timeout, PostgreSQL's lock_timeout), then
// the event is kept on this computer: the window never stalls for the library. A statement itself may run
// longer (reading a long history from a busy server), up to kWindowStatementTimeoutMs.
constexpr int kWindowBusyTimeoutMs = 250;
constexpr int kWindowStatementTimeoutMs = 5000;

} // namespace

void MainWindow::connectHistory()
{
    connect(m_document, &ToolDocument::recorded, this, &MainWindow::recordHistory);
    connect(m_history, &HistoryRecorder::recorded, this, &MainWindow::checkTrends);
    connect(m_history, &HistoryRecorder::unavailable, this, [this](const QString &message) {
        statusBar()->showMessage(
            tr("The history library cannot be written: %1 Measurements wait here and are "
               "written as soon as it can be.")
                .arg(message));
    });
    connect(m_history, &HistoryRecorder::available, this, [this] {
        if (m_history->location().isShared())
            return; // the library's status label says it, with how many changes were written
        statusBar()->showMessage(
            tr("The history library is written again: every waiting measurement is in it."), 10000);
    });
    connect(m_tablePanel->view()->selectionModel(), &QItemSelectionModel::selectionChanged, this,
        &MainWindow::showSelectedHistory);
    connect(m_historyDock->exportButton(), &QPushButton::clicked, this, &MainWindow::exportHistory);
    connect(m_history, &HistoryRecorder::usesChanged, this, &MainWindow::refreshToolLife);
    // The machine as the library knows it: its controller's dialect and how the window reached it. Its name
    // may be its kind's (a machine nobody named), known now: its history and tool life are shown.
    connect(m_connection, &MachineConnection::stateChanged, this, [this](MachineConnection::State state) {
        if (state != MachineConnection::State::Connected)
            return;
        if (m_history->library()) {
            (void)m_history->library()->addMachine({ machineName(),
                dialectKeyOf(m_connection->controllerKind()), m_connection->description() });
        }
        refreshToolLife();
        showSelectedHistory();
    });
    // Ages move on while the window is open: "3 h ago" becomes "4 h ago", and a tool turns stale.
    m_document->model()->setStaleAfterDays(AppSettings().staleAfterDays());
    auto *ages = new QTimer(this);
    connect(ages, &QTimer::timeout, m_document->model(), &ToolTableModel::refreshAges);
    ages->start(60 * 1000);
    const QString chosen = AppSettings().libraryLocation();
    auto location = chosen.isEmpty() ? Result<LibraryLocation>(LibraryLocation::standard())
                                     : LibraryLocation::parse(chosen);
    // Opened once the event loop runs, not on the way to the window; unless --library chose one before.
    QTimer::singleShot(0, this, [this, location] {
        if (m_history->location().isSet())
            return;
        if (location)
            setLibrary(location.value());
        else
            refuseLibrary(location.error().text()); // a setting this Toffee cannot read
    });
}

void MainWindow::refuseLibrary(const QString &message)
{
    setLibrary(LibraryLocation::standard());
    useOwnLibrary(message);
}

void MainWindow::setLibrary(const LibraryLocation &location, const QString &station)
{
    if (!station.isEmpty())
        m_station = station;
    m_askedLibrary = location;
    // The window opens a shared library on its own thread: a server that does not answer holds it up for the
    // connect timeout, so that is short. (Reconnecting is asked from another thread: HistoryRecorder.)
    const Library::Options options { .busyTimeoutMs = kWindowBusyTimeoutMs,
        .statementTimeoutMs = kWindowStatementTimeoutMs,
        .connectTimeoutS = 2,
        .station = m_station };
    // A failure is told by the recorder's unavailable(); the measurements wait for a library that opens, and
    // a shared one's wait in the station's own library (the outbox).
    auto opened = m_history->setLocation(location, options);
    // A server that did not answer is waited for (the station works offline, its changes in the outbox); any
    // other failure needs the URL, the password file or the server fixed first.
    if (!opened && location.isShared() && opened.error().code != Library::kUnreachable) {
        // The station's own library, where a shared one's changes wait too: LibraryLocation::standard().
        (void)m_history->setLocation(m_history->outboxLocation(), options);
        useOwnLibrary(opened.error().text());
    }
    m_libraryLabel->refresh();
    updateTitle();
}

// Told without stopping the window (a startup with --library must not wait for a click), and kept in the
// status bar.
void MainWindow::useOwnLibrary(const QString &message)
{
    const QString own = tr("Toffee records into this station's own library (%1) until the shared one is "
                           "fixed (Machine ▸ History Library…).")
                            .arg(m_history->location().displayName());
    auto *box = new QMessageBox(QMessageBox::Warning, tr("The shared library cannot be used"),
        message + u"\n\n"_s + own, QMessageBox::Ok, this);
    box->setObjectName(u"libraryFailureBox"_s);
    box->setAccessibleName(tr("The shared library cannot be used"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
    statusBar()->showMessage(message + u' ' + own);
}

void MainWindow::recordHistory(const Recording &recording)
{
    m_history->record(historyEvent(recording, machineName()));
}

void MainWindow::refreshToolLife()
{
    if (!m_history->library())
        return;
    if (auto used = m_history->library()->usedLife(machineName()))
        m_document->model()->setUsedLife(used.value());
}

Result<int> MainWindow::recordProgramRun(const QString &path)
{
    auto program = ProgramUse::read(path, Dialect::Carvera, machineName());
    if (!program)
        return program.error();
    m_history->recordUse(program.value().uses);
    return int(program.value().uses.size());
}

void MainWindow::recordProgramRun()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Record a Program Run"),
        AppSettings().lastDirectory(), tr("G-code programs (*.nc *.gcode *.ngc *.tap *.cnc);;All files (*)"));
    if (path.isEmpty())
        return;
    const auto recorded = recordProgramRun(path);
    if (!recorded)
        return showError(tr("The program run was not recorded"), recorded.error().text());
    statusBar()->showMessage(tr("Recorded the cutting time of %1 tools from %2.")
                                 .arg(recorded.value())
                                 .arg(QFileInfo(path).fileName()),
        8000);
}

void MainWindow::editHistorySettings()
{
    HistorySettingsDialog dialog(this, m_askedLibrary);
    if (dialog.exec() != QDialog::Accepted)
        return;
    AppSettings settings;
    settings.setLibraryLocation(dialog.location());
    settings.setMachineName(dialog.machineName());
    settings.setStationName(dialog.stationName());
    settings.setStaleAfterDays(dialog.staleAfterDays());
    m_document->model()->setStaleAfterDays(dialog.staleAfterDays());
    m_station = settings.stationName();
    if (auto location = LibraryLocation::parse(dialog.location()))
        setLibrary(location.value());
    refreshToolLife();
    showSelectedHistory();
}

void MainWindow::showSelectedHistory()
{
    const QList<int> selected = m_tablePanel->selectedToolNumbers();
    m_historyDock->showTool(
        selected.size() == 1 ? selected.front() : -1, machineName(), AppSettings().breakTestTolerance());
}

void MainWindow::exportHistory()
{
    const QString suggested
        = QDir(AppSettings().lastDirectory()).filePath(u"T%1-history.csv"_s.arg(m_historyDock->tool()));
    const QString path
        = QFileDialog::getSaveFileName(this, tr("Export History"), suggested, tr("CSV (*.csv)"));
    if (path.isEmpty())
        return;
    if (auto written = m_historyDock->exportCsv(path); !written)
        showError(tr("The history was not exported"), written.error().text());
    else
        statusBar()->showMessage(
            tr("Exported %1 measurements to %2").arg(m_historyDock->events().size()).arg(path), 5000);
}

// A probe is checked once it is in the library, against the probes before it.
void MainWindow::checkTrends(const QList<HistoryEvent> &events)
{
    if (!m_history->library())
        return;
    const double tolerance = AppSettings().breakTestTolerance();
    for (const HistoryEvent &e : events) {
        if (const auto warning = checkProbeAgainstTrend(*m_history->library(), e, tolerance))
            statusBar()->showMessage(*warning);
    }
}

} // namespace Toffee
