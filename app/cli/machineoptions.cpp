// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli's machine options: read and checked apart from running the commands.
#include "app/cli/machineoptions.h"

#include <climits>
#include <cmath>

#include <QFileInfo>
#include <QHostAddress>

#include "model/clock.h"
#include "model/formats/tablefile.h"
#include "model/job/jobchecker.h"
#include "model/textparsing.h"
#include "serial/machine/machinecontroller.h"
#include "serial/transport/serialporttransport.h"
#include "serial/transport/tcptransport.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

bool wantsTool(const Invocation &call)
{
    return call.command == u"select-tool" || call.command == u"change-tool" || call.command == u"restore"
        || call.command == u"measure-repeatability";
}

Result<void> countArguments(const Invocation &call, MachineOptions &)
{
    if (call.arguments.size() != (wantsTool(call) ? 1 : 0))
        return Error { wantsTool(call) ? u"usage: toffee-cli ... %1 N"_s.arg(call.command)
                                       : u"%1 takes no arguments."_s.arg(call.command) };
    return {};
}

Result<void> readTool(const Invocation &call, MachineOptions &o)
{
    if (!wantsTool(call))
        return {};
    const auto n = parseInteger(call.arguments.front().toUtf8());
    if (!n || *n < INT_MIN || *n > INT_MAX)
        return Error { u"\"%1\" is not a tool number."_s.arg(call.arguments.front()) };
    o.tool = int(*n);
    return MachineController::validateToolNumber(o.tool);
}

Result<void> readCommandOptions(const Invocation &call, MachineOptions &o)
{
    o.tolerance = MachineController::kDefaultTolerance;
    if ((call.command == u"break-test" || call.command == u"check-rack") && call.has(u"tolerance"_s)) {
        const auto t = decimalOption(call, u"tolerance"_s);
        if (!t)
            return Error { u"--tolerance must be a number of millimetres, such as 0.05."_s };
        o.tolerance = *t;
        if (auto r = MachineController::validateTolerance(o.tolerance); !r)
            return r;
    }
    if (call.command == u"set-tlo") {
        if (call.has(u"z"_s) == call.has(u"above-z0"_s))
            return Error { u"set-tlo needs one of --z V or --above-z0 H."_s };
        const QString name = call.has(u"z"_s) ? u"z"_s : u"above-z0"_s;
        const auto v = decimalOption(call, name);
        if (!v)
            return Error { u"--%1 must be a number of millimetres."_s.arg(name) };
        if (auto r = MachineController::validateOffset(u"--"_s + name, *v); !r)
            return r;
        (name == u"z" ? o.z : o.aboveZ0) = *v;
    }
    if (call.has(u"touches"_s)) {
        const auto n = parseInteger(call.option(u"touches"_s).toUtf8());
        if (!n || *n < 1 || *n > ProbeSettings::kMaxTouches)
            return Error { u"--touches must be a whole number from 1 to %1."_s.arg(
                ProbeSettings::kMaxTouches) };
        o.touches = int(*n);
    }
    if (call.has(u"offset"_s)) {
        const QStringList xy = call.option(u"offset"_s).split(u',');
        const auto x = parseDecimal(xy.value(0).trimmed().toUtf8());
        const auto y = parseDecimal(xy.value(1).trimmed().toUtf8());
        if (xy.size() != 2 || !x || !y)
            return Error { u"--offset must be X,Y in millimetres from the setter's centre, such as 20,0."_s };
        o.offset = std::pair(*x, *y);
    }
    if (call.command == u"measure-repeatability") {
        if (!o.touches || *o.touches < 2)
            return Error {
                u"measure-repeatability needs --touches K, 2 to %1: the touches the setter's spread is "
                "measured over."_s.arg(ProbeSettings::kMaxTouches)
            };
        o.sameEdge = true;
    }
    if (auto valid = o.probePlan(0).validate(); !valid)
        return Error { valid.error().message };
    if (call.command == u"link-test" && call.has(u"count"_s)) {
        const auto c = parseInteger(call.option(u"count"_s).toUtf8());
        if (!c || *c < 1 || *c > 10000000)
            return Error { u"--count must be a whole number from 1 up."_s };
        o.count = int(*c);
    }
    return {};
}

// Found out before the machine moves, not after: a measurement that cannot be saved is lost.
Result<void> openTable(const Invocation &call, MachineOptions &o)
{
    if (!call.has(u"table"_s))
        return {};
    o.tablePath = call.option(u"table"_s);
    auto loaded = loadTableFile(o.tablePath);
    if (!loaded)
        return Error { loaded.error().text() };
    o.table = loaded.takeValue();
    const QFileInfo info(o.tablePath);
    if (!info.isWritable() || !QFileInfo(info.absolutePath()).isWritable())
        return Error {
            u"%1 cannot be written (check its permissions and its folder's); nothing was sent to the "
            "machine."_s.arg(o.tablePath)
        };
    return {};
}

// The rack commands and a change that takes a stored TLO read the table; --rack says what the rack holds.
Result<void> readRack(const Invocation &call, MachineOptions &o)
{
    o.rack = carveraRack();
    if (call.has(u"rack"_s)) {
        auto rack = parseRack(call.option(u"rack"_s));
        if (!rack)
            return rack.error();
        o.rack = rack.value();
    }
    o.useStoredTlo = call.has(u"use-stored-tlo"_s);
    if (call.has(u"stale-days"_s)) {
        const auto days = parseInteger(call.option(u"stale-days"_s).toUtf8());
        if (!days || *days < 0 || *days > 3650)
            return Error { u"--stale-days must be a whole number of days from 0 to 3650."_s };
        o.staleDays = int(*days);
    }
    const bool offsets = call.command == u"push-offsets" || call.command == u"pull-offsets";
    const bool needsTable
        = isRackCommand(call.command) || offsets || (call.command == u"change-tool" && o.useStoredTlo);
    if (needsTable && !o.table)
        return Error { u"%1 reads the stored TLOs from the table: name it with --table FILE."_s.arg(
            call.command == u"change-tool" ? u"change-tool --use-stored-tlo"_s : call.command) };
    return {};
}

// restore N sets the TLO the table holds for N: the table must have one.
Result<void> checkRestore(const Invocation &call, MachineOptions &o)
{
    if (call.command != u"restore")
        return {};
    if (!o.table)
        return Error { u"restore sets the TLO the table holds: name the table with --table FILE."_s };
    const Tool *tool = o.table->find(o.tool);
    if (!tool || !tool->measuredTlo)
        return Error { u"T%1 has no measured TLO in %2: probe it instead."_s.arg(o.tool).arg(o.tablePath) };
    // What makes a stored TLO doubtful, as the job preparation refuses it: said by name, before anything is
    // sent; --anyway takes it all the same (the reference is checked on the machine whatever is said).
    QStringList doubts;
    if (tool->tloSource == TloSource::Manual)
        doubts << u"it was set by hand, not measured"_s;
    if (tool->tloSource == TloSource::Pulled)
        doubts << u"it was read from the controller's table, not measured"_s;
    if (tool->breakTestFailed)
        doubts << u"it failed its last break test"_s;
    const QDateTime now = Clock::now();
    if (Clock::isInFuture(tool->measuredAt, now))
        doubts << u"it is dated %1, in the future (a clock was wrong)"_s.arg(
            tool->measuredAt.toUTC().toString(Qt::ISODate));
    else if (tool->measuredAt.isValid() && tool->measuredAt.secsTo(now) > qint64(o.staleDays) * 24 * 3600)
        doubts << u"it is %1 days old, older than the stale limit (%2 d, --stale-days)"_s
                      .arg(tool->measuredAt.secsTo(now) / (24 * 3600))
                      .arg(o.staleDays);
    if (!doubts.isEmpty() && !call.has(u"anyway"_s))
        return Error { u"T%1's stored TLO may not be its length now: %2. Probe T%1 instead, or restore it "
                       "anyway (--anyway) if you know it holds. Nothing was sent."_s.arg(o.tool)
                           .arg(doubts.join(u"; "_s)) };
    return {};
}

Result<void> openHistory(const Invocation &call, MachineOptions &o)
{
    // Only what records needs the library: status, report, select-tool, unlock and link-test work without
    // one.
    static const QStringList kRecording = { u"probe"_s, u"break-test"_s, u"set-tlo"_s, u"change-tool"_s,
        u"restore"_s, u"measure-rack"_s, u"check-rack"_s, u"pull-offsets"_s, u"measure-repeatability"_s };
    const bool unlock = call.command == u"unlock"_s;
    if (!kRecording.contains(call.command) && !unlock)
        return {};
    // Without --machine, the name is the machine's kind's, once known (prepareForController).
    o.machine = call.has(u"machine"_s) ? call.option(u"machine"_s).trimmed() : kDefaultMachineName;
    if (o.machine.isEmpty())
        return Error { u"--machine needs a name."_s };
    if (unlock) {
        // Read only, when there is one: the stored TLO a failed break test left out of force (an unlock works
        // without it, and says what is in force).
        if (auto existing = openExistingLibrary(call); existing)
            o.library = existing.takeValue();
        return {};
    }
    auto library = openLibraryOption(call);
    if (!library)
        return Error { library.error().message
            + u" Nothing was sent to the machine; use --no-history to measure without "
              "recording the history."_s };
    o.library = library.takeValue();
    return {};
}

// A library busy with another program's write, or out of reach: what the command measures is kept on this
// computer and sent later, as any measurement the library cannot take now.
bool laterWill(const Library &library, const Error &error)
{
    return error.code == Library::kBusy || error.code == Library::kUnreachable || library.isConnectionLost();
}

// The machine as the library knows it: its controller's dialect, and how it was reached this time.
Result<void> registerMachine(const Invocation &call, MachineOptions &o, ControllerKind kind)
{
    if (!o.library)
        return {};
    const QString connection = o.target.emulator ? u"emulator"_s
        : o.target.isNetwork()                   ? o.target.name()
                                                 : o.target.port + u' ' + QString::number(o.target.baud);
    // The dialect its programs are checked in.
    const QString dialect = dialectKeyOf(kind);
    if (auto added = o.library->addMachine({ o.machine, dialect, connection }); !added) {
        // Another program holds the library for now: the machine may still measure, and what it measures
        // is kept on this computer and sent later, as any measurement the library cannot take now.
        if (!laterWill(*o.library, added.error()))
            return Error { added.error().message
                + u" Nothing was sent to the machine but the questions that tell its controller."_s };
        call.err << u"toffee-cli: warning: "_s << added.error().message
                 << u" What this command measures is kept on this computer and sent when the library is "
                    "free."_s
                 << Qt::endl;
    }
    return {};
}

// A controller that keeps no reference tool (grblHAL) is given the one Toffee kept for the machine: the
// newest probe's in the history, else the newest measured tool's in the table. Without either, the next probe
// makes its tool the reference. Its tool setter likewise: --setter, kept in the library, or the library's.
Result<void> readReference(const Invocation &call, MachineOptions &o, ControllerKind kind)
{
    if (keepsOwnReference(kind))
        return {};
    // The setter is the machine's: --setter is kept in the library for the next time, which it comes from
    // when not given.
    if (o.library && o.target.setter) {
        if (auto kept = o.library->setToolSetter(o.machine, *o.target.setter); !kept)
            call.err << u"toffee-cli: warning: "_s << kept.error().message << Qt::endl;
    } else if (o.library) {
        auto kept = o.library->toolSetter(o.machine);
        if (!kept)
            return Error { kept.error().message };
        o.target.setter = kept.value();
    }
    static const ToolTable kNoTable;
    o.target.reference = keptReferenceMz(o.library.get(), o.machine, o.table ? *o.table : kNoTable);
    return {};
}

// No wait on the library outlasts the command's own limit (--timeout; 5 s when it says none).
Library::Options libraryOptions(const Invocation &call)
{
    Library::Options options;
    const auto seconds = decimalOption(call, u"timeout"_s);
    if (seconds && *seconds > 0 && *seconds <= 3600) {
        options.busyTimeoutMs = std::max(1, int(*seconds * 1000));
        options.connectTimeoutS = std::max(1, int(std::ceil(*seconds)));
    }
    return options;
}

} // namespace

Result<std::unique_ptr<Library>> openLibraryOption(const Invocation &call)
{
    if (call.has(u"no-history"_s))
        return std::unique_ptr<Library> {};
    auto location = call.has(u"library"_s) ? LibraryLocation::parse(call.option(u"library"_s))
                                           : Result<LibraryLocation>(LibraryLocation::standard());
    if (!location)
        return location.error();
    auto library = Library::open(location.value(), libraryOptions(call));
    if (library)
        sendWaiting(*library.value(), call.err);
    return library;
}

Result<std::unique_ptr<Library>> openExistingLibrary(const Invocation &call)
{
    if (call.has(u"no-history"_s))
        return std::unique_ptr<Library> {};
    if (call.has(u"library"_s))
        return openLibraryOption(call);
    const LibraryLocation standard = LibraryLocation::standard();
    if (!QFileInfo::exists(standard.path))
        return std::unique_ptr<Library> {};
    auto library = Library::open(standard, libraryOptions(call));
    if (library)
        sendWaiting(*library.value(), call.err);
    return library;
}

std::optional<Dialect> programDialect(const Invocation &call, const Library *library, const QString &machine)
{
    if (call.has(u"dialect"_s))
        return dialectFromKey(call.option(u"dialect"_s));
    if (const auto machines = library ? library->machines() : Result<QList<MachineRecord>>(Error {})) {
        for (const MachineRecord &m : machines.value()) {
            if (m.name == machine && !m.dialect.isEmpty())
                return dialectFromKey(m.dialect);
        }
    }
    return Dialect::Carvera;
}

// The name stands for this machine, or for none yet; another machine under it is refused.
Result<void> bindIdentity(const Invocation &call, MachineOptions &o)
{
    if (!o.library)
        return {};
    auto bound = o.library->bindMachine(o.machine, o.identity.key(), call.has(u"same-machine"_s));
    if (!bound) {
        if (!laterWill(*o.library, bound.error()))
            return Error { bound.error().message };
        // Not known now: nothing of the library's is adopted for it.
        o.newMachine = true;
        call.err << u"toffee-cli: warning: "_s << bound.error().message << Qt::endl;
        return {};
    }
    using Kind = Library::MachineBinding::Kind;
    if (bound.value().kind == Kind::Other) {
        const MachineIdentity before = MachineIdentity::fromKey(bound.value().boundTo);
        if (o.identity.followsFrom(before)) {
            if (auto moved = o.library->bindMachine(o.machine, o.identity.key(), true); !moved)
                return Error { moved.error().message };
            call.err << u"toffee-cli: \"%1\" was %2 before; now it is %3."_s.arg(
                o.machine, before.title(), o.identity.title())
                     << Qt::endl;
            return {};
        }
    }
    if (bound.value().kind == Kind::Other)
        return Error {
            u"The library's machine \"%1\" is %2; this is %3. A machine's reference, tool setter "
            "and history are its own: give this one a name of its own (--machine NAME), or, if it "
            "is the same machine reached another way, say so (--same-machine). Nothing was sent to "
            "the machine but the questions that tell its controller."_s.arg(
                o.machine, MachineIdentity::fromKey(bound.value().boundTo).title(), o.identity.title())
        };
    if (bound.value().kind == Kind::New) {
        o.newMachine = true;
        call.err << u"toffee-cli: \"%1\" is %2, new to the library"_s.arg(o.machine, o.identity.title())
                 << (!keepsOwnReference(o.identity.controller) && !o.identity.emulator
                            ? u": it keeps no reference of its own, so the first tool it measures becomes "
                              "its reference."_s
                            : u"."_s)
                 << Qt::endl;
    }
    return {};
}

Result<void> prepareForController(
    const Invocation &call, MachineOptions &options, const MachineIdentity &identity)
{
    const ControllerKind kind = identity.controller;
    options.identity = identity;
    if (!call.has(u"machine"_s))
        options.machine = options.identity.defaultName();
    if (auto bound = bindIdentity(call, options); !bound)
        return bound;
    if (auto registered = registerMachine(call, options, kind); !registered)
        return registered;
    if (auto read = readReference(call, options, kind); !read)
        return read;
    // A machine new to the library adopts no reference: not the history's of a name it takes over, nor a
    // table's, measured on who knows which machine.
    if (options.newMachine)
        options.target.reference.reset();
    return {};
}

Result<MachineOptions> readMachineOptions(const Invocation &call)
{
    MachineOptions o;
    for (auto read : { countArguments, choosePort, readTool, readTarget, readCommandOptions, openTable,
             readRack, checkRestore, openHistory }) {
        if (auto r = read(call, o); !r)
            return r.error();
    }
    return o;
}

ProbePlan MachineOptions::probePlan(int tool) const
{
    ProbePlan plan = table ? table->probePlan(tool) : ProbePlan {};
    if (touches)
        plan.touches = *touches;
    if (offset)
        std::tie(plan.offsetX, plan.offsetY) = *offset;
    if (sameEdge)
        plan.turn = false;
    return plan;
}

} // namespace Toffee::Cli
