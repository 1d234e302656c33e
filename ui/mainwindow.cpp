// SPDX-License-Identifier: GPL-3.0-or-later
#include "mainwindow.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QTableView>
#include <QToolBar>
#include <QUndoStack>

#include "appsettings.h"
#include "tooldocument.h"
#include "tooltablepanel.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QString fileFilters()
{
    return MainWindow::tr("Tool tables (*.json *.tbl *.csv);;Toffee tool table (*.json);;LinuxCNC tool table "
                          "(*.tbl);;CSV spreadsheet (*.csv);;All files (*)");
}

} // namespace

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_document(new ToolDocument(this))
    , m_tablePanel(new ToolTablePanel(m_document->model(), this))
{
    setObjectName(u"mainWindow"_s);
    setCentralWidget(m_tablePanel);
    createActions();

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
    connect(m_document->model(), &ToolTableModel::editRejected, this,
        [this](const QString &message) { showError(tr("Value not accepted"), message); });
    updateTitle();
    readSettings();
}

MainWindow::~MainWindow() = default;

void MainWindow::createActions()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QToolBar *toolBar = addToolBar(tr("Main"));
    toolBar->setObjectName(u"mainToolBar"_s);

    auto add
        = [this](QMenu *menu, const QString &name, const QString &text, QKeySequence shortcut, auto slot) {
              auto *action = new QAction(text, this);
              action->setObjectName(name);
              action->setShortcut(shortcut);
              connect(action, &QAction::triggered, this, slot);
              menu->addAction(action);
              return action;
          };
    toolBar->addAction(add(file, u"actionNew"_s, tr("&New"), QKeySequence::New, &MainWindow::newTable));
    toolBar->addAction(add(file, u"actionOpen"_s, tr("&Open…"), QKeySequence::Open, &MainWindow::open));
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(u"menuRecent"_s);
    toolBar->addAction(add(file, u"actionSave"_s, tr("&Save"), QKeySequence::Save, [this] { save(); }));
    add(file, u"actionSaveAs"_s, tr("Save &As…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
        [this] { saveAs(); });
    file->addSeparator();
    add(file, u"actionImport"_s, tr("&Import…"), QKeySequence(Qt::CTRL | Qt::Key_I),
        &MainWindow::importTable);
    add(file, u"actionExport"_s, tr("&Export…"), QKeySequence(Qt::CTRL | Qt::Key_E),
        &MainWindow::exportTable);
    file->addSeparator();
    add(file, u"actionQuit"_s, tr("&Quit"), QKeySequence(Qt::CTRL | Qt::Key_Q), &QWidget::close);

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    QAction *undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(u"actionUndo"_s);
    undo->setShortcut(QKeySequence::Undo);
    QAction *redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(u"actionRedo"_s);
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
    edit->addSeparator();
    add(edit, u"actionFind"_s, tr("&Filter…"), QKeySequence::Find, [this] {
        m_tablePanel->filterEdit()->setFocus();
        m_tablePanel->filterEdit()->selectAll();
    });
    updateRecentFiles();
}

void MainWindow::updateTitle()
{
    const QString name
        = m_document->filePath().isEmpty() ? tr("Untitled") : QFileInfo(m_document->filePath()).fileName();
    setWindowFilePath(m_document->filePath());
    setWindowTitle(name + u"[*] — Toffee"_s);
    setWindowModified(m_document->isModified());
}

void MainWindow::updateRecentFiles()
{
    m_recentMenu->clear();
    const QStringList files = AppSettings().recentFiles();
    for (const QString &path : files) {
        QAction *action = m_recentMenu->addAction(QFileInfo(path).fileName());
        action->setToolTip(path);
        connect(action, &QAction::triggered, this, [this, path] {
            if (maybeSave())
                openFile(path);
        });
    }
    m_recentMenu->setEnabled(!files.isEmpty());
}

void MainWindow::showError(const QString &title, const QString &message)
{
    QMessageBox::warning(this, title, message);
}

bool MainWindow::openFile(const QString &path)
{
    if (auto r = m_document->open(path); !r) {
        showError(tr("Cannot open the tool table"),
            r.error().text() + u"\n\n"_s + tr("The table on screen has not been changed."));
        return false;
    }
    AppSettings settings;
    settings.addRecentFile(QFileInfo(path).absoluteFilePath());
    settings.setLastDirectory(QFileInfo(path).absolutePath());
    updateRecentFiles();
    statusBar()->showMessage(tr("Opened %1").arg(path), 5000);
    return true;
}

void MainWindow::newTable()
{
    if (maybeSave())
        m_document->newTable();
}

void MainWindow::open()
{
    if (!maybeSave())
        return;
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open Tool Table"), AppSettings().lastDirectory(), fileFilters());
    if (!path.isEmpty())
        openFile(path);
}

bool MainWindow::confirmLossySave(const QString &path)
{
    const auto format = formatForPath(path).value_or(TableFormat::Json);
    const QStringList losses = formatLosses(m_document->table(), format);
    if (losses.isEmpty())
        return true;
    return QMessageBox::question(this, tr("Save as %1?").arg(formatName(format)),
               losses.join(u'\n') + u"\n\n"_s + tr("Save anyway?"))
        == QMessageBox::Yes;
}

bool MainWindow::save()
{
    if (m_document->filePath().isEmpty())
        return saveAs();
    if (!confirmLossySave(m_document->filePath()))
        return false;
    if (auto r = m_document->save(); !r) {
        showError(tr("Cannot save the tool table"), r.error().text());
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(m_document->filePath()), 5000);
    return true;
}

bool MainWindow::saveAs()
{
    QString path = QFileDialog::getSaveFileName(
        this, tr("Save Tool Table"), AppSettings().lastDirectory(), fileFilters());
    if (path.isEmpty())
        return false;
    if (!formatForPath(path))
        path += u".json"_s;
    if (!confirmLossySave(path))
        return false;
    if (auto r = m_document->saveAs(path, *formatForPath(path)); !r) {
        showError(tr("Cannot save the tool table"), r.error().text());
        return false;
    }
    AppSettings settings;
    settings.addRecentFile(QFileInfo(path).absoluteFilePath());
    settings.setLastDirectory(QFileInfo(path).absolutePath());
    updateRecentFiles();
    return true;
}

void MainWindow::importTable()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import Tools"), AppSettings().lastDirectory(), fileFilters());
    if (path.isEmpty())
        return;
    auto count = m_document->importFrom(path);
    if (!count) {
        showError(tr("Cannot import"), count.error().text() + u"\n\n"_s + tr("Nothing was imported."));
        return;
    }
    statusBar()->showMessage(tr("Imported %1 tools from %2").arg(count.value()).arg(path), 5000);
}

void MainWindow::exportTable()
{
    QString path = QFileDialog::getSaveFileName(
        this, tr("Export Tool Table"), AppSettings().lastDirectory(), fileFilters());
    if (path.isEmpty())
        return;
    if (!formatForPath(path))
        path += u".json"_s;
    if (!confirmLossySave(path))
        return;
    if (auto r = m_document->exportTo(path, *formatForPath(path)); !r)
        showError(tr("Cannot export"), r.error().text());
    else
        statusBar()->showMessage(tr("Exported to %1").arg(path), 5000);
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

void MainWindow::removeTools()
{
    m_document->removeTools(m_tablePanel->selectedToolNumbers());
}

bool MainWindow::maybeSave()
{
    if (!m_document->isModified())
        return true;
    const auto answer = QMessageBox::warning(this, tr("Unsaved changes"),
        tr("The tool table has changes that are not saved.\nSave them first?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (maybeSave()) {
        writeSettings();
        event->accept();
    } else {
        event->ignore();
    }
}

void MainWindow::readSettings()
{
    AppSettings settings;
    if (!restoreGeometry(settings.windowGeometry()))
        resize(1100, 640);
    restoreState(settings.windowState());
}

void MainWindow::writeSettings()
{
    AppSettings settings;
    settings.setWindowGeometry(saveGeometry());
    settings.setWindowState(saveState());
}

} // namespace Toffee
