// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli probing: how a tool of a table is measured on the tool setter, shown or set.
#include <QJsonObject>

#include "app/cli/cli.h"
#include "model/formats/tablefile.h"
#include "model/limits.h"
#include "model/probing.h"
#include "model/textparsing.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

int probingSettings(Invocation &call)
{
    const QString usage = u"usage: toffee-cli probing N --table FILE [--set SETTINGS]"_s;
    const QString path = call.option(u"table"_s);
    if (call.arguments.size() != 1 || path.isEmpty())
        return fail(call, usage, BadInput);
    const auto number = parseInteger(call.arguments.front().toUtf8());
    if (!number || *number < Limits::kMinToolNumber || *number > Limits::kMaxToolNumber)
        return fail(call, u"probing: \"%1\" is not a tool number."_s.arg(call.arguments.front()), BadInput);
    const int tool = int(*number);
    const auto format = formatForPath(path);
    if (!format)
        return fail(call,
            u"%1: cannot tell the table's format from its name (.json, .tbl or .csv)."_s.arg(path), BadInput);
    auto table = loadTableFile(path, format);
    if (!table)
        return fail(call, table.error().text(), BadInput);
    const Tool *found = table.value().find(tool);
    if (!found)
        return fail(call, u"T%1 is not in %2: nothing was changed."_s.arg(tool).arg(path), BadInput);
    Tool changed = *found;
    const Units units = table.value().units();
    if (call.has(u"set"_s)) {
        // The file must be able to keep them, or nothing is written.
        if (*format == TableFormat::LinuxCnc)
            return fail(call,
                u"%1 is a LinuxCNC table, which has no place for how a tool is probed: keep the settings in "
                u"a "
                "Toffee table (.json or .csv). Nothing was changed."_s.arg(path),
                BadInput);
        const auto parsed = ProbeSettings::parse(call.option(u"set"_s), units);
        if (!parsed)
            return fail(call, u"probing: %1 Nothing was changed."_s.arg(parsed.error().message), BadInput);
        changed.probing = parsed.value().settings;
        changed.flutes = parsed.value().flutes;
        if (auto r = table.value().replace(tool, changed); !r)
            return fail(call, r.error().text(), BadInput);
        if (auto saved = saveTableFile(path, table.value(), *format); !saved)
            return fail(call, saved.error().text(), BadInput);
    }
    const ProbePlan plan = ProbePlan::of(changed.probing, changed.flutes, units);
    const QString text = ProbeSettings::text(changed.probing, changed.flutes, units);
    if (call.json) {
        printJson(call,
            QJsonObject { { u"tool"_s, tool }, { u"settings"_s, text }, { u"touches"_s, plan.touches },
                { u"offset_x_mm"_s, plan.offsetX }, { u"offset_y_mm"_s, plan.offsetY },
                { u"turn"_s, plan.turn },
                { u"latch_feed_mm"_s, plan.latchFeed ? QJsonValue(*plan.latchFeed) : QJsonValue() },
                { u"spread_limit_mm"_s, plan.spreadLimit ? QJsonValue(*plan.spreadLimit) : QJsonValue() } });
        return Success;
    }
    call.out << "T" << tool << ": "
             << (text.isEmpty() ? u"one touch at the setter's centre, at its own feed (the default)"_s : text)
             << Qt::endl;
    return Success;
}

} // namespace Toffee::Cli
