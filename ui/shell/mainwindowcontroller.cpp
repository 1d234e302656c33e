// SPDX-License-Identifier: GPL-3.0-or-later
// What only some controllers need, in the window: a grblHAL machine's tool setter (Machine ▸ Tool Setter…)
// and reference, given to it on connecting, and its own tool table pushed from the file or pulled into it
// (Machine ▸ Push Offsets…, Pull Offsets…), each with a preview of the differences first.
#include "model/clock.h"
#include "ui/common/askfirst.h"
#include "ui/shell/mainwindow.h"

#include <cmath>

#include <QAction>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>

#include "model/document/tooldocument.h"
#include "model/library/historyrecorder.h"
#include "model/library/library.h"
#include "model/numberformat.h"
#include "serial/machine/offsetsync.h"
#include "serial/machineconnection.h"
#include "ui/common/appsettings.h"
#include "ui/connection/connectionpanel.h"
#include "ui/connection/linuxcncaccessdialog.h"
#include "ui/machine/machinedock.h"
#include "ui/machine/offsetsyncdialog.h"
#include "ui/machine/toolsetterdialog.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QString controllerName(const MachineConnection *connection)
{
    return connection->firmware().isCarvera() || connection->firmware().kind == FirmwareInfo::Kind::Unknown
        ? connection->firmware().description()
        : controllerKindTitle(connection->controllerKind());
}

} // namespace

void MainWindow::connectControllerSettings()
{
    // Once the controller is known, before anything of its own is sent: the tool setter and the
    // reference Toffee kept for the machine.
    m_connection->setPreparer([this](const MachineIdentity &identity, ConnectionTarget &target) {
        if (const QString refused = bindMachine(identity); !refused.isEmpty())
            return refused;
        if (!keepsOwnReference(identity.controller) && !identity.emulator) {
            target.setter = machineToolSetter();
            // A machine new to the library adopts no reference: its first probe makes one.
            target.reference = m_newMachine ? std::nullopt : keptReference();
        }
        if (identity.controller == ControllerKind::LinuxCnc) {
            const AppSettings::LinuxCncAccess access
                = AppSettings().linuxCncAccess(AppSettings().chosenMachineName());
            target.linuxCncIni = access.ini;
            target.enablePassword = access.enablePassword.toUtf8();
        }
        return QString();
    });
    auto update = [this] {
        const MachineController *controller = m_connection->session();
        const bool connected = m_connection->state() == MachineConnection::State::Connected;
        const bool table = connected && controller && m_connection->firmware().hasToolTable();
        for (QAction *action : { m_pushOffsetsAction, m_pullOffsetsAction }) {
            action->setEnabled(table && m_connection->canOperate() && !recordingBlocked());
            action->setToolTip(table ? action->text().remove(u'&')
                                     : tr("For a controller that keeps a tool table of its own (grblHAL): "
                                          "connect to one first."));
        }
    };
    connect(m_connection, &MachineConnection::stateChanged, this, update);
    connect(m_connection, &MachineConnection::busyChanged, this, update);
    connect(m_connection, &MachineConnection::haltedChanged, this, update);
    update();
}

// The machine's name stands for this machine in the library, or for none yet (then it is new: said, and
// nothing of the library's adopted for it). Bound to another machine: asked whether it is the same one
// reached another way; if not, the connection is refused, naming both. Empty: go on.
QString MainWindow::bindMachine(const MachineIdentity &identity)
{
    m_newMachine = false;
    Library *library = m_history->library();
    if (!library)
        return {};
    const QString name = machineName();
    auto bound = library->bindMachine(name, identity.key());
    if (!bound) {
        m_newMachine = true; // not known now: nothing of the library's is adopted for it
        statusBar()->showMessage(bound.error().message, 10000);
        return {};
    }
    using Kind = Library::MachineBinding::Kind;
    if (bound.value().kind == Kind::New) {
        m_newMachine = true;
        statusBar()->showMessage(
            tr("“%1” is %2, new to the history library.").arg(name, identity.title()), 10000);
        return {};
    }
    if (bound.value().kind == Kind::Same)
        return {};
    const MachineIdentity before = MachineIdentity::fromKey(bound.value().boundTo);
    if (identity.followsFrom(before)) {
        if (auto moved = library->bindMachine(name, identity.key(), true); !moved)
            return moved.error().message;
        statusBar()->showMessage(
            tr("“%1” was %2 before; now it is %3.").arg(name, before.title(), identity.title()), 10000);
        return {};
    }
    const QString other = before.title();
    const bool same = askFirst(this,
        { QMessageBox::Question, tr("Another machine under this name"),
            tr("“%1” in the history library is %2; this is %3.").arg(name, other, identity.title()),
            tr("A machine's reference, tool setter and history are its own. If this is the "
               "same machine reached another way, say so; if not, give it a name of its own "
               "(Machine ▸ History Library…, Machine name) and connect again."),
            tr("Same Machine"), u"sameMachineButton"_s });
    if (!same)
        return tr("Not connected: “%1” in the history library is %2, not %3. Give this machine a name "
                  "of its own (Machine ▸ History Library…, Machine name), then connect again.")
            .arg(name, other, identity.title());
    if (auto rebound = library->bindMachine(name, identity.key(), true); !rebound)
        return rebound.error().message;
    return {};
}

// The reference Toffee kept for this machine: the newest probe's in the history, else the newest measured
// tool's in the table. Nothing: the next probe makes its tool the reference.
std::optional<double> MainWindow::keptReference() const
{
    return keptReferenceMz(m_history->library(), machineName(), m_document->table());
}

// The machine's setter: the library's, else this computer's.
std::optional<ToolSetter> MainWindow::machineToolSetter() const
{
    if (Library *library = m_history->library()) {
        if (const auto kept = library->toolSetter(machineName()); kept && kept.value())
            return kept.value();
    }
    return AppSettings().toolSetter(machineName());
}

void MainWindow::editLinuxCncAccess()
{
    // Kept under the name the operator gave the machine, or, before any, for the machine without a name: the
    // name a machine gets after its kind is known only once connected.
    const QString machine = AppSettings().chosenMachineName();
    LinuxCncAccessDialog dialog(
        machine.isEmpty() ? tr("this machine") : machine, AppSettings().linuxCncAccess(machine), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    AppSettings().setLinuxCncAccess(machine, dialog.access());
    statusBar()->showMessage(tr("The LinuxCNC access is kept on this computer; it applies from the next "
                                "connection."),
        10000);
}

void MainWindow::editToolSetter()
{
    ToolSetterDialog dialog(machineName(), machineToolSetter().value_or(ToolSetter {}), m_connection, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const ToolSetter setter = dialog.setter();
    AppSettings().setToolSetter(machineName(), setter);
    if (Library *library = m_history->library()) {
        if (auto kept = library->setToolSetter(machineName(), setter); !kept)
            statusBar()->showMessage(
                tr("The tool setter is kept on this computer only: %1").arg(kept.error().message), 10000);
    }
    if (MachineController *controller = m_connection->session(); controller && controller->needsToolSetter())
        controller->setToolSetter(setter);
    statusBar()->showMessage(tr("%1's tool setter: X %2, Y %3, lowest Z %4 mm.")
                                 .arg(machineName(), formatNumber(setter.x, NumberFormat::upTo(3).inLocale()),
                                     formatNumber(setter.y, NumberFormat::upTo(3).inLocale()),
                                     formatNumber(setter.zMin, NumberFormat::upTo(3).inLocale())),
        10000);
}

void MainWindow::pushOffsets()
{
    // Read first, so that the preview shows what the controller holds now, not at connecting.
    m_connection->readToolTable([this](const SessionResult &read) {
        if (!read.ok() || !read.controllerTools)
            return showError(tr("Cannot read the controller's tool table"), read.message);
        const int size = m_connection->firmware().toolTableSize;
        const PushPlan plan = planPush(m_document->table(), *read.controllerTools, size);
        QList<OffsetDifference> rows;
        for (const PushedEntry &entry : plan.entries) {
            OffsetDifference row { entry.tool, entry.inFile, entry.inController, false, {} };
            switch (entry.action) {
            case PushedEntry::Action::Beyond:
                row.what = size > 0 ? tr("beyond its table (T1 to T%1)").arg(size) : tr("not in its table");
                break;
            case PushedEntry::Action::Unchanged:
                row.what = tr("unchanged");
                break;
            case PushedEntry::Action::Write:
                row.changes = true;
                row.what = tr("written");
                break;
            }
            rows.append(row);
        }
        const QList<ControllerTool> writes = plan.writes();
        const QString refusal = plan.beyond().isEmpty() ? QString()
            : size > 0
            ? tr("%1 cannot go into %2's table of %3 tools: nothing is pushed. Renumber them, or remove "
                 "their TLOs, and push again.")
                  .arg(plan.beyond().join(u", "_s), controllerName(m_connection))
                  .arg(size)
            : tr("%1 are not in %2's tool table, and G10 L1 cannot add a tool: nothing is pushed. Add them "
                 "to its table, or remove their TLOs, and push again.")
                  .arg(plan.beyond().join(u", "_s), controllerName(m_connection));
        OffsetSyncDialog dialog(
            OffsetSyncDialog::Direction::Push, controllerName(m_connection), rows, refusal, this);
        if (dialog.exec() != QDialog::Accepted || writes.isEmpty())
            return;
        m_connection->writeToolTable(writes, [this, count = writes.size()](const SessionResult &r) {
            if (!r.ok())
                return showError(tr("The offsets were not all pushed"), r.message);
            statusBar()->showMessage(tr("Written into %1's table and read back, all agreeing: %2 TLOs.")
                                         .arg(controllerName(m_connection))
                                         .arg(count),
                10000);
        });
    });
}

void MainWindow::pullOffsets()
{
    m_connection->readToolTable([this](const SessionResult &read) {
        if (!read.ok() || !read.controllerTools)
            return showError(tr("Cannot read the controller's tool table"), read.message);
        QList<OffsetDifference> rows;
        for (const PulledEntry &entry : planPull(m_document->table(), *read.controllerTools)) {
            OffsetDifference row { entry.tool, entry.inFile, entry.inController, entry.changes(), {} };
            switch (entry.action) {
            case PulledEntry::Action::Unchanged:
                row.what = tr("unchanged");
                break;
            case PulledEntry::Action::Empty:
                if (!m_document->table().find(entry.tool))
                    continue; // an empty entry of a tool the file does not have: nothing to say
                row.what = tr("empty in the controller: left alone");
                break;
            case PulledEntry::Action::Take:
                row.what = tr("taken, as set on the controller");
                break;
            case PulledEntry::Action::NewTool:
                row.what = tr("new tool");
                break;
            }
            rows.append(row);
        }
        OffsetSyncDialog dialog(
            OffsetSyncDialog::Direction::Pull, controllerName(m_connection), rows, {}, this);
        if (dialog.exec() != QDialog::Accepted)
            return;
        const QDateTime now = Clock::now();
        QList<Recording> recordings;
        for (const OffsetDifference &row : std::as_const(rows)) {
            // Set on the controller, not measured by Toffee: no reference, so never restored.
            if (row.changes)
                recordings.append({ row.tool, *row.inController, TloSource::Pulled, std::nullopt,
                    std::nullopt, now, RecordingKind::Pulled });
        }
        // All of them or none: a table half taken from the controller is neither.
        if (auto recorded
            = m_document->recordAll(recordings, tr("Pull Offsets from %1").arg(controllerName(m_connection)));
            !recorded)
            return showError(tr("The offsets were not pulled"), recorded.error().message);
        statusBar()->showMessage(
            tr("Taken from the controller's table into the file: %1 TLOs.").arg(recordings.size()), 10000);
    });
}

} // namespace Toffee
