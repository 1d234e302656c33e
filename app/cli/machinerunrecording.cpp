// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli's machine commands: what an operation measured, into the table file and the history.
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

// What a successful probe, a manual offset or a break test means for the table, saved at once, and for the
// history library, table or not. The event is kept on this computer before the library is asked: a library
// that is busy, locked, damaged or out of reach leaves it there, to be sent the next time the library opens.
// Ctrl-C or SIGTERM waits until the table is saved and the event kept, not for the library.
bool MachineRun::record(const SessionResult &r)
{
    std::optional<HistoryEvent> event;
    Result<QString> kept = QString();
    bool saved = false;
    {
        const CriticalSection critical;
        saved = recordTable(r);
        if (m_options.library && r.recording) {
            event = historyEvent(*r.recording, m_options.machine);
            kept = Spool().keep(m_options.library->location(), { *event });
        }
    }
    if (event)
        recordHistory({ *event }, kept);
    return saved;
}

bool MachineRun::recordAll(const QList<Recording> &recordings)
{
    if (recordings.isEmpty())
        return true;
    QList<HistoryEvent> events;
    Result<QString> kept = QString();
    {
        const CriticalSection critical;
        if (m_options.table) {
            ToolTable next = *m_options.table;
            Result<void> saved = next.recordAll(recordings);
            if (saved)
                saved = saveTableFile(m_options.tablePath, next,
                    formatForPath(m_options.tablePath).value_or(TableFormat::Json));
            if (!saved) {
                m_exitCode = BadInput;
                fail(m_call, u"nothing was recorded: %1"_s.arg(saved.error().text()), BadInput);
                m_recordFailed = true;
                return false;
            }
            *m_options.table = next;
        }
        if (m_options.library) {
            for (const Recording &r : recordings)
                events.append(historyEvent(r, m_options.machine));
            kept = Spool().keep(m_options.library->location(), events);
        }
    }
    if (!events.isEmpty())
        recordHistory(events, kept);
    return true;
}

void MachineRun::recordHistory(const QList<HistoryEvent> &events, const Result<QString> &kept)
{
    Library &library = *m_options.library;
    QStringList names;
    for (const HistoryEvent &event : events)
        names << u"T%1's %2"_s.arg(event.tool).arg(eventKindName(event.kind).replace(u'_', u' '));
    const QString what = names.join(u", "_s);
    if (auto written = library.append(events); !written) {
        m_call.err << "toffee-cli: " << written.error().message << Qt::endl;
        if (kept) {
            m_history = u"kept"_s;
            m_call.err << "toffee-cli: " << what << " is kept on this computer (" << kept.value()
                       << ") and will be sent the next time toffee-cli or the window opens the library."
                       << Qt::endl;
        } else {
            m_history = u"not_recorded"_s;
            m_call.err << "toffee-cli: " << what << " could not be kept on this computer either ("
                       << kept.error().message << "): it is not in the history." << Qt::endl;
        }
        return;
    }
    m_history = u"recorded"_s;
    if (kept) {
        if (auto removed = Spool().remove(kept.value()); !removed)
            m_call.err << "toffee-cli: " << removed.error().message << Qt::endl;
    }
    for (const HistoryEvent &event : events) {
        if (auto warning = checkProbeAgainstTrend(library, event, m_options.tolerance)) {
            m_trendWarning = *warning;
            m_call.err << "toffee-cli: warning: " << *warning << Qt::endl;
        }
    }
}

bool MachineRun::recordTable(const SessionResult &r)
{
    if (!m_options.table)
        return true;
    const int measured = r.tool.value_or(-1);
    QString problem;
    if (!r.recording) {
        problem = u"the machine reports no tool in the spindle; nothing was recorded."_s;
        m_exitCode = MachineError;
    } else {
        Result<void> saved = m_options.table->record(*r.recording); // as the window records it
        if (saved)
            saved = saveTableFile(m_options.tablePath, *m_options.table,
                formatForPath(m_options.tablePath).value_or(TableFormat::Json));
        if (saved)
            return true;
        const QString why = saved.error().text();
        problem = r.breakTest
            ? u"the break test ran on T%1 but could not be recorded: %2"_s.arg(measured).arg(why)
            : m_call.command == u"set-tlo"
            ? u"set T%1's TLO to %2 mm on the machine but could not record it: %3"_s.arg(measured).arg(
                mm(r.tlo->tlo()), why)
            : u"measured T%1 (TLO %2 mm) but could not record it: %3"_s.arg(measured).arg(
                mm(r.tlo->tlo()), why);
        m_exitCode = BadInput;
    }
    fail(m_call, problem, ExitCode(m_exitCode));
    m_recordFailed = true;
    return false;
}

MachineRun::Done MachineRun::printed(std::function<void(const SessionResult &)> print)
{
    return [this, print](const SessionResult &r) {
        if (r.ok() || (r.outcome == SessionResult::Outcome::ToolBroken && r.breakTest))
            print(r);
        finishWith(r);
    };
}

MachineRun::Done MachineRun::recorded()
{
    return [this](const SessionResult &r) {
        if (!r.ok())
            return finishWith(r);
        if (m_call.command == u"change-tool" && r.tool == Limits::kEmptySpindle) {
            // change-tool -1: the spindle was emptied, and there is nothing to measure or record.
            if (m_call.json)
                printJson(
                    m_call, QJsonObject { { u"tool"_s, Limits::kEmptySpindle }, { u"tlo"_s, QJsonValue() } });
            else
                m_call.out << "The spindle is empty." << Qt::endl;
            return finishWith(r);
        }
        if (record(r))
            printTlo(m_call, r, m_trendWarning, m_history);
        // What the operation found besides its numbers (the reference made, edges too far apart), on stderr.
        if (!r.message.isEmpty())
            m_call.err << "toffee-cli: note: " << r.message << Qt::endl;
        finishWith(r);
    };
}

namespace {

// Twice the setter's spread, and never below the firmware's smallest: the tolerance a break test can trust.
double trustedTolerance(double spread)
{
    return std::max(Limits::kMinBreakTolerance, std::ceil(2.0 * spread * 1000.0 - 1e-6) / 1000.0);
}

} // namespace

bool MachineRun::measureRepeatability()
{
    const int tool = m_options.tool;
    if (m_connection.activeTool() != tool) {
        finishWith(SessionResult::failed(SessionResult::Outcome::Refused,
            u"The machine says T%1 is in the spindle, not T%2: put T%2 in (select-tool %2) first. Nothing "
            u"was "
            "sent."_s.arg(m_connection.activeTool().value_or(Limits::kEmptySpindle))
                .arg(tool)));
        return true;
    }
    return m_connection.probe([this, tool](const SessionResult &r) {
        if (!r.ok() || !r.tlo)
            return finishWith(r);
        (void)record(r);
        SetterRepeatability measured { tool, r.recording ? r.recording->at : Clock::now(), r.tlo->touches };
        const double spread = measured.spread();
        const double trusted = trustedTolerance(spread);
        QString kept = u"not_recorded"_s;
        if (m_options.library) {
            auto saved = m_options.library->setRepeatability(m_options.machine, measured);
            kept = saved ? u"recorded"_s : u"not_recorded"_s;
            if (!saved)
                m_call.err << "toffee-cli: the setter's repeatability was not kept: " << saved.error().message
                           << Qt::endl;
        }
        if (m_call.json) {
            QJsonArray touches;
            for (double z : measured.touches)
                touches.append(z);
            printJson(m_call,
                QJsonObject { { u"tool"_s, tool }, { u"touches"_s, touches }, { u"spread"_s, spread },
                    { u"smallest_tolerance"_s, trusted }, { u"tlo"_s, r.tlo->tlo() },
                    { u"history"_s, kept } });
        } else {
            m_call.out << "T" << tool << " touched " << measured.touches.size()
                       << " times on the same edge: the setter "
                       << "repeats within " << mm(spread) << " mm; a break test can trust a tolerance of "
                       << mm(trusted) << " mm or more." << Qt::endl;
        }
        finishWith(r);
    });
}

void MachineRun::warnBelowRepeatability()
{
    if (!m_options.library)
        return;
    const auto kept = m_options.library->repeatability(m_options.machine);
    if (!kept || !kept.value())
        return;
    const double trusted = trustedTolerance(kept.value()->spread());
    if (m_options.tolerance + 1e-9 < trusted)
        m_call.err << "toffee-cli: note: " << m_options.machine << "'s tool setter repeats within "
                   << mm(kept.value()->spread()) << " mm (measure-repeatability): a tolerance of "
                   << mm(m_options.tolerance) << " mm may find an intact tool broken; " << mm(trusted)
                   << " mm or more is one it can trust." << Qt::endl;
}

} // namespace Toffee::Cli::Machine
