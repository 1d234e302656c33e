// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli show and convert: tool tables, no machine.
#include <QJsonArray>
#include <QJsonObject>

#include "app/cli/cli.h"
#include "app/cli/machineoptions.h"
#include "model/formats/tablefile.h"
#include "model/library/historyevent.h"
#include "model/library/library.h"
#include "model/library/spool.h"
#include "model/limits.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/toollife.h"
#include "model/toolvalidation.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

std::optional<Units> tblUnits(Invocation &call)
{
    if (!call.has(u"units"_s))
        return Units::Millimetre;
    return unitsFromSymbol(call.option(u"units"_s));
}

QJsonValue jsonNumber(double v)
{
    return QJsonValue(v);
}

QJsonObject toolJson(const Tool &tool)
{
    QJsonObject o {
        { u"number"_s, tool.number },
        { u"pocket"_s, tool.pocket },
        { u"description"_s, tool.description },
        { u"length_geometry"_s, jsonNumber(tool.lengthGeometry) },
        { u"length_wear"_s, jsonNumber(tool.lengthWear) },
        { u"total_length"_s, jsonNumber(tool.totalLength()) },
        { u"radius_geometry"_s, jsonNumber(tool.radiusGeometry) },
        { u"radius_wear"_s, jsonNumber(tool.radiusWear) },
        { u"measured_tlo"_s, tool.measuredTlo ? QJsonValue(*tool.measuredTlo) : QJsonValue() },
        { u"measured_at"_s,
            tool.measuredAt.isValid() ? QJsonValue(tool.measuredAt.toUTC().toString(Qt::ISODateWithMs))
                                      : QJsonValue() },
        { u"tlo_source"_s,
            tool.measuredTlo ? QJsonValue(QString(tloSourceName(tool.tloSource))) : QJsonValue() },
        { u"break_test_failed"_s, tool.breakTestFailed },
        { u"reference_mz"_s, tool.referenceMz ? QJsonValue(*tool.referenceMz) : QJsonValue() },
        { u"notes"_s, tool.notes },
        { u"cutter_type"_s, tool.cutterType.isEmpty() ? QJsonValue() : QJsonValue(tool.cutterType) },
        { u"overall_length"_s, tool.overallLength ? QJsonValue(*tool.overallLength) : QJsonValue() },
        { u"life_limit_minutes"_s,
            tool.lifeLimitMinutes ? QJsonValue(*tool.lifeLimitMinutes) : QJsonValue() },
        { u"life_limit_uses"_s, tool.lifeLimitUses ? QJsonValue(*tool.lifeLimitUses) : QJsonValue() },
    };
    return o;
}

} // namespace

int showTable(Invocation &call)
{
    if (call.arguments.size() != 1)
        return fail(call, u"usage: toffee-cli show TABLE"_s, BadInput);
    const auto units = tblUnits(call);
    if (!units)
        return fail(call, u"--units must be mm or in."_s, BadInput);
    const QString path = call.arguments.front();
    auto table = loadTableFile(path, {}, *units);
    if (!table)
        return fail(call, table.error().text(), BadInput);

    const ToolTable &t = table.value();
    if (call.json) {
        QJsonArray tools;
        for (const Tool &tool : t.tools())
            tools.append(toolJson(tool));
        printJson(call,
            QJsonObject {
                { u"file"_s, path }, { u"units"_s, unitsSymbol(t.units()) }, { u"tools"_s, tools } });
        return Success;
    }
    auto n = [&t](double v) {
        return displayNumber(v, t.units());
    };
    call.out << path << ": " << t.size() << (t.size() == 1 ? " tool" : " tools") << ", "
             << unitsSymbol(t.units()) << "\n";
    call.out << u"%1 %2 %3 %4 %5 %6 %7 %8  %9\n"_s.arg(u"Tool"_s, 7)
                    .arg(u"Pocket"_s, 6)
                    .arg(u"Length"_s, 10)
                    .arg(u"Wear"_s, 9)
                    .arg(u"Total"_s, 10)
                    .arg(u"Radius"_s, 9)
                    .arg(u"R.wear"_s, 8)
                    .arg(u"TLO"_s, 10)
                    .arg(u"Description"_s);
    for (const Tool &tool : t.tools()) {
        call.out << u"%1 %2 %3 %4 %5 %6 %7 %8  %9\n"_s.arg(u"T"_s + QString::number(tool.number), 7)
                        .arg(tool.pocket, 6)
                        .arg(n(tool.lengthGeometry), 10)
                        .arg(n(tool.lengthWear), 9)
                        .arg(n(tool.totalLength()), 10)
                        .arg(n(tool.radiusGeometry), 9)
                        .arg(n(tool.radiusWear), 8)
                        .arg(tool.measuredTlo ? n(*tool.measuredTlo) : u"-"_s, 10)
                        .arg(tool.description);
        // What an operator must not miss comes after the description, where a long one cannot hide it.
        if (tool.measuredTlo && tool.tloSource == TloSource::Manual)
            call.out << "        TLO set by hand, not measured\n";
        if (tool.measuredTlo && tool.tloSource == TloSource::Pulled)
            call.out << "        TLO read from the controller's table, not measured\n";
        if (tool.breakTestFailed)
            call.out << "        FAILED ITS LAST BREAK TEST: check it, then probe it again\n";
        if (const QString life = ToolLife::limitText(tool); !life.isEmpty())
            call.out << "        life limit: " << life << '\n';
    }
    call.out.flush();
    return Success;
}

int convertTable(Invocation &call)
{
    if (call.arguments.size() != 2)
        return fail(call, u"usage: toffee-cli convert IN OUT [--to json|tbl|csv]"_s, BadInput);
    const auto units = tblUnits(call);
    if (!units)
        return fail(call, u"--units must be mm or in."_s, BadInput);
    const QString in = call.arguments.at(0);
    const QString out = call.arguments.at(1);
    const auto format = call.has(u"to"_s) ? formatFromName(call.option(u"to"_s)) : formatForPath(out);
    if (!format)
        return fail(call,
            call.has(u"to"_s)
                ? u"--to must be json, tbl or csv."_s
                : u"%1: cannot tell the format from the name; add --to json|tbl|csv."_s.arg(out),
            BadInput);
    auto table = loadTableFile(in, {}, *units);
    if (!table)
        return fail(call, table.error().text(), BadInput);
    const QStringList losses = formatLosses(table.value(), *format);
    if (auto r = saveTableFile(out, table.value(), *format); !r)
        return fail(call, r.error().text(), BadInput);
    for (const QString &loss : losses)
        call.err << "toffee-cli: warning: " << loss << Qt::endl;
    if (call.json) {
        printJson(call,
            QJsonObject { { u"input"_s, in }, { u"output"_s, out }, { u"format"_s, formatSuffix(*format) },
                { u"tools"_s, int(table.value().size()) },
                { u"warnings"_s, QJsonArray::fromStringList(losses) } });
    } else {
        call.out << "wrote " << table.value().size() << " tools to " << out << " (" << formatName(*format)
                 << ")" << Qt::endl;
    }
    return Success;
}

int newCutter(Invocation &call)
{
    const QString usage = u"usage: toffee-cli new-cutter N --table FILE [--machine NAME] [--no-history]"_s;
    const QString path = call.option(u"table"_s);
    if (call.arguments.size() != 1 || path.isEmpty())
        return fail(call, usage, BadInput);
    const auto number = parseInteger(call.arguments.front().toUtf8());
    if (!number || *number < Limits::kMinToolNumber || *number > Limits::kMaxToolNumber)
        return fail(
            call, u"new-cutter: \"%1\" is not a tool number."_s.arg(call.arguments.front()), BadInput);
    const int tool = int(*number);
    const auto units = tblUnits(call);
    if (!units)
        return fail(call, u"--units must be mm or in."_s, BadInput);
    const auto format = formatForPath(path);
    if (!format)
        return fail(call,
            u"%1: cannot tell the table's format from its name (.json, .tbl or .csv)."_s.arg(path), BadInput);
    auto table = loadTableFile(path, format, *units);
    if (!table)
        return fail(call, table.error().text(), BadInput);
    const Tool *before = table.value().find(tool);
    if (!before)
        return fail(call, u"T%1 is not in %2: nothing was changed."_s.arg(tool).arg(path), BadInput);
    const Tool old = *before;
    const Recording ended = table.value().newCutterRecording(tool); // before the cutter ends
    // The library first: a history that cannot be opened is said before the file changes.
    auto library = openLibraryOption(call);
    if (!library)
        return fail(call, library.error().message, BadInput);
    if (auto changed = table.value().newCutter(tool); !changed)
        return fail(call, changed.error().text(), BadInput);
    if (auto saved = saveTableFile(path, table.value(), *format); !saved)
        return fail(call, saved.error().text(), BadInput);
    // A LinuxCNC table holds no TLO or mark, and its wear is in the length: only a length could end.
    if (*table.value().find(tool) == old)
        call.err << "toffee-cli: note: " << path << " holds nothing of T" << tool
                 << "'s old cutter to end (no measured TLO, length, wear or break mark); only the history "
                    "records the "
                    "new cutter."
                 << Qt::endl;
    QString history = u"not_recorded"_s;
    if (library.value()) {
        const QString machine
            = call.has(u"machine"_s) ? call.option(u"machine"_s).trimmed() : kDefaultMachineName;
        const HistoryEvent event = historyEvent(ended, machine);
        const auto kept = Spool().keep(library.value()->location(), { event });
        if (auto written = library.value()->append({ event }); written) {
            history = u"recorded"_s;
            if (kept)
                (void)Spool().remove(kept.value());
        } else {
            history = kept ? u"kept"_s : u"not_recorded"_s;
            call.err << "toffee-cli: " << written.error().message << Qt::endl;
            if (kept)
                call.err << "toffee-cli: the new cutter is kept on this computer (" << kept.value()
                         << ") and goes into the history the next time it opens." << Qt::endl;
        }
    }
    const auto n = [&table](double v) {
        return displayNumber(v, table.value().units());
    };
    if (call.json) {
        printJson(call,
            QJsonObject { { u"tool"_s, tool }, { u"table"_s, path },
                { u"machine"_s,
                    call.has(u"machine"_s) ? call.option(u"machine"_s).trimmed() : kDefaultMachineName },
                { u"old_tlo"_s, old.measuredTlo ? QJsonValue(*old.measuredTlo) : QJsonValue() },
                { u"old_length_geometry"_s, old.lengthGeometry }, { u"old_length_wear"_s, old.lengthWear },
                { u"old_radius_wear"_s, old.radiusWear }, { u"old_break_test_failed"_s, old.breakTestFailed },
                { u"history"_s, history } });
        return Success;
    }
    call.out << "T" << tool << " has a new cutter in " << path << ".\n";
    if (old.measuredTlo)
        call.out << "  the old cutter's TLO " << n(*old.measuredTlo) << " "
                 << unitsSymbol(table.value().units())
                 << " is no longer stored (kept in the history as the old cutter's)\n";
    if (old.lengthGeometry != 0.0)
        call.out << "  its length " << n(old.lengthGeometry) << " " << unitsSymbol(table.value().units())
                 << " (the old cutter's, which G43 would apply to the new one) is reset to 0\n";
    if (old.lengthWear != 0.0 || old.radiusWear != 0.0)
        call.out << "  its wear (length " << n(old.lengthWear) << ", radius " << n(old.radiusWear)
                 << ") is reset to 0\n";
    if (old.breakTestFailed)
        call.out << "  its break-test mark is cleared\n";
    call.out << "  measure T" << tool << " on the tool setter before it cuts." << Qt::endl;
    return Success;
}

} // namespace Toffee::Cli
