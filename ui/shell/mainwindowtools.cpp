// SPDX-License-Identifier: GPL-3.0-or-later
// The table's own edits from the window: add a tool, remove tools (asked first when measured), a new cutter.
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

} // namespace Toffee
