// SPDX-License-Identifier: GPL-3.0-or-later
// The window's file side: open, save, save as (with the question before a format that drops fields), import,
// export, recent files, unsaved changes, and a file changed by another program.
#include "ui/shell/mainwindow.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>

#include "model/camimport/camlibrary.h"
#include "model/camimport/importpreview.h"
#include "model/document/filewatcher.h"
#include "model/document/tooldocument.h"
#include "ui/common/appsettings.h"
#include "ui/table/importpreviewdialog.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QString fileFilters()
{
    return MainWindow::tr("Tool tables (*.json *.tbl *.csv);;Toffee tool table (*.json);;LinuxCNC tool table "
                          "(*.tbl);;CSV spreadsheet (*.csv);;All files (*)");
}

// Import takes CAM libraries as well: a .json is a Toffee table or a Fusion library by its content.
QString importFilters()
{
    return MainWindow::tr(
        "Tool tables and CAM libraries (*.json *.tbl *.csv *.tools *.hsmlib *.nc *.gcode *.cnc "
        "*.ngc *.tap *.txt);;Toffee tool table (*.json);;LinuxCNC tool table (*.tbl);;CSV "
        "spreadsheet (*.csv);;Fusion tool library (*.json *.tools);;HSM tool library "
        "(*.hsmlib);;Makera CAM program (*.nc *.gcode *.cnc *.ngc *.tap *.txt);;All files (*)");
}

} // namespace

void MainWindow::fileChangedOnDisk(const QString &path)
{
    if (path != m_document->filePath())
        return;
    const QString question = m_document->isModified()
        ? tr("%1 was changed by another program.\n\nReload it? Your unsaved changes in Toffee would be lost.")
        : tr("%1 was changed by another program.\n\nReload it?");
    if (QMessageBox::question(this, tr("File changed on disk"), question.arg(path)) != QMessageBox::Yes)
        return;
    if (auto r = m_document->open(path); !r) {
        showError(tr("Cannot reload the tool table"),
            r.error().text() + u"\n\n"_s + tr("The table on screen has not been changed."));
        return;
    }
    m_fileWatcher->watch(path);
    statusBar()->showMessage(tr("Reloaded %1").arg(path), 5000);
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

void MainWindow::rememberFile(const QString &path)
{
    m_fileWatcher->watch(path);
    AppSettings settings;
    settings.addRecentFile(QFileInfo(path).absoluteFilePath());
    settings.setLastDirectory(QFileInfo(path).absolutePath());
    updateRecentFiles();
}

bool MainWindow::openFile(const QString &path)
{
    if (auto r = m_document->open(path); !r) {
        showError(tr("Cannot open the tool table"),
            r.error().text() + u"\n\n"_s + tr("The table on screen has not been changed."));
        return false;
    }
    rememberFile(path);
    statusBar()->showMessage(tr("Opened %1").arg(path), 5000);
    return true;
}

void MainWindow::newTable()
{
    if (maybeSave()) {
        m_document->newTable();
        m_fileWatcher->watch({});
        updateTitle(); // from a machine's table the path stays empty: nothing else says it changed
    }
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
               losses.join(u'\n') + u"\n\n"_s
                   + tr("After saving, the table on screen shows what the file holds; until the window is "
                        "closed, "
                        "Undo brings the rest back. To keep everything, Cancel and use Save As with a .json "
                        "file.\n\nSave anyway?"),
               QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
        == QMessageBox::Yes;
}

bool MainWindow::save()
{
    if (m_document->isLibraryTable())
        return saveLibraryTable();
    if (m_document->filePath().isEmpty())
        return saveAs();
    if (!confirmLossySave(m_document->filePath()))
        return false;
    if (auto r = m_document->save(); !r) {
        showError(tr("Cannot save the tool table"), r.error().text());
        return false;
    }
    m_fileWatcher->watch(m_document->filePath());
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
    rememberFile(path);
    return true;
}

void MainWindow::importTable()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import Tools"), AppSettings().lastDirectory(), importFilters());
    if (!path.isEmpty())
        importFile(path);
}

bool MainWindow::importFile(const QString &path)
{
    if (isCamLibraryFile(path))
        return importCamLibrary(path);
    auto count = m_document->importFrom(path);
    if (!count) {
        showError(tr("Cannot import"), count.error().text() + u"\n\n"_s + tr("Nothing was imported."));
        return false;
    }
    statusBar()->showMessage(tr("Imported %1 tools from %2").arg(count.value()).arg(path), 5000);
    return true;
}

bool MainWindow::importCamLibrary(const QString &path)
{
    auto library = loadCamLibrary(path);
    // Tools that give no unit: the operator says which, or nothing is imported; never a guess.
    std::optional<Units> assumed;
    if (library) {
        if (const QString names = ImportPreview::toolsWithoutUnitNamed(library.value()); !names.isEmpty()) {
            QMessageBox box(QMessageBox::Question, tr("Which unit?"),
                tr("Tools in %2 without a unit (Fusion writes \"unit\" on every tool): %1. Their diameters "
                   "and "
                   "lengths "
                   "are read in the unit you choose; the preview shows each of them before anything changes.")
                    .arg(names, QFileInfo(path).fileName()),
                QMessageBox::Cancel, this);
            box.setObjectName(u"camUnitsBox"_s);
            QPushButton *mm = box.addButton(tr("Millimetres"), QMessageBox::AcceptRole);
            mm->setObjectName(u"camUnitsMillimetres"_s);
            QPushButton *in = box.addButton(tr("Inches"), QMessageBox::AcceptRole);
            in->setObjectName(u"camUnitsInches"_s);
            box.setDefaultButton(QMessageBox::Cancel);
            box.exec();
            if (box.clickedButton() == mm)
                assumed = Units::Millimetre;
            else if (box.clickedButton() == in)
                assumed = Units::Inch;
            else
                return false;
        }
    }
    auto preview = library ? ImportPreview::build(m_document->table(), library.value(), assumed)
                           : Result<ImportPreview>(library.error());
    if (!preview) {
        showError(tr("Cannot import"), preview.error().text() + u"\n\n"_s + tr("Nothing was imported."));
        return false;
    }
    ImportPreviewDialog dialog(preview.value(), path, camFormatName(library.value().format), this);
    if (dialog.exec() != QDialog::Accepted)
        return false;
    m_document->replaceTable(
        preview.value().merged(), tr("Import tools from %1").arg(QFileInfo(path).fileName()));
    // A tool whose cutter the library changed: the old cutter ends in the history too.
    for (const ImportedTool &changed : preview.value().newCutters())
        recordHistory(Recording::newCutter(changed.number, changed.endedTlo, changed.endedReferenceMz));
    if (!preview.value().newCutters().isEmpty())
        refreshToolLife();
    statusBar()->showMessage(tr("Imported from %1: %2").arg(path, preview.value().summary()), 5000);
    return true;
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

bool MainWindow::maybeSave()
{
    if (!hasUnsavedEdits())
        return true;
    const auto answer = QMessageBox::warning(this, tr("Unsaved changes"),
        tr("The tool table has changes that are not saved.\nSave them first?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

} // namespace Toffee
