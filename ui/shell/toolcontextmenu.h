// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>

class QAction;
class QMenu;
class QPoint;
class QWidget;

namespace Toffee {

class MachineConnection;
class MachineDock;
class ToolDocument;
class ToolTablePanel;

// What the operator does with a tool of the table, from the table itself: its context menu (the right button,
// the Menu key, Shift+F10) and keys of its own. Make it active (the controller's select: the Carvera's
// M493.2, grblHAL's M61; asked first, since the TLO in force stays), set its TLO (the Machine dock's editor,
// focused), restore it (Ctrl+R), probe it (F5, when it is the tool in the spindle), change to it (M6: the
// Carvera from its rack, grblHAL by hand with cycle start; asked first, then measured); then New Cutter and
// Remove Tool. Each entry is enabled only when it can run, and says why not in its tooltip.
class ToolContextMenu final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ToolContextMenu)

public:
    ToolContextMenu(QWidget *window, MachineConnection *connection, ToolDocument *document,
        ToolTablePanel *table, MachineDock *machine);

    [[nodiscard]] QAction *makeActiveAction() const { return m_makeActive; }
    [[nodiscard]] QAction *setTloAction() const { return m_setTlo; }
    [[nodiscard]] QAction *changeToAction() const { return m_changeTo; }
    // The menu for the selected tool, as it is shown (for tests: not executed).
    [[nodiscard]] QMenu *buildMenu();
    // Asks first unless `confirm` is false; nothing is sent when the machine cannot operate.
    void makeActive(bool confirm = true);
    // The machine's tool change to the selected tool (M6), asked first; the tool is measured after it and
    // recorded. A change the person does (grblHAL's, a Carvera tool outside the rack) waits in
    // ToolChangeWait's box.
    void changeTo(bool confirm = true);

private:
    [[nodiscard]] int selectedTool() const;
    void update();
    void setTlo();
    void showMenu(const QPoint &position);

    QWidget *m_window;
    MachineConnection *m_connection;
    ToolDocument *m_document;
    ToolTablePanel *m_table;
    MachineDock *m_machine;
    QAction *m_makeActive;
    QAction *m_setTlo;
    QAction *m_changeTo;
    QMenu *m_menu = nullptr;
};

} // namespace Toffee
