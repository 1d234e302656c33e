// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli library: the machine tables a library holds, put there from a file and read back into one, for
// a shop that sets its shared library up from a script.
#include <QJsonArray>
#include <QJsonObject>

#include "app/cli/cli.h"
#include "app/cli/machineoptions.h"
#include "model/formats/tablefile.h"
#include "model/library/library.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

int listTables(Invocation &call, Library &library)
{
    auto machines = library.tableMachines();
    if (!machines)
        return fail(call, machines.error().message, MachineError);
    QJsonArray list;
    for (const QString &machine : machines.value()) {
        // A table that cannot be read is listed as such; the machines after it are still listed.
        auto table = library.readTable(machine);
        if (!table) {
            list.append(QJsonObject { { u"machine"_s, machine }, { u"error"_s, table.error().message } });
            call.err << "toffee-cli: " << table.error().message << Qt::endl;
            if (!call.json)
                call.out << machine << ": cannot be read (see above)\n";
            continue;
        }
        const qsizetype tools = table.value().table().size();
        list.append(QJsonObject { { u"machine"_s, machine }, { u"tools"_s, tools },
            { u"units"_s, unitsSymbol(table.value().units) } });
        if (!call.json)
            call.out << machine << ": " << tools << " tools (" << unitsSymbol(table.value().units) << ")\n";
    }
    if (call.json)
        printJson(call,
            QJsonObject { { u"library"_s, library.location().text() },
                { u"read_only"_s, library.isReadOnly() }, { u"tables"_s, list } });
    else if (machines.value().isEmpty())
        call.out << "no machine tables in " << library.location().displayName() << '\n';
    call.out.flush();
    return Success;
}

int putTable(Invocation &call, Library &library, const QString &machine)
{
    if (call.arguments.size() != 2)
        return fail(call, u"usage: toffee-cli library put --machine NAME TABLE"_s, BadInput);
    auto table = loadTableFile(call.arguments.at(1));
    if (!table)
        return fail(call, table.error().text(), BadInput);
    auto created = library.createTable(machine, table.value());
    if (!created)
        return fail(call, created.error().message, BadInput);
    if (call.json)
        printJson(call, QJsonObject { { u"machine"_s, machine }, { u"tools"_s, table.value().size() } });
    else
        call.out << "put " << table.value().size() << " tools as " << machine << "'s table in "
                 << library.location().displayName() << Qt::endl;
    return Success;
}

int getTable(Invocation &call, Library &library, const QString &machine)
{
    const QString out = call.option(u"output"_s);
    const auto format = formatForPath(out);
    if (call.arguments.size() != 1 || out.isEmpty() || !format)
        return fail(
            call, u"usage: toffee-cli library get --machine NAME -o OUT (.json, .tbl or .csv)"_s, BadInput);
    auto table = library.readTable(machine);
    if (!table)
        return fail(call, table.error().message, BadInput);
    if (auto saved = saveTableFile(out, table.value().table(), *format); !saved)
        return fail(call, saved.error().text(), BadInput);
    if (call.json)
        printJson(call, QJsonObject { { u"machine"_s, machine }, { u"output"_s, out } });
    else
        call.out << "wrote " << machine << "'s table to " << out << Qt::endl;
    return Success;
}

} // namespace

int runLibrary(Invocation &call)
{
    const QString what = call.arguments.value(0);
    if (what != u"tables"_s && what != u"put"_s && what != u"get"_s)
        return fail(call, u"library takes tables, put or get."_s, BadInput);
    if (call.has(u"no-history"_s))
        return fail(call, u"library reads the library: leave out --no-history."_s, BadInput);
    const QString machine = call.option(u"machine"_s);
    if (what != u"tables"_s && machine.isEmpty())
        return fail(call, u"library %1 needs --machine NAME."_s.arg(what), BadInput);
    auto library = openLibraryOption(call);
    if (!library)
        return fail(call, library.error().message, BadInput);
    if (what == u"tables"_s)
        return listTables(call, *library.value());
    return what == u"put"_s ? putTable(call, *library.value(), machine)
                            : getTable(call, *library.value(), machine);
}

} // namespace Toffee::Cli
