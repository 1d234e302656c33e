// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/mainwindow.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QHash>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QResizeEvent>
#include <QScreen>
#include <QStatusBar>
#include <QTableView>
#include <QToolBar>
#include <QUndoStack>

#include "model/document/autosave.h"
#include "model/document/filewatcher.h"
#include "model/document/tooldocument.h"
#include "model/library/historyrecorder.h"
#include "serial/machineconnection.h"
#include "ui/common/appearance.h"
#include "ui/common/appsettings.h"
#include "ui/connection/connectionpanel.h"
#include "ui/history/historydock.h"
#include "ui/machine/breaktestpanel.h"
#include "ui/machine/consoledock.h"
#include "ui/machine/machinedock.h"
#include "ui/machine/probepanel.h"
#include "ui/machine/tlopanel.h"
#include "ui/machine/toolchangewait.h"
#include "ui/rack/rackpanel.h"
#include "ui/shell/toolcontextmenu.h"
#include "ui/table/exportdialog.h"
#include "ui/table/tooltablepanel.h"

using namespace Qt::StringLiterals;

namespace Toffee {

MainWindow::MainWindow(QWidget *parent)
    : MainWindow(Build::Now, parent)
{ }

// The frame alone is cheap: its size, its name. What fills it is built by build(), which start-up calls once
// the window is on the screen (main.cpp).
MainWindow::MainWindow(Build when, QWidget *parent)
    : QMainWindow(parent)
{
    setObjectName(u"mainWindow"_s);
    m_station = AppSettings().stationName();
    restoreWindowGeometry();
    if (when == Build::Now)
        build();
}

// Start-up's order: the frame goes to the screen first (Qt's show() sends the map request to the X server at
// once), then what fills it is built, before the event loop paints it for the first time. The window so
// appears as soon as a bare one would, and its first picture is already the whole window.
void MainWindow::showThenBuild()
{
    show();
    build();
}

void MainWindow::build()
{
    if (m_document)
        return;
    m_document = new ToolDocument(this);
    m_tablePanel = new ToolTablePanel(m_document->model(), this);
    m_connection = new MachineConnection(this);
    // Every probe and break test measures a tool as the open table's settings say (its Probing column).
    m_connection->setProbePlans(
        [document = m_document](int tool) { return document->table().probePlan(tool); });
    m_machineDock = new MachineDock(m_connection, m_document, this);
    m_consoleDock = new ConsoleDock(m_connection, m_document, this);
    m_fileWatcher = new FileWatcher(this);
    m_autoSave = new AutoSave(m_document, AutoSave::defaultDirectory(), this);
    m_history = new HistoryRecorder(this);
    m_historyDock = new HistoryDock(m_history, this);
    m_rackPanel = new RackPanel(m_connection, m_document);
    new ToolChangeWait(m_connection, this);
    m_rackDock = new QDockWidget(tr("Rack"), this);
    setWindowIcon(themeIcon(u"toffee"_s));
    setCentralWidget(m_tablePanel);
    setAcceptDrops(true);
    addDockWidget(Qt::RightDockWidgetArea, m_machineDock);
    addDockWidget(Qt::BottomDockWidgetArea, m_consoleDock);
    addDockWidget(Qt::BottomDockWidgetArea, m_historyDock);
    tabifyDockWidget(m_consoleDock, m_historyDock);
    m_consoleDock->raise();
    createRackDock();
    // The machine panel runs the full height beside the table and the console: at 1280×720 it then needs no
    // scrolling to reach the break test.
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    createActions();
    createMachineActions();
    createMachineStrip();
    connectMachine();
    connectControllerSettings();
    connectDocument();
    connectHistory();
    connectLibrary();
    updateTitle();
    // Built into a window already shown, the panels are shown by posted events: the saved layout is laid onto
    // them once they are, or the docks come back at sizes the panels did not yet have (a squeezed table).
    if (isVisible())
        QCoreApplication::sendPostedEvents(nullptr, QEvent::MetaCall);
    restoreDockState();
}

// The machine's state, tool and TLO in a strip that no scrolling, dock or window size hides (and that the
// toolbar menu cannot switch off).
void MainWindow::createMachineStrip()
{
    auto *strip = new QToolBar(tr("Machine State"), this);
    strip->setObjectName(u"machineStateBar"_s);
    strip->setMovable(false);
    strip->setFloatable(false);
    strip->toggleViewAction()->setEnabled(false);
    strip->toggleViewAction()->setVisible(false);
    strip->addWidget(m_machineDock->tloPanel());
    addToolBarBreak();
    addToolBar(Qt::TopToolBarArea, strip);
}

// The tool changer beside the machine panel, a tab of its own: the two are used one after the other.
void MainWindow::createRackDock()
{
    m_rackDock->setObjectName(u"rackDock"_s);
    m_rackDock->setWidget(m_rackPanel);
    addDockWidget(Qt::RightDockWidgetArea, m_rackDock);
    tabifyDockWidget(m_machineDock, m_rackDock);
    m_machineDock->raise();
}

// The status bar follows the connection; its failures become messages.
void MainWindow::connectMachine()
{
    m_machineLabel = new QLabel(this);
    m_machineLabel->setObjectName(u"machineStatusLabel"_s);
    statusBar()->addPermanentWidget(m_machineLabel);
    connect(m_connection, &MachineConnection::stateChanged, this, &MainWindow::updateMachineStatus);
    connect(m_connection, &MachineConnection::statusChanged, this, &MainWindow::updateMachineStatus);
    connect(m_connection, &MachineConnection::busyChanged, this, &MainWindow::updateMachineStatus);
    connect(m_connection, &MachineConnection::haltedChanged, this, &MainWindow::updateMachineStatus);
    connect(m_connection, &MachineConnection::stateChanged, this, [this](MachineConnection::State state) {
        // "Disconnected: …" is history once connected again.
        if (state != MachineConnection::State::Disconnected)
            statusBar()->clearMessage();
    });
    connect(m_connection, &MachineConnection::connectFailed, this,
        [this](const QString &message) { showError(tr("Cannot connect to the machine"), message); });
    connect(m_connection, &MachineConnection::disconnected, this, [this](const QString &reason) {
        statusBar()->showMessage(tr("Disconnected: %1").arg(reason), 10000);
    });
    // Queued: the box waits for the operator, and reconnecting replaces the link whose closing said this.
    connect(
        m_connection, &MachineConnection::linkLost, this, &MainWindow::offerReconnect, Qt::QueuedConnection);
    connect(m_connection, &MachineConnection::interruptionChecked, this, [this](const QString &verdict) {
        statusBar()->showMessage(verdict, 30000);
        if (isVisible())
            QMessageBox::information(this, tr("Connected again"), verdict);
    });
    connect(m_tablePanel->view()->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
        const QList<int> selected = m_tablePanel->selectedToolNumbers();
        m_machineDock->probePanel()->setSelectedTool(selected.size() == 1 ? selected.front() : -1);
    });
    new ToolContextMenu(this, m_connection, m_document, m_tablePanel, m_machineDock); // after the selection's
    updateMachineStatus();
}

// The link went while an operation ran: nothing of it was recorded, and only the machine can say whether it
// happened. Reconnecting reads its offsets back (MachineConnection::interruptionChecked says what they show).
void MainWindow::offerReconnect(const QString &operation, const QString &reason)
{
    if (!isVisible())
        return;
    QMessageBox box(QMessageBox::Warning, tr("The link to the machine was lost"),
        operation.isEmpty() ? tr("The link to the machine was lost: %1").arg(reason)
                            : tr("The link to the machine was lost during \"%1\": %2").arg(operation, reason),
        QMessageBox::NoButton, this);
    box.setInformativeText(operation.isEmpty()
            ? tr("Nothing was running. Reconnect to read the machine's tool and TLO again.")
            : tr("Nothing of it was written to the tool table or the history: the machine did not confirm "
                 "it. Reconnect to read the machine's offsets back; Toffee then says whether it happened."));
    QPushButton *reconnect = box.addButton(tr("Reconnect"), QMessageBox::AcceptRole);
    reconnect->setObjectName(u"reconnectButton"_s);
    box.addButton(tr("Not Now"), QMessageBox::RejectRole);
    box.setDefaultButton(reconnect);
    box.exec();
    if (box.clickedButton() == reconnect && m_connection->state() == MachineConnection::State::Disconnected)
        m_connection->connectTo(m_connection->target());
}

// The tool count, the title, the file on disk, autosave and the table's own warnings.
void MainWindow::connectDocument()
{
    m_countLabel = new QLabel(this);
    m_countLabel->setObjectName(u"toolCountLabel"_s);
    statusBar()->addPermanentWidget(m_countLabel);
    auto updateCount = [this] {
        const auto count = m_document->table().size();
        m_countLabel->setText(count == 1 ? tr("1 tool") : tr("%1 tools").arg(count));
    };
    connect(m_document->model(), &QAbstractItemModel::modelReset, this, updateCount);
    connect(m_document->model(), &QAbstractItemModel::rowsInserted, this, updateCount);
    connect(m_document->model(), &QAbstractItemModel::rowsRemoved, this, updateCount);
    updateCount();

    connect(m_document, &ToolDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_document, &ToolDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_fileWatcher, &FileWatcher::changedOnDisk, this, &MainWindow::fileChangedOnDisk);
    connect(m_autoSave, &AutoSave::failed, this, [this](const QString &message) {
        statusBar()->showMessage(
            tr("Unsaved edits are not protected against a crash until they are saved: %1").arg(message));
    });
    connect(m_document->model(), &ToolTableModel::pocketShared, this,
        [this](int number, int pocket, const QList<int> &others) {
            QStringList names;
            for (int n : others)
                names << u"T"_s + QString::number(n);
            statusBar()->showMessage(
                tr("T%1 shares pocket %2 with %3. LinuxCNC's random tool changer needs each "
                   "tool in its own pocket.")
                    .arg(number)
                    .arg(pocket)
                    .arg(names.join(u", "_s)),
                10000);
        });
    connect(m_document->model(), &ToolTableModel::editRejected, this,
        [this](const QString &message) { showError(tr("Value not accepted"), message); });
}

MainWindow::~MainWindow()
{
    // Children outlive this class's part of the object: whatever they say while they are destroyed must not
    // reach MainWindow's slots (UBSan's "downcast of address ... not an object of type MainWindow").
    if (!m_document)
        return; // never built
    for (QObject *sender : std::initializer_list<QObject *> {
             m_document, m_document->model(), m_connection, m_fileWatcher, m_autoSave, m_history })
        sender->disconnect(this);
}

void MainWindow::updateMachineStatus()
{
    QString text;
    switch (m_connection->state()) {
    case MachineConnection::State::Disconnected:
        text = tr("Not connected");
        break;
    case MachineConnection::State::Connecting:
        text = tr("Connecting to %1…").arg(m_connection->description());
        break;
    case MachineConnection::State::Connected: {
        const auto status = m_connection->link() ? m_connection->link()->lastStatus() : std::nullopt;
        text = m_connection->description() + u" — "_s
            + (m_connection->isHalted() ? tr("halted")
                    : status            ? machineStateName(status->state)
                                        : tr("connected"));
        if (m_connection->isBusy())
            text += u" — "_s + m_connection->operation();
        break;
    }
    }
    m_machineLabel->setText(text);
    const bool ready
        = m_connection->state() == MachineConnection::State::Connected && !m_connection->isBusy();
    // Motion waits for Unlock while halted; Unlock itself is what a halted machine needs.
    if (auto *probe = findChild<QAction *>(u"actionProbe"_s))
        probe->setEnabled(m_connection->canOperate() && !recordingBlocked());
    // The stock firmware's M491.1 would only measure again: its panel is hidden, and F6 goes with it.
    if (auto *breakTest = findChild<QAction *>(u"actionBreakTest"_s))
        breakTest->setEnabled(
            m_connection->canOperate() && m_connection->firmware().hasBreakTest() && !recordingBlocked());
    if (auto *unlock = findChild<QAction *>(u"actionUnlock"_s))
        unlock->setEnabled(ready);
    if (auto *stop = findChild<QAction *>(u"actionStop"_s))
        stop->setEnabled(m_connection->state() == MachineConnection::State::Connected);
}

void MainWindow::updateTitle()
{
    const QString name = m_document->isLibraryTable() ? libraryTableTitle()
        : m_document->filePath().isEmpty()            ? tr("Untitled")
                                                      : QFileInfo(m_document->filePath()).fileName();
    setWindowFilePath(m_document->filePath());
    setWindowTitle(name + u"[*] — Toffee"_s);
    setWindowModified(hasUnsavedEdits());
    updateLibraryState();
}

void MainWindow::resizeEvent(QResizeEvent *event)
{
    QMainWindow::resizeEvent(event);
    if (!isVisible())
        return;
    // The machine panel takes at most a third of a narrow window: at 1024 px the table keeps its columns.
    if (const int wide = event->size().width(); wide != event->oldSize().width() && m_machineDock
        && m_machineDock->isVisible() && !m_machineDock->isFloating()
        && dockWidgetArea(m_machineDock) != Qt::BottomDockWidgetArea) {
        const int most = std::max(m_machineDock->minimumSizeHint().width(), wide / 3);
        if (m_machineDock->width() > most)
            resizeDocks({ m_machineDock }, { most }, Qt::Horizontal);
    }
    const int was = event->oldSize().height();
    const int is = event->size().height();
    if (was <= 0 || is <= 0 || was == is)
        return;
    for (QDockWidget *dock :
        { static_cast<QDockWidget *>(m_consoleDock), static_cast<QDockWidget *>(m_historyDock) }) {
        if (dock && dock->isVisible() && !dock->isFloating()
            && dockWidgetArea(dock) == Qt::BottomDockWidgetArea) {
            resizeDocks({ dock }, { std::max(dock->minimumSizeHint().height(), dock->height() * is / was) },
                Qt::Vertical);
            break; // tabbed together: one height
        }
    }
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (m_connection->isBusy()) {
        const auto answer = QMessageBox::warning(this, tr("The machine is busy"),
            tr("The machine is running \"%1\". Stop it and quit?").arg(m_connection->operation()),
            QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Yes) {
            event->ignore();
            return;
        }
        m_connection->stop();
    }
    if (maybeSave()) {
        writeSettings();
        event->accept();
    } else {
        event->ignore();
    }
}

void MainWindow::restoreWindowGeometry()
{
    if (!restoreGeometry(AppSettings().windowGeometry())) {
        // 1280×720 is the smallest workshop screen Toffee is laid out for; never more than the screen has.
        const QSize available = screen() ? screen()->availableGeometry().size() : QSize(1280, 720);
        resize(QSize(1280, 720).boundedTo(available));
    }
}

void MainWindow::restoreDockState()
{
    if (!restoreState(AppSettings().windowState())) {
        resizeDocks({ m_consoleDock }, { 110 }, Qt::Vertical);
        resizeDocks({ m_machineDock }, { 400 }, Qt::Horizontal);
    }
}

void MainWindow::writeSettings()
{
    AppSettings settings;
    settings.setWindowGeometry(saveGeometry());
    settings.setWindowState(saveState());
}

} // namespace Toffee
