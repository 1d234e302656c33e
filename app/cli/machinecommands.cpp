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

namespace Toffee::Cli {

namespace {

const QStringList kMachineCommands = { u"status"_s, u"report"_s, u"probe"_s, u"break-test"_s, u"set-tlo"_s,
    u"select-tool"_s, u"change-tool"_s, u"restore"_s, u"unlock"_s, u"stop"_s, u"link-test"_s, u"rack"_s,
    u"measure-rack"_s, u"check-rack"_s, u"push-offsets"_s, u"pull-offsets"_s, u"measure-repeatability"_s };

// After a stop, how long the machine is given to come to rest before its status is read.
constexpr int kStopSettleMs = 300;

} // namespace

namespace Machine {

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

namespace {

// Each touch's machine Z and their spread, in the JSON (an empty list and null for one touch) and after the
// line printed ("4 touches, spread 0.060 mm").
void addTouches(QJsonObject &o, const QList<double> &touches)
{
    QJsonArray list;
    for (double z : touches)
        list.append(z);
    o.insert(u"touches"_s, list);
    o.insert(u"spread"_s, touches.size() > 1 ? QJsonValue(spreadOf(touches)) : QJsonValue());
}

QString touchesLine(const QList<double> &touches)
{
    if (touches.size() < 2)
        return {};
    QStringList each;
    for (double z : touches)
        each << mm(z);
    return u"; %1 touches at machine Z %2, spread %3 mm"_s.arg(touches.size())
        .arg(each.join(u", "_s), mm(spreadOf(touches)));
}

} // namespace

void printTlo(Invocation &call, const SessionResult &r, const QString &trendWarning, const QString &history)
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
        addTouches(o, r.tlo->touches);
        if (!r.message.isEmpty())
            o.insert(u"note"_s, r.message);
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
    call.out << touchesLine(r.tlo->touches) << Qt::endl;
}

void printStatus(
    Invocation &call, const MachineStatus &s, const MachineConnection &connection, const QString &machine)
{
    const FirmwareInfo firmware = connection.firmware();
    const MachineIdentity identity = connection.identity();
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
    if (s.haltReason) {
        const HaltWords words = connection.haltWords(*s.haltReason);
        call.out << " (halted: " << words.name << ". " << words.recovery << ")";
    }
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
        QJsonObject o { { u"old_tlo"_s, r.breakTest->oldTlo }, { u"new_tlo"_s, r.breakTest->newTlo },
            { u"difference"_s, diff }, { u"tolerance"_s, r.tolerance }, { u"broken"_s, broken } };
        addTouches(o, r.breakTest->touches);
        printJson(call, o);
    } else {
        call.out << "T" << r.tool.value_or(-1) << ": old TLO " << mm(r.breakTest->oldTlo) << ", new "
                 << mm(r.breakTest->newTlo) << ", difference " << mm(diff) << " (tolerance "
                 << formatNumber(r.tolerance, NumberFormat::upTo(3)) << "): " << (broken ? "BROKEN" : "OK")
                 << touchesLine(r.breakTest->touches) << Qt::endl;
    }
    if (broken)
        call.err << "toffee-cli: " << r.message << Qt::endl;
    else if (!r.message.isEmpty())
        call.err << "toffee-cli: note: " << r.message << Qt::endl;
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

void MachineRun::finishWith(const SessionResult &r, bool reported)
{
    if (!m_recordFailed || r.outcome == SessionResult::Outcome::ToolBroken)
        m_exitCode = exitCodeFor(r.outcome);
    if (!reported && !r.ok() && !(r.outcome == SessionResult::Outcome::ToolBroken && r.breakTest))
        fail(m_call, r.message, ExitCode(m_exitCode));
    m_loop.quit();
}

void MachineRun::operate()
{
    const QString &command = m_call.command;
    MachineConnection &c = m_connection;
    // A change that waits for a person (change-tool, a rack's drop of a tool changed by hand): refused
    // without a terminal, said with its limit on one.
    attendToolChanges(c.session(), m_call.err, &m_loop);
    const auto status = printed(
        [this](const SessionResult &r) { printStatus(m_call, *r.status, m_connection, m_options.machine); });
    bool started = true;
    if (command == u"status")
        started = c.status(status);
    else if (command == u"report")
        started = c.report(printed([this](const SessionResult &r) { printTlo(m_call, r); }));
    else if (command == u"probe")
        started = c.probe(recorded());
    else if (command == u"measure-repeatability")
        started = measureRepeatability();
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
    else if (command == u"break-test") {
        warnBelowRepeatability();
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
    } else if (command == u"restore")
        started = restore();
    else if (command == u"select-tool")
        started = c.selectTool(
            m_options.tool, printed([this](const SessionResult &r) { printSelected(m_call, r); }));
    else if (command == u"unlock")
        started = c.unlock(printed([this](const SessionResult &r) {
            if (const auto now = r.status ? r.status : m_connection.link()->lastStatus())
                printStatus(m_call, *now, m_connection, m_options.machine);
            if (!r.message.isEmpty()) // what is in force now, and why
                m_call.err << "toffee-cli: " << r.message << Qt::endl;
        }),
            brokenToolTloInSpindle());
    else if (command == u"stop") {
        // At once, whatever runs (another program's line too); then what the machine says it is doing.
        c.stop();
        QTimer::singleShot(kStopSettleMs, &m_connection, [this, status] {
            if (!m_connection.status(status))
                finishWith(SessionResult::failed(
                    SessionResult::Outcome::MachineError, m_connection.haltedMessage()));
        });
    } else if (command == u"link-test")
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

} // namespace Machine

bool isMachineCommand(const QString &command)
{
    return kMachineCommands.contains(command);
}

int runMachineCommand(Invocation &call)
{
    auto options = readMachineOptions(call);
    if (!options)
        return fail(call, options.error().message, BadInput);
    return Machine::MachineRun(call, options.takeValue()).exec();
}

} // namespace Toffee::Cli
