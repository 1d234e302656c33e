// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli's machine commands: one connection, one operation, one result.
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
#include "app/cli/operatorpresence.h"
#include "model/clock.h"
#include "model/formats/tablefile.h"
#include "model/job/toolfacts.h"
#include "model/library/spool.h"
#include "model/library/weartrend.h"
#include "model/limits.h"
#include "model/numberformat.h"
#include "serial/carvera/carverareplies.h"
#include "serial/machine/machinecontroller.h"
#include "serial/machine/machinelink.h"
#include "serial/machineconnection.h"
#include "serial/offsetsync.h"
#include "serial/transport/streamtransport.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

const QStringList kMachineCommands = { u"status"_s, u"report"_s, u"probe"_s, u"break-test"_s, u"set-tlo"_s,
    u"select-tool"_s, u"change-tool"_s, u"restore"_s, u"unlock"_s, u"link-test"_s, u"rack"_s,
    u"measure-rack"_s, u"check-rack"_s, u"push-offsets"_s, u"pull-offsets"_s };

ExitCode exitCodeFor(SessionResult::Outcome outcome)
{
    switch (outcome) {
    case SessionResult::Outcome::Success:
        return Success;
    case SessionResult::Outcome::Refused:
        return BadInput;
    case SessionResult::Outcome::ToolBroken:
        return ToolBroken;
    case SessionResult::Outcome::MachineError:
        return MachineError;
    case SessionResult::Outcome::LinkFailure:
        return LinkFailure;
    }
    return MachineError;
}

QString mm(double v)
{
    return formatNumber(v, NumberFormat::fixed(3));
}

QJsonArray axes(const std::array<double, 3> &a)
{
    return { a[0], a[1], a[2] };
}

void printTlo(
    Invocation &call, const SessionResult &r, const QString &trendWarning = {}, const QString &history = {})
{
    const int tool = r.tool.value_or(-1);
    // The TLO in force is the machine's; the reference and the tool's MCS Z only where it reported them (the
    // stock firmware reports neither, and after a TLO set by hand there is no MCS Z of the tool).
    const auto json = [](std::optional<double> v) {
        return v ? QJsonValue(*v) : QJsonValue();
    };
    if (call.json) {
        QJsonObject o { { u"tool"_s, tool }, { u"reference_mz"_s, json(r.tlo->referenceMz) },
            { u"current_mz"_s, json(r.tlo->currentMz) }, { u"tlo"_s, r.tlo->tlo() } };
        if (!trendWarning.isEmpty())
            o.insert(u"trend_warning"_s, trendWarning);
        if (!history.isEmpty())
            o.insert(u"history"_s, history);
        printJson(call, o);
        return;
    }
    call.out << "T" << tool << ": TLO " << mm(r.tlo->tlo()) << " mm";
    if (r.tlo->currentMz && r.tlo->referenceMz)
        call.out << " (current tool MCS Z " << mm(*r.tlo->currentMz) << ", reference MCS Z "
                 << mm(*r.tlo->referenceMz) << ")";
    else if (r.tlo->referenceMz)
        call.out << " (reference MCS Z " << mm(*r.tlo->referenceMz) << ")";
    call.out << Qt::endl;
}

void printStatus(Invocation &call, const MachineStatus &s, const FirmwareInfo &firmware,
    const MachineIdentity &identity, const QString &machine)
{
    if (call.json) {
        printJson(call,
            QJsonObject { { u"controller"_s, controllerKindName(identity.controller) },
                { u"machine"_s, machine }, { u"identity"_s, identity.key() }, { u"state"_s, s.state },
                { u"tool"_s, s.tool ? QJsonValue(*s.tool) : QJsonValue() },
                { u"tlo"_s, s.tlo ? QJsonValue(*s.tlo) : QJsonValue() }, { u"mpos"_s, axes(s.mpos) },
                { u"wpos"_s, axes(s.wpos) },
                { u"halt_reason"_s, s.haltReason ? QJsonValue(*s.haltReason) : QJsonValue() },
                { u"firmware"_s, firmwareJson(firmware) } });
        return;
    }
    call.out << s.state;
    if (s.haltReason)
        call.out << " (halted: " << haltReasonName(*s.haltReason) << ". " << haltRecovery(*s.haltReason)
                 << ")";
    if (s.tool)
        call.out << "  T" << *s.tool << "  TLO " << mm(s.tlo.value_or(0));
    call.out << "  MPos " << mm(s.mpos[0]) << ' ' << mm(s.mpos[1]) << ' ' << mm(s.mpos[2]) << "  WPos "
             << mm(s.wpos[0]) << ' ' << mm(s.wpos[1]) << ' ' << mm(s.wpos[2]) << Qt::endl;
    call.out << machine << ": " << identity.title() << ", " << firmware.description();
    if (!firmware.hasBreakTest())
        call.out << ": no break test" << (firmware.hasManualOffset() ? "" : ", no manual offset");
    call.out << Qt::endl;
}

void printBreakTest(Invocation &call, const SessionResult &r)
{
    const double diff = std::fabs(r.breakTest->newTlo - r.breakTest->oldTlo);
    const bool broken = r.outcome == SessionResult::Outcome::ToolBroken;
    if (call.json) {
        printJson(call,
            QJsonObject { { u"old_tlo"_s, r.breakTest->oldTlo }, { u"new_tlo"_s, r.breakTest->newTlo },
                { u"difference"_s, diff }, { u"tolerance"_s, r.tolerance }, { u"broken"_s, broken } });
    } else {
        call.out << "T" << r.tool.value_or(-1) << ": old TLO " << mm(r.breakTest->oldTlo) << ", new "
                 << mm(r.breakTest->newTlo) << ", difference " << mm(diff) << " (tolerance "
                 << formatNumber(r.tolerance, NumberFormat::upTo(3)) << "): " << (broken ? "BROKEN" : "OK")
                 << Qt::endl;
    }
    if (broken)
        call.err << "toffee-cli: " << r.message << Qt::endl;
}

void printSelected(Invocation &call, const SessionResult &r)
{
    // M493.2 keeps the TLO of the tool measured before: say so, every time.
    const QString warning
        = u"T%1 is active but the machine keeps the TLO in force before (another tool's, or none): T%1's "
          "own is not set; probe T%1 (or set its TLO) before you cut."_s.arg(r.tool.value_or(-1));
    if (call.json)
        printJson(call, QJsonObject { { u"tool"_s, r.tool.value_or(-1) }, { u"warning"_s, warning } });
    else
        call.out << warning << Qt::endl;
}

void printLinkTimes(Invocation &call, QList<double> times, const QString &link)
{
    std::sort(times.begin(), times.end());
    const double median = times.at(times.size() / 2);
    const double p99 = times.at(std::min<qsizetype>(times.size() - 1, qsizetype(times.size() * 0.99)));
    const double mean = std::accumulate(times.cbegin(), times.cend(), 0.0) / double(times.size());
    if (call.json)
        printJson(call,
            QJsonObject { { u"count"_s, times.size() }, { u"median_ms"_s, median }, { u"p99_ms"_s, p99 },
                { u"max_ms"_s, times.last() }, { u"mean_ms"_s, mean }, { u"link"_s, link } });
    else
        call.out << times.size() << " round trips over " << link << ": median " << mm(median) << " ms, p99 "
                 << mm(p99) << " ms, max " << mm(times.last()) << " ms" << Qt::endl;
}

// One machine command: one connection, one named operation of it, one result and its exit code.
class MachineRun
{
public:
    MachineRun(Invocation &call, MachineOptions options)
        : m_call(call)
        , m_options(std::move(options))
    { }

    int exec()
    {
        QObject::connect(&m_connection, &MachineConnection::connectFailed, &m_loop,
            [this] { finishWith(m_connection.connectResult()); });
        m_connection.setPreparer([this](const MachineIdentity &identity, ConnectionTarget &target) {
            if (auto prepared = prepareForController(m_call, m_options, identity); !prepared)
                return prepared.error().message;
            target.setter = m_options.target.setter;
            target.reference = m_options.target.reference;
            return QString();
        });
        QObject::connect(
            &m_connection, &MachineConnection::stateChanged, &m_loop, [this](MachineConnection::State state) {
                if (state == MachineConnection::State::Connected && !std::exchange(m_started, true))
                    operate();
            });
        // Started from inside the loop, so that a failure reported at once still ends it.
        QTimer::singleShot(0, &m_loop, [this] { m_connection.connectTo(m_options.target); });
        m_loop.exec();
        closeQuietly();
        m_connection.disconnectFromMachine();
        return m_exitCode;
    }

private:
    using Done = MachineConnection::Done;

    // No more status queries, and the answer to one already sent is let in (at most 200 ms) before the link
    // closes: a controller that writes its report to a client already gone may take it badly (grblHAL's
    // simulator exits), and a closing socket with unread data resets the connection.
    void closeQuietly()
    {
        MachineLink *link = m_connection.link();
        if (!link || m_connection.state() != MachineConnection::State::Connected)
            return;
        link->setPollInterval(0);
        if (!link->isStatusRequested())
            return;
        QEventLoop quiet;
        QTimer::singleShot(200, &quiet, &QEventLoop::quit);
        QObject::connect(link, &MachineLink::statusChanged, &quiet, &QEventLoop::quit);
        quiet.exec();
    }

    void operate();
    // push-offsets: the table's TLOs into the controller's own table; pull-offsets: back into the file.
    bool pushOffsets();
    void pulled(const SessionResult &r);
    void linkTest();
    // Sets the table's TLO for the tool back on the machine, when it was measured against the machine's
    // reference.
    bool restore();
    [[nodiscard]] std::optional<double> storedTloInSpindle() const;
    [[nodiscard]] std::optional<double> brokenToolTloInSpindle() const;
    void roundTrip();
    // `reported`: the command printed the failure itself (a rack's summary holds it).
    void finishWith(const SessionResult &r, bool reported = false);
    [[nodiscard]] bool record(const SessionResult &r);
    [[nodiscard]] bool recordTable(const SessionResult &r);
    void recordHistory(const QList<HistoryEvent> &events, const Result<QString> &kept);
    // Several recordings at once (a pull): the table file and the history take all of them, or none.
    [[nodiscard]] bool recordAll(const QList<Recording> &recordings);
    // A result printed by `print` when the operation got that far (a broken tool's verdict included).
    [[nodiscard]] Done printed(std::function<void(const SessionResult &)> print);
    // A probe or a manual offset: recorded, then printed.
    [[nodiscard]] Done recorded();

    Invocation &m_call;
    MachineOptions m_options;
    MachineConnection m_connection;
    QEventLoop m_loop;
    int m_exitCode = Success;
    bool m_started = false;
    QString m_trendWarning; // a probe off its tool's wear trend
    QString m_history; // what became of the event: recorded, kept (on this computer), not_recorded
    QList<double> m_times; // link-test: each round trip's milliseconds
    QElapsedTimer m_clock;
    bool m_recordFailed = false; // then the exit code says so (unless the tool is broken, which says more)
};

void MachineRun::finishWith(const SessionResult &r, bool reported)
{
    if (!m_recordFailed || r.outcome == SessionResult::Outcome::ToolBroken)
        m_exitCode = exitCodeFor(r.outcome);
    if (!reported && !r.ok() && !(r.outcome == SessionResult::Outcome::ToolBroken && r.breakTest))
        fail(m_call, r.message, ExitCode(m_exitCode));
    m_loop.quit();
}

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
        finishWith(r);
    };
}

void MachineRun::operate()
{
    const QString &command = m_call.command;
    MachineConnection &c = m_connection;
    // A change that waits for a person (change-tool, a rack's drop of a tool changed by hand): refused
    // without a terminal, said with its limit on one.
    attendToolChanges(c.session(), m_call.err, &m_loop);
    const auto status = printed([this](const SessionResult &r) {
        printStatus(m_call, *r.status, m_connection.firmware(), m_connection.identity(), m_options.machine);
    });
    bool started = true;
    if (command == u"status")
        started = c.status(status);
    else if (command == u"report")
        started = c.report(printed([this](const SessionResult &r) { printTlo(m_call, r); }));
    else if (command == u"probe")
        started = c.probe(recorded());
    else if (command == u"change-tool")
        started = c.changeTool(m_options.tool, recorded(), storedTloForChange(m_call, m_options, c));
    else if (isRackCommand(command) && !c.firmware().hasRack())
        finishWith(SessionResult::failed(SessionResult::Outcome::Refused,
            u"%1 has no tool rack; %2 is for the Carvera's. Change tools with change-tool N."_s.arg(
                c.firmware().description(), command)));
    else if (isRackCommand(command))
        started = startRackCommand(
            m_call, m_options, c, [this](const SessionResult &r) { return record(r); },
            [this](const SessionResult &r, bool incomplete) {
                finishWith(r, true);
                if (incomplete)
                    m_exitCode = Incomplete;
            });
    else if (command == u"set-tlo")
        started = m_options.z ? c.setTlo(*m_options.z, recorded())
                              : c.setTloAboveZ0(*m_options.aboveZ0, recorded());
    else if (command == u"break-test")
        started = c.breakTest(m_options.tolerance, printed([this](const SessionResult &r) {
            printBreakTest(m_call, r);
            if (r.breakTest)
                (void)record(r);
            if (r.outcome == SessionResult::Outcome::ToolBroken && !m_options.table && !m_options.library)
                m_call.err << "toffee-cli: with neither --table nor the history, a later toffee-cli unlock "
                              "cannot know the stored TLO: after unlocking, set it back (set-tlo "
                           << mm(r.breakTest->oldTlo) << ") or probe the tool." << Qt::endl;
        }),
            storedTloInSpindle());
    else if (command == u"restore")
        started = restore();
    else if (command == u"select-tool")
        started = c.selectTool(
            m_options.tool, printed([this](const SessionResult &r) { printSelected(m_call, r); }));
    else if (command == u"unlock")
        started = c.unlock(printed([this](const SessionResult &r) {
            if (const auto now = r.status ? r.status : m_connection.link()->lastStatus())
                printStatus(
                    m_call, *now, m_connection.firmware(), m_connection.identity(), m_options.machine);
            if (!r.message.isEmpty()) // what is in force now, and why
                m_call.err << "toffee-cli: " << r.message << Qt::endl;
        }),
            brokenToolTloInSpindle());
    else if (command == u"link-test")
        linkTest();
    else if (command == u"push-offsets")
        started = pushOffsets();
    else if (command == u"pull-offsets")
        started = c.readToolTable([this](const SessionResult &r) { pulled(r); });
    if (!started) {
        SessionResult refused;
        refused.outcome = SessionResult::Outcome::MachineError;
        refused.message = c.haltedMessage();
        finishWith(refused);
    }
}

bool MachineRun::pushOffsets()
{
    // What the controller held on connecting, to write only what differs and say what changed.
    const PushPlan plan = planPush(*m_options.table,
        m_connection.connectResult().controllerTools.value_or(QList<ControllerTool> {}),
        m_connection.firmware().toolTableSize);
    if (plan.entries.isEmpty()) {
        finishWith(SessionResult::failed(SessionResult::Outcome::Refused,
            u"%1 holds no tool with a TLO: nothing to write."_s.arg(m_options.tablePath)));
        return true;
    }
    if (!plan.beyond().isEmpty()) {
        finishWith(SessionResult::failed(SessionResult::Outcome::Refused,
            u"%1 cannot go into the controller's table of %2 tools. Nothing was written: renumber them, or "
            "remove their TLOs, and push again."_s.arg(plan.beyond().join(u", "_s))
                .arg(m_connection.firmware().toolTableSize)));
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
                       << " tools written into the controller's table and read back ($#): all agree."
                       << Qt::endl;
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

// N round trips of "G90" on the link itself, polling off: the link's own latency, not an operation's.
void MachineRun::linkTest()
{
    m_connection.link()->setPollInterval(0);
    roundTrip();
}

void MachineRun::roundTrip()
{
    if (m_times.size() == m_options.count) {
        printLinkTimes(m_call, m_times, m_connection.description());
        return finishWith(SessionResult {});
    }
    m_clock.start();
    m_connection.link()->send("G90", MachineLink::kDefaultTimeoutMs, [this](const CommandReply &reply) {
        if (!reply.ok()) {
            SessionResult r;
            r.outcome = reply.status == CommandReply::Status::Refused ? SessionResult::Outcome::MachineError
                                                                      : SessionResult::Outcome::LinkFailure;
            r.message = reply.message;
            return finishWith(r);
        }
        m_times.append(double(m_clock.nsecsElapsed()) / 1e6);
        roundTrip();
    });
}

} // namespace

bool isMachineCommand(const QString &command)
{
    return kMachineCommands.contains(command);
}

int runMachineCommand(Invocation &call)
{
    auto options = readMachineOptions(call);
    if (!options)
        return fail(call, options.error().message, BadInput);
    return MachineRun(call, options.takeValue()).exec();
}

} // namespace Toffee::Cli
