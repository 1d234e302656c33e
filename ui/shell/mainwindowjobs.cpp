// SPDX-License-Identifier: GPL-3.0-or-later
// The window's jobs: File ▸ Check Job…, and a program dropped on the window.
#include "ui/shell/mainwindow.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMimeData>

#include "model/document/tooldocument.h"
#include "model/formats/tablefile.h"
#include "model/library/historyrecorder.h"
#include "serial/machineconnection.h"
#include "ui/common/appsettings.h"
#include "ui/job/jobcheckdialog.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// The programs a check takes by their name: what posts for the Carvera, LinuxCNC and the others write.
bool isProgramFile(const QString &path)
{
    static const QStringList suffixes
        = { u"nc"_s, u"gcode"_s, u"ngc"_s, u"tap"_s, u"cnc"_s, u"gc"_s, u"g"_s, u"pgm"_s, u"mpf"_s };
    return suffixes.contains(QFileInfo(path).suffix().toLower());
}

// The one local file a drag carries, or nothing.
QString droppedFile(const QMimeData *mime)
{
    if (!mime || !mime->hasUrls() || mime->urls().size() != 1 || !mime->urls().front().isLocalFile())
        return {};
    return mime->urls().front().toLocalFile();
}

} // namespace

void MainWindow::checkJob()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Check Job"), AppSettings().lastDirectory(),
        tr("G-code programs (*.nc *.gcode *.ngc *.tap *.cnc *.gc *.g *.pgm *.mpf);;All files (*)"));
    if (!path.isEmpty())
        openJobCheck(path);
}

JobCheckDialog *MainWindow::openJobCheck(const QString &path)
{
    AppSettings settings;
    JobSources sources { m_document->table(), m_document->filePath(), m_history->location(), machineName(),
        settings.staleAfterDays(), machineReference(), std::nullopt, std::nullopt };
    if (!sources.library->isSet())
        sources.library.reset();
    if (m_connection->firmware().isGrblHal())
        sources.machineDialect = Dialect::GrblHal;
    else if (m_connection->firmware().isLinuxCnc())
        sources.machineDialect = Dialect::LinuxCnc;
    if (const MachineController *controller = m_connection->session()) {
        if (const auto table = controller->controllerTable()) {
            QHash<int, double> tlos;
            for (const ControllerTool &entry : *table)
                tlos.insert(entry.tool, entry.tlo);
            sources.controllerTlos = tlos;
        }
    }
    if (!m_jobDialog) {
        m_jobDialog = new JobCheckDialog(std::move(sources), this);
        m_jobDialog->setAttribute(Qt::WA_DeleteOnClose);
    } else {
        m_jobDialog->setSources(std::move(sources));
    }
    m_jobDialog->show();
    m_jobDialog->raise();
    m_jobDialog->activateWindow();
    m_jobDialog->check(path);
    return m_jobDialog;
}

// The reference MCS Z the connected machine holds, when it has one: stored TLOs measured against another are
// not restored by a preparation.
std::optional<double> MainWindow::machineReference() const
{
    const auto &offsets = m_connection->lastOffsets();
    if (!offsets || offsets->referenceMz == 0.0)
        return std::nullopt; // a reference of 0 is an uncalibrated machine (docs/CARVERA.md § 3)
    return offsets->referenceMz;
}

void MainWindow::dragEnterEvent(QDragEnterEvent *event)
{
    const QString path = droppedFile(event->mimeData());
    if (!path.isEmpty() && (isProgramFile(path) || formatForPath(path)))
        event->acceptProposedAction();
}

// A program dropped on the window is checked; a table is opened, as File ▸ Open would.
void MainWindow::dropEvent(QDropEvent *event)
{
    const QString path = droppedFile(event->mimeData());
    if (path.isEmpty())
        return;
    event->acceptProposedAction();
    if (isProgramFile(path))
        openJobCheck(path);
    else if (formatForPath(path) && maybeSave())
        openFile(path);
}

} // namespace Toffee
