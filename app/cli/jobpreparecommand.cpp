// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli job prepare: the program rewritten so that the machine restores stored offsets and break-tests
// each tool (the Carvera), or has its G43 after each change (the G43 controllers).
#include <QJsonArray>
#include <QJsonObject>

#include "app/cli/jobcommands.h"
#include "model/formats/tablefile.h"
#include "model/job/jobprepare.h"
#include "model/textparsing.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

Result<PrepareOptions> readPrepareOptions(Invocation &call, const JobCheckSetup &setup)
{
    PrepareOptions o;
    o.dialect = setup.dialect;
    o.useStoredTlo = call.has(u"use-stored-tlo"_s);
    o.breakTest = call.has(u"break-test"_s);
    o.staleDays = setup.staleDays;
    o.rack = setup.rack.value_or(QList<int> {});
    o.now = setup.now;
    o.zFloor = setup.zFloor;
    if (call.has(u"tolerance"_s)) {
        if (!o.breakTest)
            return Error { u"--tolerance is the break test's: give --break-test with it."_s };
        const auto h = parseDecimal(call.option(u"tolerance"_s).toUtf8());
        if (!h)
            return Error { u"--tolerance must be a number of millimetres, such as 0.05."_s };
        o.tolerance = *h;
    }
    return o;
}

void printSummary(Invocation &call, const PrepareSummary &s, const QString &output)
{
    if (call.json) {
        QJsonArray notes;
        for (const QString &n : s.notes)
            notes.append(n);
        printJson(call,
            QJsonObject { { u"output"_s, output }, { u"original_lines"_s, s.originalLines },
                { u"prepared_lines"_s, s.preparedLines }, { u"inserted"_s, s.inserted },
                { u"changed"_s, s.changed }, { u"cutting_moves_checked"_s, s.cuttingMoves },
                { u"notes"_s, notes } });
        return;
    }
    for (const PrepareHunk &hunk : s.hunks) {
        for (const PrepareRow &row : hunk) {
            if (row.originalLine == 0)
                call.out << "  + " << row.preparedLine << ": " << row.prepared << '\n';
            else if (row.original != row.prepared)
                call.out << "  ~ " << row.preparedLine << ": " << row.prepared << "   (line "
                         << row.originalLine << " was: " << row.original << ")\n";
        }
    }
    for (const QString &note : s.notes)
        call.out << "note: " << note << '\n';
    call.out << "wrote " << output << ": " << s.preparedLines << " lines (" << s.inserted << " inserted, "
             << s.changed << " changed); " << s.cuttingMoves << " cutting moves checked against the original"
             << Qt::endl;
}

} // namespace

int prepareJob(Invocation &call)
{
    if (call.arguments.size() != 2 || !call.has(u"table"_s) || !call.has(u"output"_s))
        return fail(call,
            u"usage: toffee-cli job prepare PROGRAM --table FILE [--use-stored-tlo] [--break-test "
            u"[--tolerance H]] "
            "-o OUT"_s,
            BadInput);
    std::unique_ptr<Library> library;
    QString machine;
    auto setup = readJobSetup(call, library, machine);
    if (!setup)
        return fail(call, setup.error().text(), BadInput);
    const auto options = readPrepareOptions(call, setup.value());
    if (!options)
        return fail(call, options.error().message, BadInput);
    auto table = loadTableFile(call.option(u"table"_s));
    if (!table)
        return fail(call, table.error().text(), BadInput);
    const QString output = call.option(u"output"_s);
    PrepareGuards guards;
    guards.protectedFiles = { call.option(u"table"_s) };
    guards.moreFacts = libraryFacts(library.get(), machine);
    const auto summary
        = prepareJobFile(call.arguments.at(1), table.value(), options.value(), output, {}, guards);
    if (!summary)
        return fail(call, summary.error().text(), summary.error().line > 0 ? MachineError : BadInput);
    printSummary(call, summary.value(), output);
    if (summary.value().untestedTools > 0) {
        call.err << "toffee-cli: the program was prepared, but " << summary.value().untestedTools
                 << (summary.value().untestedTools == 1 ? " tool gets" : " tools get")
                 << " no break test (each note above says why)." << Qt::endl;
        return Incomplete;
    }
    return Success;
}

} // namespace Toffee::Cli
