// SPDX-License-Identifier: GPL-3.0-or-later
// The window's history side: every recording goes to the history library, a probe off its tool's trend is
// pointed out, and a library that cannot be written is told once while the measurements wait.
#include "ui/mainwindow.h"

#include <QStatusBar>

#include "model/document/tooldocument.h"
#include "model/library/historyrecorder.h"
#include "model/library/weartrend.h"
#include "ui/appsettings.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// A write waits this long for toffee-cli's to finish, then the event waits in memory: the window never stalls
// for the library.
constexpr int kWindowBusyTimeoutMs = 250;

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
        statusBar()->showMessage(
            tr("The history library is written again: every waiting measurement is in it."), 10000);
    });
    const QString chosen = AppSettings().libraryLocation();
    auto location = chosen.isEmpty() ? Result<LibraryLocation>(LibraryLocation::standard())
                                     : LibraryLocation::parse(chosen);
    setLibrary(location ? location.value() : LibraryLocation::standard());
}

void MainWindow::setLibrary(const LibraryLocation &location)
{
    // A failure is told by the recorder's unavailable(); the measurements wait for a library that opens.
    (void)m_history->setLocation(location, Library::Options { kWindowBusyTimeoutMs });
}

void MainWindow::recordHistory(const Recording &recording)
{
    m_history->record(historyEvent(recording, AppSettings().machineName()));
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
