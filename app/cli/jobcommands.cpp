// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli job check and job prepare: a program against the tool table before it runs.
#include <cmath>

#include <QJsonArray>
#include <QJsonObject>

#include "app/cli/cli.h"
#include "app/cli/jobcommands.h"
#include "app/cli/machineoptions.h"
#include "model/formats/tablefile.h"
#include "model/job/jobcheck.h"
#include "model/limits.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/timetext.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

QJsonValue optionalNumber(std::optional<double> v)
{
    return v ? QJsonValue(*v) : QJsonValue();
}

QJsonArray numbers(const QList<int> &lines)
{
    QJsonArray out;
    for (int line : lines)
        out.append(line);
    return out;
}

QJsonObject reportJson(const JobReport &report)
{
    QJsonArray tools;
    for (const JobTool &t : report.tools)
        tools.append(QJsonObject { { u"number"_s, t.number }, { u"load_lines"_s, numbers(t.loadLines) },
            { u"loads"_s, t.loads }, { u"in_table"_s, t.inTable }, { u"tlo"_s, optionalNumber(t.tlo) },
            { u"measured_at"_s,
                t.measuredAt.isValid() ? QJsonValue(t.measuredAt.toString(Qt::ISODateWithMs))
                                       : QJsonValue() },
            { u"cutting_seconds"_s, t.cuttingSeconds }, { u"feed_path_mm"_s, t.feedPathMm },
            { u"lowest_z"_s, optionalNumber(t.lowestZ) }, { u"set_by_hand"_s, t.setByHand } });
    QJsonArray findings;
    for (const Finding &f : report.findings)
        findings.append(QJsonObject { { u"severity"_s, severityName(f.severity()) },
            { u"kind"_s, findingKey(f.kind) }, { u"line"_s, f.line },
            { u"tool"_s, f.tool >= 0 ? QJsonValue(f.tool) : QJsonValue() }, { u"message"_s, f.message },
            { u"lines"_s, numbers(f.lines) }, { u"count"_s, f.count }, { u"more_tools"_s, f.moreTools } });
    // The tools beyond the listed ones, counted: how many, how often loaded, from which line.
    return { { u"program"_s, report.program }, { u"dialect"_s, dialectInfo(report.dialect).key },
        { u"lines"_s, report.lines }, { u"cancelled"_s, report.cancelled }, { u"tools"_s, tools },
        { u"distinct_tools"_s, report.distinctTools() }, { u"more_tools"_s, report.moreTools },
        { u"more_tool_loads"_s, report.moreLoads },
        { u"more_tools_from_line"_s, report.moreTools > 0 ? QJsonValue(report.moreFromLine) : QJsonValue() },
        { u"findings"_s, findings }, { u"cutting_seconds"_s, report.cuttingSeconds },
        { u"rapid_mm"_s, report.rapidMm }, { u"errors"_s, report.errors() },
        { u"warnings"_s, report.warnings() } };
}

QString mm(double v)
{
    return formatNumber(v, NumberFormat::fixed(3));
}

QString lineList(const Finding &f)
{
    return f.count > f.lines.size() ? f.linesText() + u" ("_s + QString::number(f.count) + u" in all)"_s
                                    : f.linesText();
}

void printTool(Invocation &call, const JobTool &t, const QDateTime &now)
{
    call.out << "  T" << t.number << "  loaded at line " << t.loadLines.value(0);
    if (t.loads > 1)
        call.out << " (" << t.loads << " times)";
    if (!t.inTable)
        call.out << "  not in the table";
    else if (t.tlo)
        call.out << "  TLO " << mm(*t.tlo) << (t.setByHand ? " set by hand" : "");
    else
        call.out << "  not measured";
    if (t.measuredAt.isValid())
        call.out << " (" << ageText(t.measuredAt, now) << ')';
    call.out << "  cutting " << durationText(t.cuttingSeconds) << ", " << mm(t.feedPathMm) << " mm";
    if (t.lowestZ)
        call.out << ", lowest Z " << mm(*t.lowestZ);
    call.out << '\n';
}

void printReport(Invocation &call, const JobReport &report, const QDateTime &now)
{
    call.out << report.program << ": " << report.lines << " lines as " << dialectInfo(report.dialect).name
             << ", cutting " << durationText(report.cuttingSeconds) << ", rapids " << mm(report.rapidMm)
             << " mm" << (report.cancelled ? " (cancelled: what was read so far)" : "") << '\n';
    call.out << (report.tools.isEmpty() ? "No tool changes.\n" : "Tools, in order of use:\n");
    for (const JobTool &t : report.tools)
        printTool(call, t, now);
    if (report.moreTools > 0)
        call.out << u"  … and "_s << report.moreTools << " more tools from line " << report.moreFromLine
                 << " (" << report.moreLoads << " loads): counted, not listed; the first "
                 << report.tools.size() << " of the program's " << report.distinctTools()
                 << " distinct tools are listed.\n";
    for (const Finding &f : report.findings) {
        call.out << severityName(f.severity()) << ": line " << f.line << ": " << f.message;
        if (f.count > 1)
            call.out << " (lines " << lineList(f) << ')';
        call.out << '\n';
    }
    call.out << report.summary() << Qt::endl;
}

} // namespace

Result<JobCheckSetup> readJobSetup(Invocation &call, std::unique_ptr<Library> &library, QString &machine)
{
    machine = call.has(u"machine"_s) ? call.option(u"machine"_s).trimmed() : kDefaultMachineName;
    auto opened = openExistingLibrary(call);
    if (!opened)
        return Error { opened.error().message + u" Use --no-history to check without the history."_s };
    library = opened.takeValue();
    const auto dialect = programDialect(call, library.get(), machine);
    if (!dialect)
        return Error { u"--dialect must be one of carvera, grblhal, fanuc, fagor, ab9, aerotech, linuxcnc."_s };
    JobCheckSetup setup;
    setup.dialect = *dialect;
    if (call.has(u"table"_s)) {
        auto table = loadTableFile(call.option(u"table"_s));
        if (!table)
            return table.error();
        setup.useTable(table.value());
    }
    if (call.has(u"z-floor"_s)) {
        const auto z = parseDecimal(call.option(u"z-floor"_s).toUtf8());
        if (!z || !std::isfinite(*z) || std::fabs(*z) > kMaxMachineMillimetres)
            return Error { u"--z-floor must be a work Z in the program's units, such as -20."_s };
        setup.zFloor = *z;
    }
    if (call.has(u"stale-days"_s)) {
        const auto days = parseInteger(call.option(u"stale-days"_s).toUtf8());
        if (!days || *days < 1 || *days > 3650)
            return Error { u"--stale-days must be a whole number of days from 1 to 3650."_s };
        setup.staleDays = int(*days);
    }
    if (call.has(u"rack"_s)) {
        const auto rack = parseRack(call.option(u"rack"_s));
        if (!rack)
            return Error { u"--rack: "_s + rack.error().message };
        setup.rack = rack.value();
    } else if (setup.dialect == Dialect::Carvera) {
        setup.rack = carveraRack();
    }
    return setup;
}

int checkJob(Invocation &call)
{
    if (call.arguments.size() != 2)
        return fail(call,
            u"usage: toffee-cli job check PROGRAM [--table FILE] [--machine NAME] [--dialect D] [--z-floor Z]"_s,
            BadInput);
    std::unique_ptr<Library> library;
    QString machine;
    auto setup = readJobSetup(call, library, machine);
    if (!setup)
        return fail(call, setup.error().text(), BadInput);
    const QDateTime now = setup.value().now;
    const auto report
        = checkJobFile(call.arguments.at(1), setup.takeValue(), libraryFacts(library.get(), machine));
    if (!report)
        return fail(call, report.error().text(), BadInput);
    if (call.json)
        printJson(call, reportJson(report.value()));
    else
        printReport(call, report.value(), now);
    return report.value().exitCode();
}

int runJob(Invocation &call)
{
    const QString sub = call.arguments.value(0);
    if (sub == u"check"_s)
        return checkJob(call);
    if (sub == u"prepare"_s)
        return prepareJob(call);
    return fail(call, u"usage: toffee-cli job check PROGRAM … | job prepare PROGRAM --table FILE -o OUT …"_s,
        BadInput);
}

} // namespace Toffee::Cli
