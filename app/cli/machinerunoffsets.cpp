// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli's machine commands: the table's TLOs into the controller (push), back (pull), and one restored.
#include <algorithm>
#include <cmath>
#include <numeric>

#include <QElapsedTimer>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonObject>
#include <QTimer>

#include "app/cli/cli.h"
#include "app/cli/interrupt.h"
#include "app/cli/machineoptions.h"
#include "app/cli/machinerun.h"
#include "app/cli/operatorpresence.h"
#include "model/clock.h"
#include "model/formats/tablefile.h"
#include "model/job/toolfacts.h"
#include "model/library/spool.h"
#include "model/library/weartrend.h"
#include "model/limits.h"
#include "model/numberformat.h"
#include "serial/machine/machinecontroller.h"
#include "serial/machine/machinelink.h"
#include "serial/machine/offsetsync.h"
#include "serial/machineconnection.h"
#include "serial/transport/streamtransport.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli::Machine {

bool MachineRun::pushOffsets()
{
    // What the controller held on connecting, to write only what differs and say what changed. A controller
    // whose table could not be read (LinuxCNC's file out of reach) says why.
    if (m_connection.firmware().hasToolTable() && !m_connection.connectResult().controllerTools) {
        m_connection.readToolTable([this](const SessionResult &r) { finishWith(r); });
        return true;
    }
    const PushPlan plan = planPush(*m_options.table,
        m_connection.connectResult().controllerTools.value_or(QList<ControllerTool> {}),
        m_connection.firmware().toolTableSize);
    if (plan.entries.isEmpty()) {
        finishWith(SessionResult::failed(SessionResult::Outcome::Refused,
            u"%1 holds no tool with a TLO: nothing to write."_s.arg(m_options.tablePath)));
        return true;
    }
    if (!plan.beyond().isEmpty()) {
        const int size = m_connection.firmware().toolTableSize;
        finishWith(SessionResult::failed(SessionResult::Outcome::Refused,
            (size > 0 ? u"%1 cannot go into the controller's table of %2 tools."_s
                            .arg(plan.beyond().join(u", "_s))
                            .arg(size)
                      : u"%1 are not in the controller's tool table, and G10 L1 cannot add a tool."_s.arg(
                          plan.beyond().join(u", "_s)))
                + u" Nothing was written: renumber them, or remove their TLOs, and push again."_s));
        return true;
    }
    const auto report = [this, plan] {
        QJsonArray written;
        for (const PushedEntry &e : plan.entries) {
            const bool changed = e.action == PushedEntry::Action::Write;
            written.append(QJsonObject { { u"tool"_s, e.tool }, { u"tlo"_s, e.inFile },
                { u"was"_s, e.inController ? QJsonValue(*e.inController) : QJsonValue() },
                { u"changed"_s, changed } });
            if (!m_call.json) {
                m_call.out << "T" << e.tool << ": " << mm(e.inFile) << " mm";
                if (e.inController && changed)
                    m_call.out << " (was " << mm(*e.inController) << ")";
                else if (!changed)
                    m_call.out << " (unchanged)";
                m_call.out << Qt::endl;
            }
        }
        if (m_call.json)
            printJson(m_call, QJsonObject { { u"written"_s, written }, { u"read_back"_s, u"agrees"_s } });
        else
            m_call.out << plan.writes().size() << " of " << plan.entries.size()
                       << " tools written into the controller's table and read back: all agree." << Qt::endl;
        finishWith(SessionResult {});
    };
    if (plan.writes().isEmpty()) {
        report(); // nothing differs: nothing is sent
        return true;
    }
    return m_connection.writeToolTable(plan.writes(), [this, report](const SessionResult &r) {
        if (!r.ok())
            return finishWith(r);
        report();
    });
}

// pull-offsets: each entry of the controller's table that holds a TLO goes into the file: a new tool added,
// a changed TLO taken as set on the controller (not measured by Toffee: TloSource::Pulled, with no
// reference), with a history event. An entry of 0.000 is an empty one, left alone.
void MachineRun::pulled(const SessionResult &r)
{
    if (!r.ok() || !r.controllerTools)
        return finishWith(r);
    QJsonArray changes;
    int unchanged = 0;
    int empty = 0;
    const QDateTime now = Clock::now();
    QList<Recording> recordings;
    const QList<PulledEntry> plan = planPull(*m_options.table, *r.controllerTools);
    for (const PulledEntry &entry : plan) {
        unchanged += entry.action == PulledEntry::Action::Unchanged ? 1 : 0;
        empty += entry.action == PulledEntry::Action::Empty ? 1 : 0;
        if (entry.changes())
            recordings.append({ entry.tool, entry.inController, TloSource::Pulled, std::nullopt, std::nullopt,
                now, RecordingKind::Pulled });
    }
    // All of them or none, in the file and in the history alike.
    if (!recordAll(recordings))
        return finishWith(SessionResult::failed(SessionResult::Outcome::MachineError, {}), true);
    for (const PulledEntry &entry : plan) {
        if (!entry.changes())
            continue;
        const bool isNew = entry.action == PulledEntry::Action::NewTool;
        changes.append(QJsonObject { { u"tool"_s, entry.tool }, { u"tlo"_s, entry.inController },
            { u"was"_s, entry.inFile ? QJsonValue(*entry.inFile) : QJsonValue() },
            { u"new_tool"_s, isNew } });
        if (!m_call.json) {
            m_call.out << "T" << entry.tool << ": " << mm(entry.inController) << " mm"
                       << (isNew ? " (new tool)" : "");
            if (const auto was = entry.inFile)
                m_call.out << " (was " << mm(*was) << ")";
            m_call.out << " read from the controller" << Qt::endl;
        }
    }
    if (m_call.json)
        printJson(m_call,
            QJsonObject { { u"changed"_s, changes }, { u"unchanged"_s, unchanged }, { u"empty"_s, empty } });
    else
        m_call.out << changes.size() << " changed, " << unchanged << " unchanged, " << empty
                   << " empty entries left alone." << Qt::endl;
    finishWith(SessionResult {});
}

// The table's TLO for the tool in the spindle, which a break test compares with (none without --table).
std::optional<double> MachineRun::storedTloInSpindle() const
{
    const auto tool = m_connection.activeTool();
    const auto stored = m_options.table && tool ? m_options.table->storedTlo(*tool) : std::nullopt;
    return stored ? std::optional(stored->tlo) : std::nullopt; // millimetres, whatever the table's units
}

// The stored TLO of the tool in the spindle when it failed its break test: unlock sets it back, since the
// failed test left the machine with the length it measured in force. The table's (--table) when it marks the
// tool broken, else the history's (the test's own record), as the window does.
std::optional<double> MachineRun::brokenToolTloInSpindle() const
{
    const auto tool = m_connection.activeTool();
    if (!tool)
        return std::nullopt;
    if (const auto stored = m_options.table ? m_options.table->storedTlo(*tool) : std::nullopt)
        return stored->breakTestFailed ? std::optional(stored->tlo) : std::nullopt;
    if (!m_options.library)
        return std::nullopt;
    const auto tested = tloBeforeFailedBreakTest(*m_options.library, m_options.machine, *tool);
    return tested ? tested.value() : std::nullopt;
}

bool MachineRun::restore()
{
    // In millimetres, as the machine has it, whatever the table's units (machineoptions checked it is there).
    const auto tool = m_options.table->storedTlo(m_options.tool);
    // The offsets read on connecting: the reference the machine has now.
    const auto &offsets = m_connection.connectResult().tlo;
    const double machineReference = offsets && offsets->referenceMz ? *offsets->referenceMz : 0.0;
    QString refusal;
    if (machineReference == 0.0)
        refusal = u"the machine reports no reference tool MCS Z, and a stored TLO is only right against the "
                  u"reference "
                  "it was measured with: probe T%1 instead."_s.arg(m_options.tool);
    else if (!tool->referenceMz)
        refusal
            = u"T%1's TLO in the table does not say which reference it was measured against, so it cannot be "
              "checked against the machine's: probe T%1 instead."_s.arg(m_options.tool);
    else if (std::fabs(*tool->referenceMz - machineReference) > tool->sameWithin)
        refusal = u"T%1's TLO %2 mm was measured against reference MCS Z %3, but the machine's reference is "
                  u"%4 now "
                  "(%5 mm apart): probe T%1 instead."_s.arg(m_options.tool)
                      .arg(mm(tool->tlo), mm(*tool->referenceMz), mm(machineReference),
                          mm(std::fabs(*tool->referenceMz - machineReference)));
    if (!refusal.isEmpty()) {
        SessionResult refused;
        refused.outcome = SessionResult::Outcome::Refused;
        refused.message = refusal;
        finishWith(refused);
        return true;
    }
    return m_connection.restoreTlo(m_options.tool, tool->tlo, recorded());
}

} // namespace Toffee::Cli::Machine
