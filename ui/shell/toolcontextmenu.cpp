// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/toolcontextmenu.h"
#include "ui/common/askfirst.h"

#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QTableView>

#include "model/document/tooldocument.h"
#include "model/numberformat.h"
#include "serial/machineconnection.h"
#include "ui/machine/machinedock.h"
#include "ui/machine/offseteditor.h"
#include "ui/machine/probepanel.h"
#include "ui/table/tooltablepanel.h"

using namespace Qt::StringLiterals;

namespace Toffee {

ToolContextMenu::ToolContextMenu(QWidget *window, MachineConnection *connection, ToolDocument *document,
    ToolTablePanel *table, MachineDock *machine)
    : QObject(window)
    , m_window(window)
    , m_connection(connection)
    , m_document(document)
    , m_table(table)
    , m_machine(machine)
    , m_makeActive(new QAction(tr("Make &Active (No Probe)…"), window))
    , m_setTlo(new QAction(tr("&Set Its TLO…"), window))
    , m_changeTo(new QAction(tr("&Change to It (M6)…"), window))
{
    m_makeActive->setObjectName(u"actionMakeActive"_s);
    m_makeActive->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_M));
    m_makeActive->setShortcutContext(Qt::WindowShortcut);
    m_setTlo->setObjectName(u"actionSetTlo"_s);
    m_setTlo->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    m_setTlo->setShortcutContext(Qt::WindowShortcut);
    m_changeTo->setObjectName(u"actionChangeTo"_s);
    m_changeTo->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_M));
    m_changeTo->setShortcutContext(Qt::WindowShortcut);
    window->addAction(m_makeActive);
    window->addAction(m_setTlo);
    window->addAction(m_changeTo);
    connect(m_changeTo, &QAction::triggered, this, [this] { changeTo(); });
    connect(m_makeActive, &QAction::triggered, this, [this] { makeActive(); });
    connect(m_setTlo, &QAction::triggered, this, &ToolContextMenu::setTlo);
    QTableView *view = m_table->view();
    view->setContextMenuPolicy(Qt::CustomContextMenu); // the Menu key and Shift+F10 ask for it too
    connect(view, &QWidget::customContextMenuRequested, this, &ToolContextMenu::showMenu);
    connect(view->selectionModel(), &QItemSelectionModel::selectionChanged, this, &ToolContextMenu::update);
    connect(m_connection, &MachineConnection::stateChanged, this, &ToolContextMenu::update);
    connect(m_connection, &MachineConnection::haltedChanged, this, &ToolContextMenu::update);
    connect(m_connection, &MachineConnection::busyChanged, this, &ToolContextMenu::update);
    connect(m_connection, &MachineConnection::statusChanged, this, &ToolContextMenu::update);
    update();
}

int ToolContextMenu::selectedTool() const
{
    const QList<int> numbers = m_table->selectedToolNumbers();
    return numbers.size() == 1 ? numbers.front() : -1;
}

void ToolContextMenu::update()
{
    const int tool = selectedTool();
    const bool ready = m_connection->canOperate();
    const bool active = tool >= 0 && m_connection->activeTool() == tool;
    m_makeActive->setEnabled(ready && tool >= 0 && !active);
    m_makeActive->setText(
        tool >= 0 ? tr("Make T%1 &Active (No Probe)…").arg(tool) : tr("Make &Active (No Probe)…"));
    m_makeActive->setToolTip(!ready ? tr("Connect to a machine that is idle and not halted first.")
            : tool < 0              ? tr("Select one tool of the table.")
            : active                ? tr("T%1 is already the active tool.").arg(tool)
                     : tr("Tell the machine that T%1 is in the spindle, without probing it.").arg(tool));
    m_changeTo->setEnabled(ready && tool > 0 && !active);
    m_changeTo->setText(tool > 0 ? tr("&Change to T%1 (M6)…").arg(tool) : tr("&Change to It (M6)…"));
    m_changeTo->setToolTip(!ready ? tr("Connect to a machine that is idle and not halted first.")
            : tool <= 0           ? tr("Select one tool of the table.")
            : active
            ? tr("T%1 is already the active tool.").arg(tool)
            : tr("The machine's tool change to T%1, then T%1 measured on the tool setter.").arg(tool));
    m_setTlo->setEnabled(ready && active);
    m_setTlo->setText(tool >= 0 ? tr("&Set T%1's TLO…").arg(tool) : tr("&Set Its TLO…"));
    m_setTlo->setToolTip(active || !ready
            ? tr("Set the TLO of the tool in the spindle by hand (Machine ▸ Set the offset by hand).")
            : tr("Only the tool in the spindle's TLO can be set: make T%1 active first.").arg(tool));
}

QMenu *ToolContextMenu::buildMenu()
{
    update();
    delete m_menu;
    m_menu = new QMenu(m_table);
    m_menu->setObjectName(u"toolContextMenu"_s);
    m_menu->setToolTipsVisible(true);
    const int tool = selectedTool();
    m_menu->addAction(m_changeTo);
    m_menu->addAction(m_makeActive);
    m_menu->addAction(m_setTlo);
    // The Probe panel's own buttons, as actions: the same checks decide.
    auto button = [this](const QString &name, const QString &text, const QKeySequence &key) {
        auto *b = m_machine->findChild<QPushButton *>(name);
        QAction *a = m_menu->addAction(text);
        a->setObjectName(name + u"Action"_s);
        a->setShortcut(key); // shown, not owned: the button and the window's action have it
        a->setShortcutContext(Qt::WidgetShortcut);
        a->setEnabled(b && b->isEnabled());
        a->setToolTip(b ? b->toolTip() : QString());
        if (b)
            connect(a, &QAction::triggered, b, &QPushButton::click);
    };
    button(u"restoreButton"_s,
        tool >= 0 ? tr("&Restore T%1's Known TLO…").arg(tool) : tr("&Restore Known TLO…"),
        QKeySequence(Qt::CTRL | Qt::Key_R));
    const auto active = m_connection->activeTool();
    button(u"probeButton"_s,
        active && *active >= 0 ? tr("&Probe T%1 (in the Spindle)").arg(*active)
                               : tr("&Probe the Tool in the Spindle"),
        QKeySequence(Qt::Key_F5));
    m_menu->addSeparator();
    for (const QString &name : { u"actionNewCutter"_s, u"actionRemoveTool"_s }) {
        if (auto *action = m_window->findChild<QAction *>(name))
            m_menu->addAction(action);
    }
    return m_menu;
}

void ToolContextMenu::showMenu(const QPoint &position)
{
    QTableView *view = m_table->view();
    // The row under the pointer becomes the selection, as a table's menu does everywhere.
    const QModelIndex index = view->indexAt(position);
    if (index.isValid() && !view->selectionModel()->isRowSelected(index.row(), index.parent()))
        view->selectRow(index.row());
    buildMenu()->popup(view->viewport()->mapToGlobal(position));
}

void ToolContextMenu::makeActive(bool confirm)
{
    const int tool = selectedTool();
    if (tool < 0 || !m_connection->canOperate() || m_connection->activeTool() == tool)
        return;
    const QString command = m_connection->controllerKind() == ControllerKind::Carvera
        ? u"M493.2 T%1"_s.arg(tool)
        : u"M61 Q%1"_s.arg(tool);
    if (confirm) {
        const bool inSpindle = askFirst(m_window,
            { QMessageBox::Question, tr("Make T%1 active?").arg(tool),
                tr("Is T%1 in the spindle now?").arg(tool),
                tr("The machine takes T%1 as the tool in the spindle, without probing it. It keeps the TLO "
                   "in "
                   "force now (another tool's, or none): probe T%1 or restore its TLO before it "
                   "cuts.\n\nSends: %2")
                    .arg(tool)
                    .arg(command),
                tr("T%1 Is in the Spindle").arg(tool), u"makeActiveYesButton"_s, u"makeActiveQuestion"_s });
        if (!inSpindle)
            return;
    }
    m_connection->selectTool(tool, [this, tool](const SessionResult &r) {
        if (!r.ok())
            QMessageBox::warning(m_window, tr("T%1 was not made active").arg(tool),
                r.message + u"\n\n"_s + tr("The machine's tool is as it was."));
    });
}

void ToolContextMenu::changeTo(bool confirm)
{
    const int tool = selectedTool();
    if (tool <= 0 || !m_connection->canOperate() || m_connection->activeTool() == tool)
        return;
    // Who does the change: the Carvera from its rack, else the person at the machine (grblHAL's every M6).
    const bool fromRack = m_connection->firmware().hasRack();
    const QString how = fromRack
        ? tr(
            "The machine puts the tool in the spindle back, takes T%1 from its rack (or asks you for it when "
            "it is not in the rack) and measures it on the tool setter. Keep hands clear.")
              .arg(tool)
        : tr(
            "The machine stops and waits for you to put T%1 in the spindle; press cycle start on the machine "
            "(or Continue here), and T%1 is measured on the tool setter. Keep hands clear.")
              .arg(tool);
    if (confirm
        && !askFirst(m_window,
            { QMessageBox::Question, tr("Change to T%1?").arg(tool), tr("Change to T%1 now?").arg(tool),
                how + u"\n\n"_s + tr("Sends: M6 T%1").arg(tool), tr("Change to T%1").arg(tool),
                u"changeToYesButton"_s, u"changeToQuestion"_s }))
        return;
    m_connection->changeTool(tool, [this, tool](const SessionResult &r) {
        if (!r.ok()) {
            // Ended by the operator: the wait box said so already.
            if (!r.message.isEmpty())
                QMessageBox::warning(m_window, tr("The change to T%1 did not finish").arg(tool),
                    r.message + u"\n\n"_s + tr("Nothing was written to the tool table."));
            return;
        }
        const auto recorded = r.recording ? m_document->record(*r.recording) : Result<void> {};
        if (auto *main = qobject_cast<QMainWindow *>(m_window); main && recorded && r.tlo)
            main->statusBar()->showMessage(
                tr("T%1 is in the spindle, measured: TLO %2, recorded in the table.")
                    .arg(tool)
                    .arg(millimetres(r.tlo->tlo())));
        if (!recorded)
            QMessageBox::warning(m_window, tr("T%1 was not recorded").arg(tool),
                tr("T%1 is in the spindle, but its TLO could not be recorded: %2")
                    .arg(tool)
                    .arg(recorded.error().message));
    });
}

void ToolContextMenu::setTlo()
{
    if (!m_setTlo->isEnabled())
        return;
    m_machine->show();
    m_machine->raise();
    OffsetEditor *editor = m_machine->offsetEditor();
    editor->setMode(OffsetEditor::SetTlo);
    editor->focusValue();
}

} // namespace Toffee
