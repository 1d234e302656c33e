// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/mainwindow.h"
#include "ui/aboutbox.h"

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
#include "ui/appearance.h"
#include "ui/appsettings.h"
#include "ui/breaktestpanel.h"
#include "ui/connectionpanel.h"
#include "ui/consoledock.h"
#include "ui/exportdialog.h"
#include "ui/historydock.h"
#include "ui/machinedock.h"
#include "ui/probepanel.h"
#include "ui/rackpanel.h"
#include "ui/tlopanel.h"
#include "ui/toolchangewait.h"
#include "ui/toolcontextmenu.h"
#include "ui/tooltablepanel.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// The icon of each action, by its object name (empty: none).
QString iconFor(const QString &action)
{
    static const QHash<QString, QString> icons = {
        { u"actionNew"_s, u"new"_s },
        { u"actionOpen"_s, u"open"_s },
        { u"actionSave"_s, u"save"_s },
        { u"actionAddTool"_s, u"add"_s },
        { u"actionRemoveTool"_s, u"remove"_s },
        { u"actionProbe"_s, u"probe"_s },
        { u"actionBreakTest"_s, u"breaktest"_s },
        { u"actionUnlock"_s, u"unlock"_s },
        { u"actionStop"_s, u"stop"_s },
        { u"actionConnect"_s, u"connect"_s },
    };
    return icons.value(action);
}

} // namespace

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

template<typename Slot>
QAction *MainWindow::addMenuAction(
    QMenu *menu, const QString &name, const QString &text, const QKeySequence &shortcut, Slot slot)
{
    auto *action = new QAction(text, this);
    action->setObjectName(name);
    action->setShortcut(shortcut);
    action->setIcon(themeIcon(iconFor(name)));
    connect(action, &QAction::triggered, this, slot);
    menu->addAction(action);
    return action;
}

void MainWindow::createActions()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QToolBar *toolBar = addToolBar(tr("Main"));
    toolBar->setObjectName(u"mainToolBar"_s);

    auto add = [this](QMenu *menu, const QString &name, const QString &text, const QKeySequence &shortcut,
                   auto slot) {
        return addMenuAction(menu, name, text, shortcut, slot);
    };
    toolBar->addAction(add(file, u"actionNew"_s, tr("&New"), QKeySequence::New, &MainWindow::newTable));
    toolBar->addAction(add(file, u"actionOpen"_s, tr("&Open…"), QKeySequence::Open, &MainWindow::open));
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(u"menuRecent"_s);
    toolBar->addAction(add(file, u"actionSave"_s, tr("&Save"), QKeySequence::Save, [this] { save(); }));
    add(file, u"actionSaveAs"_s, tr("Save &As…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
        [this] { saveAs(); });
    createLibraryActions(file);
    file->addSeparator();
    add(file, u"actionImport"_s, tr("Import &Tools…"), QKeySequence(Qt::CTRL | Qt::Key_I),
        &MainWindow::importTable);
    add(file, u"actionExport"_s, tr("&Export…"), QKeySequence(Qt::CTRL | Qt::Key_E),
        &MainWindow::exportTable);
    add(file, u"actionExportProgram"_s, tr("Export for &Controller…"),
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E), [this] {
            ExportDialog dialog(m_document->table(), this);
            dialog.exec();
        });
    file->addSeparator();
    add(file, u"actionCheckJob"_s, tr("Check &Job…"), QKeySequence(Qt::CTRL | Qt::Key_J),
        &MainWindow::checkJob);
    file->addSeparator();
    add(file, u"actionQuit"_s, tr("&Quit"), QKeySequence(Qt::CTRL | Qt::Key_Q), &QWidget::close);

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    QAction *undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(u"actionUndo"_s);
    undo->setIcon(themeIcon(u"undo"_s));
    undo->setShortcut(QKeySequence::Undo);
    QAction *redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(u"actionRedo"_s);
    redo->setIcon(themeIcon(u"redo"_s));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    toolBar->addSeparator();
    toolBar->addAction(undo);
    toolBar->addAction(redo);
    toolBar->addSeparator();
    toolBar->addAction(add(
        edit, u"actionAddTool"_s, tr("&Add Tool"), QKeySequence(Qt::CTRL | Qt::Key_T), &MainWindow::addTool));
    m_removeAction = add(
        edit, u"actionRemoveTool"_s, tr("&Remove Tool"), QKeySequence::Delete, &MainWindow::removeTools);
    m_removeAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_tablePanel->view()->addAction(m_removeAction);
    toolBar->addAction(m_removeAction);
    m_newCutterAction = add(edit, u"actionNewCutter"_s, tr("New &Cutter…"),
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N), &MainWindow::newCutter);
    m_newCutterAction->setToolTip(tr("The selected tool's pocket holds another cutter: its TLO, length, wear "
                                     "and break mark end, and it is measured before it cuts"));
    edit->addSeparator();
    add(edit, u"actionFind"_s, tr("&Filter…"), QKeySequence::Find, [this] {
        m_tablePanel->filterEdit()->setFocus();
        m_tablePanel->filterEdit()->selectAll();
    });
    updateRecentFiles();
}

void MainWindow::createMachineActions()
{
    QMenu *machine = menuBar()->addMenu(tr("&Machine"));
    auto add
        = [this, machine](const QString &name, const QString &text, const QKeySequence &shortcut, auto slot) {
              return addMenuAction(machine, name, text, shortcut, slot);
          };
    QToolBar *toolBar = addToolBar(tr("Machine"));
    toolBar->setObjectName(u"machineToolBar"_s);
    toolBar->addAction(
        add(u"actionConnect"_s, tr("&Connect / Disconnect"), QKeySequence(Qt::CTRL | Qt::Key_K),
            [this] { m_machineDock->connectionPanel()->toggleConnection(); }));
    machine->addSeparator();
    toolBar->addAction(add(u"actionProbe"_s, tr("&Probe Current Tool…"), QKeySequence(Qt::Key_F5),
        [this] { m_machineDock->probePanel()->probe(); }));
    toolBar->addAction(add(u"actionBreakTest"_s, tr("&Break Test…"), QKeySequence(Qt::Key_F6),
        [this] { m_machineDock->breakTestPanel()->run(); }));
    toolBar->addAction(add(u"actionUnlock"_s, tr("&Unlock"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_U),
        [this] { m_machineDock->tloPanel()->unlock(); }));
    toolBar->addAction(add(u"actionStop"_s, tr("&Stop the Machine"), QKeySequence(Qt::CTRL | Qt::Key_Period),
        [this] { m_machineDock->probePanel()->cancel(); }));
    // The rack's sequences, from the keyboard too; the Rack panel comes forward to show their progress.
    machine->addSeparator();
    QMenu *rack = machine->addMenu(tr("R&ack"));
    rack->setObjectName(u"menuRack"_s);
    QAction *measureRack = addMenuAction(rack, u"actionMeasureRack"_s, tr("&Measure Rack…"),
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F5), [this] {
            m_rackDock->raise();
            m_rackPanel->measureRack();
        });
    QAction *checkRack = addMenuAction(rack, u"actionCheckRack"_s, tr("&Check Rack…"),
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F6), [this] {
            m_rackDock->raise();
            m_rackPanel->checkRack();
        });
    auto rackState = [this, measureRack, checkRack] {
        measureRack->setEnabled(m_rackPanel->canMeasure() && !recordingBlocked());
        checkRack->setEnabled(m_rackPanel->canCheck() && !recordingBlocked());
    };
    connect(m_rackPanel, &RackPanel::stateChanged, this, rackState);
    rackState();
    // What only a controller with a setter cycle of Toffee's and a table of its own (grblHAL) has.
    machine->addSeparator();
    add(u"actionToolSetter"_s, tr("Tool &Setter…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T),
        [this] { editToolSetter(); });
    m_pushOffsetsAction = add(u"actionPushOffsets"_s, tr("Push &Offsets to the Controller…"),
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P), [this] { pushOffsets(); });
    m_pullOffsetsAction = add(u"actionPullOffsets"_s, tr("P&ull Offsets from the Controller…"),
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_G), [this] { pullOffsets(); });
    machine->addSeparator();
    add(u"actionRecordRun"_s, tr("&Record a Program Run…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R),
        [this] { recordProgramRun(); });
    add(u"actionHistorySettings"_s, tr("History &Library…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L),
        [this] { editHistorySettings(); });
    QMenu *view = menuBar()->addMenu(tr("&View"));
    QAction *machineView = m_machineDock->toggleViewAction();
    machineView->setObjectName(u"actionShowMachine"_s);
    machineView->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_1));
    view->addAction(machineView);
    QAction *consoleView = m_consoleDock->toggleViewAction();
    consoleView->setObjectName(u"actionShowConsole"_s);
    consoleView->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_2));
    view->addAction(consoleView);
    QAction *historyView = m_historyDock->toggleViewAction();
    historyView->setObjectName(u"actionShowHistory"_s);
    historyView->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_3));
    view->addAction(historyView);
    QAction *rackView = m_rackDock->toggleViewAction();
    rackView->setObjectName(u"actionShowRack"_s);
    rackView->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_4));
    view->addAction(rackView);
    view->addSeparator();
    auto *dark = new QAction(tr("&Dark Palette"), this);
    dark->setObjectName(u"actionDarkPalette"_s);
    dark->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_D));
    dark->setCheckable(true);
    dark->setChecked(palette().color(QPalette::Window).lightness() < 128);
    connect(dark, &QAction::toggled, this, [](bool on) {
        AppSettings().setDarkPalette(on);
        applyPalette(on);
    });
    view->addAction(dark);
    QMenu *help = menuBar()->addMenu(tr("&Help"));
    QAction *about = help->addAction(tr("&About Toffee"), this, [this] { showAbout(this); });
    about->setObjectName(u"actionAbout"_s);
    about->setShortcut(QKeySequence(Qt::Key_F1)); // the one help there is
    about->setMenuRole(QAction::AboutRole);
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

void MainWindow::addTool()
{
    const Tool tool = m_document->newTool();
    if (tool.number < 0) {
        showError(tr("Cannot add a tool"), tr("Every tool number is in use."));
        return;
    }
    if (auto r = m_document->addTool(tool); !r) {
        showError(tr("Cannot add a tool"), r.error().text());
        return;
    }
    m_tablePanel->selectTool(tool.number);
    m_tablePanel->view()->setFocus();
}

// A tool with a measured TLO is an operator's measurement: removing it asks first (naming them); a tool
// without one goes at once. Either way Undo brings it back.
void MainWindow::removeTools()
{
    const QList<int> numbers = m_tablePanel->selectedToolNumbers();
    QStringList measured;
    for (int number : numbers) {
        if (const Tool *tool = m_document->table().find(number); tool && tool->measuredTlo)
            measured << u"T"_s + QString::number(number);
    }
    if (!measured.isEmpty()) {
        QMessageBox box(QMessageBox::Question,
            numbers.size() == 1 ? tr("Remove T%1?").arg(numbers.front())
                                : tr("Remove %1 tools?").arg(numbers.size()),
            tr("%1 has a measured TLO, which goes with it from the table (the history keeps its "
               "measurements).")
                .arg(measured.join(u", "_s)),
            QMessageBox::Cancel, this);
        box.setInformativeText(tr("Edit ▸ Undo brings it back."));
        QPushButton *remove = box.addButton(tr("Remove"), QMessageBox::DestructiveRole);
        remove->setObjectName(u"removeToolsButton"_s);
        box.setDefaultButton(QMessageBox::Cancel);
        box.exec();
        if (box.clickedButton() != remove)
            return;
    }
    m_document->removeTools(numbers);
}

void MainWindow::newCutter()
{
    const QList<int> numbers = m_tablePanel->selectedToolNumbers();
    if (numbers.size() != 1) {
        statusBar()->showMessage(tr("Select the one tool whose cutter was changed."), 5000);
        return;
    }
    const int number = numbers.front();
    const Tool *tool = m_document->table().find(number);
    if (!tool)
        return;
    const Units units = m_document->table().units();
    QStringList ends;
    if (tool->measuredTlo)
        ends << tr("its TLO %1 %2 (%3)")
                    .arg(displayNumber(*tool->measuredTlo, units), unitsSymbol(units),
                        tool->tloSource == TloSource::Manual       ? tr("set by hand")
                            : tool->tloSource == TloSource::Pulled ? tr("read from the controller")
                                                                   : tr("measured"));
    if (tool->lengthGeometry != 0.0)
        ends << tr("its length %1 %2").arg(displayNumber(tool->lengthGeometry, units), unitsSymbol(units));
    if (tool->lengthWear != 0.0 || tool->radiusWear != 0.0)
        ends << tr("its wear (length %1, radius %2)")
                    .arg(displayNumber(tool->lengthWear, units), displayNumber(tool->radiusWear, units));
    if (tool->breakTestFailed)
        ends << tr("its broken mark");
    if (tool->lifeLimitMinutes || tool->lifeLimitUses || m_document->model()->usedLife(number).uses > 0)
        ends << tr("its used life");
    QMessageBox box(QMessageBox::Question, tr("New cutter in T%1?").arg(number),
        ends.isEmpty()
            ? tr("T%1 gets a new cutter. Measure it on the tool setter before it cuts.").arg(number)
            : tr("T%1 gets a new cutter: %2 belong to the old one and end here (the history keeps "
                 "them as the old cutter's). Measure T%1 on the tool setter before it cuts.")
                  .arg(number)
                  .arg(ends.join(u", "_s)),
        QMessageBox::Cancel, this);
    box.setInformativeText(
        tr("Edit ▸ Undo puts the old values back in the table; the history keeps that a new "
           "cutter went in, and the job check warns of a TLO from before it."));
    QPushButton *confirm = box.addButton(tr("New Cutter"), QMessageBox::AcceptRole);
    confirm->setObjectName(u"newCutterButton"_s);
    box.setDefaultButton(QMessageBox::Cancel);
    box.setObjectName(u"newCutterBox"_s);
    box.exec();
    if (box.clickedButton() != confirm)
        return;
    if (auto r = m_document->record(m_document->table().newCutterRecording(number)); !r) {
        showError(tr("Cannot put in a new cutter"), r.error().text());
        return;
    }
    refreshToolLife();
    statusBar()->showMessage(tr("T%1 has a new cutter: measure it before it cuts.").arg(number), 8000);
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
