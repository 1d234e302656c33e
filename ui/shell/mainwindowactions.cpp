// SPDX-License-Identifier: GPL-3.0-or-later
// The window's menus, toolbar and their actions, each with its shortcut and icon.
#include "ui/shell/aboutbox.h"
#include "ui/shell/guidedialog.h"
#include "ui/shell/mainwindow.h"

#include <QAction>
#include <QActionGroup>
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
    // What only a controller with a setter cycle of Toffee's and a table of its own (grblHAL, LinuxCNC) has.
    machine->addSeparator();
    add(u"actionToolSetter"_s, tr("Tool &Setter…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T),
        [this] { editToolSetter(); });
    add(u"actionLinuxCncAccess"_s, tr("&LinuxCNC Access…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_X),
        [this] { editLinuxCncAccess(); });
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
    // Each dock shown and hidden from View, Ctrl+1 to Ctrl+4.
    const std::pair<QDockWidget *, QString> docks[]
        = { { m_machineDock, u"actionShowMachine"_s }, { m_consoleDock, u"actionShowConsole"_s },
              { m_historyDock, u"actionShowHistory"_s }, { m_rackDock, u"actionShowRack"_s } };
    int key = Qt::Key_1;
    for (const auto &[dock, name] : docks) {
        QAction *shown = dock->toggleViewAction();
        shown->setObjectName(name);
        shown->setShortcut(QKeySequence(Qt::CTRL | Qt::Key(key++)));
        view->addAction(shown);
    }
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
    createLanguageMenu(view);
    QMenu *help = menuBar()->addMenu(tr("&Help"));
    QAction *guide = help->addAction(tr("User's &Guide"), this, [this] { showGuide(this); });
    guide->setObjectName(u"actionGuide"_s);
    guide->setShortcut(QKeySequence::HelpContents); // F1
    help->addSeparator();
    QAction *about = help->addAction(tr("&About Toffee"), this, [this] { showAbout(this); });
    about->setObjectName(u"actionAbout"_s);
    about->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F1));
    about->setMenuRole(QAction::AboutRole);
}

// View ▸ Language: the window's language from its next start (a running window keeps the one it was built
// in). Each language is named in itself, so that a window in the wrong one still shows the way back.
void MainWindow::createLanguageMenu(QMenu *view)
{
    QMenu *menu = view->addMenu(tr("&Language"));
    menu->setObjectName(u"menuLanguage"_s);
    auto *group = new QActionGroup(menu);
    const QString chosen = AppSettings().language();
    struct Choice
    {
        QString code;
        QString name;
        QString object;
        QKeySequence key;
    };
    const Choice choices[] = { { QString(), tr("The System's"), u"actionLanguageSystem"_s,
                                   QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_0) },
        { u"en"_s, u"English"_s, u"actionLanguageEnglish"_s, QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_1) },
        { u"de"_s, u"Deutsch"_s, u"actionLanguageGerman"_s, QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_2) },
        { u"zh_CN"_s, u"简体中文"_s, u"actionLanguageChinese"_s,
            QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_3) } };
    for (const Choice &c : choices) {
        QAction *action = menu->addAction(c.name);
        action->setObjectName(c.object);
        action->setShortcut(c.key);
        action->setCheckable(true);
        action->setChecked(c.code == chosen);
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, c] {
            AppSettings().setLanguage(c.code);
            statusBar()->showMessage(tr("The window speaks %1 from its next start.")
                                         .arg(c.code.isEmpty() ? tr("the system's language") : c.name),
                10000);
        });
    }
}

} // namespace Toffee
