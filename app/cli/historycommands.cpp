// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli history: the measurements the library keeps, for people, as JSON or as CSV.
#include <climits>

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include "app/cli/cli.h"
#include "app/cli/machineoptions.h"
#include "model/formats/fileio.h"
#include "model/gcode/dialect.h"
#include "model/gcode/gcodeinterpreter.h"
#include "model/library/library.h"
#include "model/library/programuse.h"
#include "model/numberformat.h"
#include "model/textparsing.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

QJsonValue jsonNumber(std::optional<double> v)
{
    return v ? QJsonValue(*v) : QJsonValue();
}

QJsonObject eventJson(const HistoryEvent &e)
{
    QJsonObject o { { u"id"_s, e.id }, { u"machine"_s, e.machine }, { u"tool"_s, e.tool },
        { u"at"_s, e.at.toString(Qt::ISODateWithMs) }, { u"kind"_s, eventKindName(e.kind) },
        { u"tlo"_s, jsonNumber(e.tlo) }, { u"reference_mz"_s, jsonNumber(e.referenceMz) },
        { u"current_mz"_s, jsonNumber(e.currentMz) } };
    if (e.kind == EventKind::NewCutter)
        o.insert(u"old_tlo"_s, jsonNumber(e.oldTlo)); // the ended cutter's TLO
    if (e.kind == EventKind::BreakTest) {
        o.insert(u"tolerance"_s, jsonNumber(e.tolerance));
        o.insert(u"old_tlo"_s, jsonNumber(e.oldTlo));
        o.insert(u"new_tlo"_s, jsonNumber(e.newTlo));
        o.insert(u"failed"_s, e.failed ? QJsonValue(*e.failed) : QJsonValue());
    }
    if (!e.touches.isEmpty()) {
        QJsonArray touches;
        for (double z : e.touches)
            touches.append(z);
        o.insert(u"touches"_s, touches);
        o.insert(u"spread"_s, jsonNumber(e.spread()));
    }
    return o;
}

void printText(Invocation &call, const QList<HistoryEvent> &events)
{
    for (const HistoryEvent &e : events) {
        call.out << e.at.toString(Qt::ISODate) << "  " << e.machine << "  T" << e.tool << "  "
                 << eventKindName(e.kind);
        if (e.tlo)
            call.out << "  TLO " << formatNumber(*e.tlo, NumberFormat::fixed(3));
        if (e.kind == EventKind::NewCutter && e.oldTlo)
            call.out << "  old cutter's TLO " << formatNumber(*e.oldTlo, NumberFormat::fixed(3)) << " ended";
        if (e.kind == EventKind::BreakTest && e.failed)
            call.out << (*e.failed ? "  FAILED" : "  passed");
        if (const auto spread = e.spread())
            call.out << "  " << e.touches.size() << " touches, spread "
                     << formatNumber(*spread, NumberFormat::fixed(3));
        call.out << '\n';
    }
    call.out << events.size() << (events.size() == 1 ? " event" : " events") << Qt::endl;
}

Result<HistoryQuery> readQuery(const Invocation &call)
{
    HistoryQuery q;
    q.machine = call.option(u"machine"_s).trimmed();
    if (call.has(u"tool"_s)) {
        const auto n = parseInteger(call.option(u"tool"_s).toUtf8());
        if (!n || *n < INT_MIN || *n > INT_MAX)
            return Error { u"--tool must be a tool number."_s };
        q.tool = int(*n);
    }
    if (call.has(u"since"_s)) {
        const QString since = call.option(u"since"_s);
        q.since = QDateTime::fromString(since, Qt::ISODateWithMs);
        if (!q.since.isValid())
            q.since = QDateTime(QDate::fromString(since, Qt::ISODate), QTime(0, 0));
        if (!q.since.isValid())
            return Error { u"--since must be a date (2026-11-23) or a time (2026-11-23T08:00:00Z)."_s };
        q.since = q.since.toUTC();
    }
    return q;
}

// toffee-cli history add-use --machine M --program FILE: the program ran; each tool's cutting time and feed
// path go into the library.
int addUse(Invocation &call)
{
    if (!call.has(u"program"_s))
        return fail(call, u"usage: toffee-cli history add-use --machine NAME --program FILE [--dialect D]"_s,
            BadInput);
    const QString machine
        = call.has(u"machine"_s) ? call.option(u"machine"_s).trimmed() : kDefaultMachineName;
    auto library = openLibraryOption(call);
    if (!library || !library.value())
        return fail(call,
            library ? u"history add-use records in the library: leave out --no-history."_s
                    : library.error().message,
            BadInput);
    const auto dialect = programDialect(call, library.value().get(), machine);
    if (!dialect)
        return fail(call, u"--dialect is not a dialect Toffee knows."_s, BadInput);
    const QString path = call.option(u"program"_s);
    const auto program = ProgramUse::read(path, *dialect, machine);
    if (!program)
        return fail(call, program.error().text(), program.error().line > 0 ? MachineError : BadInput);
    const QList<ToolUse> &uses = program.value().uses;
    if (auto written = library.value()->appendUse(uses); !written)
        return fail(call, written.error().message, MachineError);
    if (call.json) {
        QJsonArray list;
        for (const ToolUse &u : uses)
            list.append(QJsonObject { { u"tool"_s, u.tool }, { u"cutting_seconds"_s, u.cuttingSeconds },
                { u"feed_path_mm"_s, u.feedPathMm } });
        printJson(call,
            QJsonObject { { u"machine"_s, machine }, { u"program"_s, path }, { u"tools"_s, list },
                { u"rapid_mm"_s, program.value().rapidMm } });
        return Success;
    }
    for (const ToolUse &u : uses)
        call.out << "T" << u.tool << ": " << formatNumber(u.cuttingSeconds / 60.0, NumberFormat::fixed(1))
                 << " min cutting, " << formatNumber(u.feedPathMm / 1000.0, NumberFormat::fixed(2))
                 << " m of feed\n";
    call.out << "recorded for " << machine << " in " << library.value()->location().displayName() << Qt::endl;
    return Success;
}

} // namespace

int showHistory(Invocation &call)
{
    if (call.arguments == QStringList { u"add-use"_s })
        return addUse(call);
    if (!call.arguments.isEmpty())
        return fail(
            call, u"history takes no arguments but add-use; say --machine, --tool or --since."_s, BadInput);
    if (call.has(u"no-history"_s))
        return fail(call, u"history reads the library: leave out --no-history."_s, BadInput);
    const auto query = readQuery(call);
    if (!query)
        return fail(call, query.error().message, BadInput);
    auto library = openLibraryOption(call);
    if (!library)
        return fail(call, library.error().message, BadInput);
    QStringList unreadable;
    const auto events = library.value()->history(query.value(), &unreadable);
    if (!events)
        return fail(call, events.error().message, MachineError);
    // Rows another program or a hand wrote wrong are named, not printed as if they were measurements.
    for (const QString &row : std::as_const(unreadable))
        call.err << "toffee-cli: left out of the history, as it is not a measurement Toffee wrote: " << row
                 << Qt::endl;
    if (call.json) {
        QJsonArray list;
        for (const HistoryEvent &e : events.value())
            list.append(eventJson(e));
        printJson(call,
            QJsonObject { { u"library"_s, library.value()->location().displayName() }, { u"events"_s, list },
                { u"unreadable"_s, QJsonArray::fromStringList(unreadable) } });
    } else if (call.has(u"csv"_s)) {
        call.out << QString::fromUtf8(eventsAsCsv(events.value()));
        call.out.flush();
    } else {
        printText(call, events.value());
    }
    return Success;
}

} // namespace Toffee::Cli
