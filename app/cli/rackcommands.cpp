// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli's rack commands: the rack with each tool's stored TLO, Measure Rack and Check Rack (a
// RackSequence, each tool printed as it settles), and the stored TLO a manual change may take.
#include <QJsonArray>
#include <QJsonObject>

#include "app/cli/machineoptions.h"
#include "model/clock.h"
#include "model/job/toolfacts.h"
#include "model/numberformat.h"
#include "model/timetext.h"
#include "serial/carvera/rack/racksequence.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

const QStringList kRackCommands = { u"rack"_s, u"measure-rack"_s, u"check-rack"_s };

QString mm(double v)
{
    return formatNumber(v, NumberFormat::fixed(3));
}

QJsonValue number(const std::optional<double> &v)
{
    return v ? QJsonValue(*v) : QJsonValue();
}

QString stateKey(RackStep::State state)
{
    switch (state) {
    case RackStep::State::Waiting:
        return u"waiting"_s;
    case RackStep::State::Running:
        return u"running"_s;
    case RackStep::State::Measured:
        return u"measured"_s;
    case RackStep::State::Passed:
        return u"passed"_s;
    case RackStep::State::Broken:
        return u"broken"_s;
    case RackStep::State::Failed:
        return u"failed"_s;
    case RackStep::State::NotRun:
        return u"not_run"_s;
    case RackStep::State::Skipped:
        return u"skipped"_s;
    }
    return {};
}

void showRack(Invocation &call, const MachineOptions &o, const MachineConnection &connection)
{
    const FirmwareInfo firmware = connection.firmware();
    const auto spindle = connection.activeTool();
    const QDateTime now = Clock::now();
    QJsonArray rackSlots;
    if (!call.json) {
        call.out << "Firmware: " << firmware.description()
                 << (firmware.hasBreakTest() ? "" : " (no break test)") << Qt::endl;
        call.out << "Spindle: "
                 << (!spindle              ? u"unknown"_s
                            : *spindle < 0 ? u"empty"_s
                                           : u"T"_s + QString::number(*spindle))
                 << Qt::endl;
    }
    for (int tool : o.rack) {
        const Tool *t = o.table->find(tool);
        const auto stored = o.table->storedTlo(tool); // in millimetres, as the machine's
        const bool byHand = stored && stored->source == TloSource::Manual;
        const bool pulled = stored && stored->source == TloSource::Pulled;
        const bool broken = t && t->breakTestFailed;
        const QDateTime at = stored ? stored->measuredAt : QDateTime();
        if (call.json) {
            rackSlots.append(QJsonObject { { u"slot"_s, tool }, { u"tool"_s, tool },
                { u"tlo"_s, stored ? QJsonValue(stored->tlo) : QJsonValue() },
                { u"measured_at"_s, at.isValid() ? QJsonValue(at.toString(Qt::ISODate)) : QJsonValue() },
                { u"reference_mz"_s, number(stored ? stored->referenceMz : std::nullopt) },
                { u"set_by_hand"_s, byHand },
                { u"tlo_source"_s,
                    stored ? QJsonValue(QString(tloSourceName(stored->source))) : QJsonValue() },
                { u"broken"_s, broken }, { u"in_spindle"_s, spindle == tool } });
            continue;
        }
        call.out << "  slot " << tool << "  T" << tool << "  "
                 << (stored ? u"TLO "_s + mm(stored->tlo) + u" mm, "_s
                                + (at.isValid() ? ageText(at, now) : u"undated"_s)
                            : u"no stored TLO"_s)
                 << (byHand ? " (set by hand)" : "") << (pulled ? " (read from the controller)" : "")
                 << (broken ? "  BROKEN" : "") << (spindle == tool ? "  (in the spindle)" : "") << Qt::endl;
    }
    if (call.json)
        printJson(call,
            QJsonObject { { u"firmware"_s, firmwareJson(firmware) },
                { u"spindle"_s, spindle ? QJsonValue(*spindle) : QJsonValue() }, { u"slots"_s, rackSlots } });
}

void printStep(Invocation &call, const RackStep &step, RackSequence::Mode mode)
{
    if (call.json || step.state == RackStep::State::Running || step.state == RackStep::State::Waiting)
        return;
    call.out << "T" << step.tool << ": " << stateKey(step.state).replace(u'_', u' ');
    if (step.measuredTlo)
        call.out << ", TLO " << mm(*step.measuredTlo);
    if (step.storedTlo && step.state != RackStep::State::NotRun)
        call.out << (mode == RackSequence::Mode::Check ? " (stored " : " (was ") << mm(*step.storedTlo)
                 << ")";
    if (step.state == RackStep::State::Skipped)
        call.out << ": " << step.message;
    call.out << Qt::endl;
}

void printSummary(Invocation &call, const RackSequence &sequence, const SessionResult &outcome)
{
    QJsonArray tools;
    QJsonArray broken;
    for (const RackStep &step : sequence.steps()) {
        tools.append(QJsonObject { { u"tool"_s, step.tool }, { u"state"_s, stateKey(step.state) },
            { u"stored_tlo"_s, number(step.storedTlo) }, { u"measured_tlo"_s, number(step.measuredTlo) },
            { u"message"_s, step.message } });
        if (step.state == RackStep::State::Broken)
            broken.append(step.tool);
    }
    if (call.json) {
        QJsonObject o { { u"command"_s, call.command }, { u"tools"_s, tools }, { u"broken"_s, broken },
            { u"cancelled"_s, sequence.isCancelled() } };
        if (!outcome.ok())
            o.insert(u"error"_s, outcome.message);
        printJson(call, o);
    } else if (!outcome.ok() || !outcome.message.isEmpty()) {
        call.err << "toffee-cli: " << outcome.message << Qt::endl;
    }
}

} // namespace

QJsonObject firmwareJson(const FirmwareInfo &f)
{
    static const char *const kKinds[] = { "unknown", "community", "stock", "grblhal", "linuxcnc" };
    static_assert(std::size(kKinds) == size_t(FirmwareInfo::Kind::LinuxCnc) + 1);
    return { { u"kind"_s, QString::fromLatin1(kKinds[int(f.kind)]) },
        { u"controller"_s,
            f.isGrblHal()        ? u"grblhal"_s
                : f.isLinuxCnc() ? u"linuxcnc"_s
                : f.isCarvera()  ? u"carvera"_s
                                 : u"unknown"_s },
        { u"version"_s, f.version }, { u"break_test"_s, f.hasBreakTest() },
        { u"manual_offset"_s, f.hasManualOffset() }, { u"tool_table_size"_s, f.toolTableSize } };
}

bool isRackCommand(const QString &command)
{
    return kRackCommands.contains(command);
}

bool startRackCommand(Invocation &call, MachineOptions &options, MachineConnection &connection,
    std::function<bool(const SessionResult &)> record,
    std::function<void(const SessionResult &, bool incomplete)> finish)
{
    if (call.command == u"rack") {
        showRack(call, options, connection);
        finish(SessionResult {}, false);
        return true;
    }
    const auto mode = call.command == u"check-rack" ? RackSequence::Mode::Check : RackSequence::Mode::Measure;
    auto *sequence = new RackSequence(
        &connection, RackSequence::plan(mode, options.rack, *options.table, options.tolerance), &connection);
    QObject::connect(sequence, &RackSequence::recorded, sequence, [sequence, record](const SessionResult &r) {
        if (!record(r))
            sequence->cancel(); // a measurement that cannot be kept: no more are taken
    });
    QObject::connect(sequence, &RackSequence::stepChanged, sequence,
        [&call, sequence](int index) { printStep(call, sequence->steps().at(index), sequence->mode()); });
    QObject::connect(
        sequence, &RackSequence::finished, sequence, [&call, sequence, finish](const SessionResult &r) {
            printSummary(call, *sequence, r);
            // A check that passed every tool it could test, but could not test them all, is no pass.
            QStringList unchecked;
            for (const RackStep &step : sequence->steps()) {
                if (sequence->mode() == RackSequence::Mode::Check && step.state == RackStep::State::Skipped)
                    unchecked << u"T%1"_s.arg(step.tool);
            }
            if (r.ok() && !unchecked.isEmpty())
                call.err << "toffee-cli: not every rack tool was checked: " << unchecked.join(u", "_s)
                         << " (each says why above)." << Qt::endl;
            finish(r, r.ok() && !unchecked.isEmpty());
        });
    if (!sequence->start()) {
        printSummary(call, *sequence, sequence->outcome());
        finish(sequence->outcome(), false);
    }
    return true;
}

std::optional<double> storedTloForChange(
    Invocation &call, const MachineOptions &o, const MachineConnection &connection)
{
    if (!o.useStoredTlo)
        return std::nullopt;
    auto note = [&call](const QString &why) {
        call.err << "toffee-cli: " << why << Qt::endl;
        return std::nullopt;
    };
    if (o.rack.contains(o.tool))
        return note(u"T%1 is in the rack: the Carvera measures a rack tool at every change."_s.arg(o.tool));
    QHash<int, ToolFacts> facts = factsFromTable(*o.table);
    if (o.library) {
        if (auto added = addLibraryFacts(facts, *o.library, o.machine, { o.tool }); !added)
            return note(added.error().message);
    }
    // The stock firmware reports no reference.
    const auto &offsets = connection.lastOffsets();
    const std::optional<double> reference = offsets && offsets->referenceMz && *offsets->referenceMz != 0.0
        ? offsets->referenceMz
        : std::nullopt;
    auto tlo = restorableTlo(
        o.tool, facts.value(o.tool), Clock::now(), o.staleDays, reference, ReferenceCheck::Required);
    if (!tlo)
        return note(tlo.error().message);
    return tlo.value();
}

} // namespace Toffee::Cli
