// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/cli.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

#include "model/limits.h"
#include "model/result.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

const QString kUsage = uR"(usage: toffee-cli [--json] COMMAND [ARGS]

Tool tables:
  show TABLE                 print a tool table (.json, .tbl or .csv)
  convert IN OUT             convert between formats, by extension or --to json|tbl|csv
  new-cutter N --table FILE  another cutter in T N's pocket: its TLO, length, wear and break mark end (the
                             TLO kept in the history as the old cutter's, --machine NAME); measure it before
                             it cuts
  probing N --table FILE [--set SETTINGS]
                             how T N is measured on the tool setter, shown or set: "X 20, Y 0" (the
                             touch-off point from the setter's centre, in the table's units), "4 edges"
                             (one touch each by default), "3 touches", "same edge" (no turn between touches),
                             "latch 20" (the slow touch's feed per minute), "spread 0.03" (edges further
                             apart are a finding); --set "" for one touch at the centre
  export --dialect D TABLE   the program that loads TABLE into a controller (--tool N for one tool)
  simulate --dialect D PROGRAM [--table FILE] [--samples N]
                             run PROGRAM as controller D would: where each move ends, and the offsets after
  dialects: carvera, grblhal, fanuc, fagor, ab9, aerotech, linuxcnc
  import SOURCE --into TABLE [--dry-run] [--cam-units mm|in]
                             tools from a CAM library (Fusion .json or .tools, .hsmlib, or a program with
                             Makera CAM's tool header) into TABLE, created (in --units, default mm) when
                             missing: what is new, what changes and how, what is unchanged; measured TLOs,
                             wear and notes are kept, inch libraries converted; a tool whose cutter is
                             another (type, diameter, overall length) gets a new cutter, as new-cutter;
                             --cam-units: the unit of the library's tools that give none

The machine: toffee-cli (--port DEV [--baud N] | --host HOST[:PORT] | --emulator) [--protocol P] [--table FILE]
                 COMMAND
  --host                     the machine over the network: its console on TCP port PORT (default 2222;
                             LinuxCNC's linuxcncrsh 5007)
  --protocol auto|text|framed  plain text, or Makera's frames (its firmware from 1.0.4); auto finds out
  --controller auto|carvera|grblhal|linuxcnc
                             the controller the machine runs; auto (the default): found by asking it,
                             with questions that change nothing on any
  --ini FILE                 LinuxCNC: the INI it runs, on this computer, whose tool table (tool.tbl) is
                             read (linuxcncrsh cannot); found by itself when LinuxCNC runs here. Its enable
                             password: TOFFEE_LINUXCNC_PASSWORD (default EMCTOO)
  --setter X,Y,ZMIN[,SEEK,LATCH[,BACKOFF]]
                             grblHAL, LinuxCNC: the tool setter in machine coordinates (mm), the lowest Z to search to,
                             the feeds (mm/min, default 500 and 40) and the back-off between touches (2 mm)
  status                     state, active tool, TLO, positions
  report                     the tool length offsets (M493.4)
  probe                      measure the current tool on the tool setter (M491); the machine moves
  break-test [--tolerance H] re-measure and compare with the stored TLO (M491.1; H >= %1, default %2)
  probe, break-test, change-tool: as --table's tool settings say (toffee-cli probing), or for this command
  --touches N                touch N times (one per cutting edge), the TLO from the longest; each touch and
                             their spread printed (JSON: "touches", "spread") and kept in the history
  --offset X,Y               touch off X,Y mm from the setter's centre (a face mill's edge)
  measure-repeatability N --touches K
                             touch T N (in the spindle) K times on the same edge: the setter's spread, and
                             the smallest break-test tolerance it can trust, kept for the machine; the tool's
                             TLO recorded as a probe's; the machine moves
  set-tlo --z V              set the TLO directly, in millimetres whatever the table's units (M493.3 Z)
  set-tlo --above-z0 H       set the TLO from the current position, the tip H above work Z0 (M493.3 Z)
  select-tool N              make tool N active without a change (M493.2 T)
  change-tool N [--use-stored-tlo [--stale-days D]]
                             change to tool N and measure it (M6 T); the machine moves. With
                             --use-stored-tlo and --table, a manual change (N not in --rack) takes N's fresh
                             measured TLO instead of a probe (M6 T H)
  rack --table FILE          the rack (--rack, default 1-6): each slot's tool with its stored TLO and its age,
                             the tool in the spindle, and the firmware the machine runs
  measure-rack --table FILE  change to each rack tool in turn and store its TLO (first setup); the machine moves
  check-rack --table FILE [--tolerance H]
                             change to each rack tool, give it its stored TLO and break-test it (M6 T,
                             M493.3 Z, M491.1 H), then put the last one back (M6 T-1); a broken tool stops it
                             (the machine halts; exit 3, the tool named). The community firmware only
  restore N --table FILE     set the TLO the table holds for tool N on the machine (M493.2 T, M493.3 Z),
                             when it was measured against the machine's reference; one set by hand, failed
                             in a break test or older than --stale-days (7) is refused unless --anyway
  unlock                     clear a halt ($X)
  stop                       stop whatever the machine is doing, at once (the Carvera and grblHAL halt:
                             unlock follows; LinuxCNC: set abort), then its status
  link-test --count N        N round trips; median, p99 and max in milliseconds
  push-offsets --table FILE  grblHAL, LinuxCNC: every tool of the table with a TLO into the controller's
                             own table (G10 L1 P Z), read back ($#; tool.tbl); tools beyond it refused by name
  pull-offsets --table FILE  grblHAL, LinuxCNC: the controller's table into the file (new tools added; a changed TLO
                             marked as read from the controller, with a history event)
  probe, break-test, set-tlo, change-tool, restore, measure-rack and check-rack record every measurement in the
  history library (--machine NAME; default Carvera, grblHAL, LinuxCNC or Emulator, as the machine is), and warn when a
  probe is off its tool's wear trend. A name stands for one machine (its controller and how it is reached):
  another machine under it is refused, its reference and setter never applied; --same-machine says that it
  is the same machine reached another way

Jobs: toffee-cli job check PROGRAM [--table FILE] [--machine NAME] [--dialect D] [--z-floor Z]
                             [--stale-days N] [--rack LIST]
                             the program against the table and the history before it runs: its tools in
                             order of use, their TLOs and ages, cutting times, and what is wrong, by line;
                             exit 0 clean, 1 warnings only, 4 errors
  job prepare PROGRAM --table FILE [--use-stored-tlo] [--break-test [--tolerance H]] -o OUT
                             Carvera: a manual change takes the tool's fresh stored TLO instead of a probe
                             (M6 T H, M493.2 T, M493.3 Z); M491.1 after each tool's last cut. G43
                             controllers: the missing G43 H after each change. Checked through the
                             interpreter before OUT is written (whole or not at all)
  --rack LIST                the tools the machine's rack holds: 1-6 (a Carvera C1, the default), none, or
                             a list such as 1,2,5-8

Wi-Fi: toffee-cli discover [--seconds S] [--discovery-port P]
                             the machines heard announcing themselves (UDP 3333, default 3 s): name, address,
                             port, and whether another program is connected to it

The history: toffee-cli history [--machine NAME] [--tool N] [--since DATE] [--json | --csv]
  history add-use --machine NAME --program FILE [--dialect D]
                             the program ran: record each tool's cutting time and feed path

Machine tables in the library (docs/LIBRARY.md): toffee-cli library tables | put | get [--library URL]
  library tables             the machines whose tool table the library holds
  library put --machine NAME TABLE
                             put TABLE in the library as NAME's table (refused when it has one)
  library get --machine NAME -o OUT
                             write NAME's table from the library to OUT (.json, .tbl or .csv)

Options:
  --json                     print one JSON object on stdout (errors too: {"error": message})
  --to FORMAT                convert: the output format (json, tbl, csv)
  --units mm|in              the units of a LinuxCNC .tbl file, which does not record them (default mm)
  --into TABLE               import: the table the tools go into (written whole or not at all)
  --dry-run                  import: show what would change, write nothing
  --table FILE               probe, change-tool, set-tlo, break-test: record in FILE the measured TLO,
                             the TLO set by hand (marked so), or a failed break test (the tool stays marked
                             until it is probed again); FILE must be writable before the machine moves
  --library PATH|URL         the library: an SQLite file (or sqlite:PATH; default
                             ~/.local/share/Toffee/Toffee/library.sqlite), or a shared one on PostgreSQL,
                             postgresql://USER@HOST[:PORT]/DB[?sslmode=require] (the password comes from
                             ~/.pgpass or PGPASSFILE, never from Toffee)
  --no-history               record nothing in the history library
  --timeout S                give up on connecting, or on any command, after S seconds (default: 5, 120 for motion)
  --help                     this text
  --version                  the version

Exit codes: 0 success, 2 bad input or usage, 3 broken tool detected, 4 machine error, alarm or program error,
5 link failure or timeout.
)"_s;

// The usage text, with the limits it quotes from their one home.
QString usage()
{
    return kUsage.arg(Limits::kMinBreakTolerance).arg(Limits::kDefaultBreakTolerance);
}

const QSet<QString> kValueOptions = { u"to"_s, u"units"_s, u"port"_s, u"baud"_s, u"table"_s, u"tolerance"_s,
    u"z"_s, u"above-z0"_s, u"count"_s, u"timeout"_s, u"dialect"_s, u"samples"_s, u"tool"_s, u"library"_s,
    u"machine"_s, u"since"_s, u"program"_s, u"z-floor"_s, u"stale-days"_s, u"output"_s, u"rack"_s, u"host"_s,
    u"protocol"_s, u"seconds"_s, u"discovery-port"_s, u"controller"_s, u"setter"_s, u"ini"_s, u"touches"_s,
    u"offset"_s, u"set"_s };
const QSet<QString> kFlagOptions = { u"json"_s, u"help"_s, u"version"_s, u"emulator"_s, u"no-history"_s,
    u"csv"_s, u"use-stored-tlo"_s, u"break-test"_s, u"same-machine"_s, u"anyway"_s };

// toffee-cli import's own options.
const QSet<QString> kImportValueOptions = { u"into"_s, u"cam-units"_s };
const QSet<QString> kImportFlagOptions = { u"dry-run"_s };

int usageError(Invocation &call, const QString &message)
{
    fail(call, message, BadInput);
    call.err << '\n' << usage();
    return BadInput;
}

} // namespace

int fail(Invocation &call, const QString &message, ExitCode code)
{
    if (call.json)
        printJson(call, QJsonObject { { u"error"_s, message } });
    call.err << "toffee-cli: " << message << Qt::endl;
    return code;
}

void printJson(Invocation &call, const QJsonObject &object)
{
    call.out << QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Compact)) << Qt::endl;
}

namespace {

// Reads --name value, --name=value and --flag into the options; the rest is the command and its arguments.
Result<void> parseOptions(const QStringList &arguments, Invocation &call)
{
    QStringList positional;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        QString arg = arguments.at(i);
        if (arg == u"-o"_s)
            arg = u"--output"_s; // job prepare … -o OUT
        if (!arg.startsWith(u"--"_s) || arg == u"--"_s) {
            positional << arg;
            continue;
        }
        QString name = arg.mid(2);
        QString value;
        if (const qsizetype eq = name.indexOf(u'='); eq >= 0) {
            value = name.mid(eq + 1);
            name.truncate(eq);
        } else if (kValueOptions.contains(name) || kImportValueOptions.contains(name)) {
            if (i + 1 >= arguments.size())
                return Error { u"--%1 needs a value."_s.arg(name) };
            value = arguments.at(++i);
        }
        if (!kValueOptions.contains(name) && !kFlagOptions.contains(name)
            && !kImportValueOptions.contains(name) && !kImportFlagOptions.contains(name))
            return Error { u"unknown option --%1."_s.arg(name) };
        call.options.insert(name, value);
    }
    if (!positional.isEmpty())
        call.command = positional.takeFirst();
    call.arguments = positional;
    return {};
}

using Command = int (*)(Invocation &);
const std::pair<QStringView, Command> kTableCommands[] = {
    { u"show", showTable },
    { u"convert", convertTable },
    { u"new-cutter", newCutter },
    { u"probing", probingSettings },
    { u"export", exportOffsets },
    { u"simulate", simulateProgram },
    { u"import", importTools },
    { u"history", showHistory },
    { u"library", runLibrary },
    { u"job", runJob },
    { u"discover", discoverMachines },
};

} // namespace

int run(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    Invocation call { {}, {}, {}, false, out, err };
    if (auto parsed = parseOptions(arguments, call); !parsed) {
        call.json = arguments.contains(u"--json"_s);
        return usageError(call, parsed.error().message);
    }
    call.json = call.has(u"json"_s);
    if (call.has(u"help"_s)) {
        out << usage();
        return Success;
    }
    if (call.has(u"version"_s)) {
        out << "toffee-cli " << TOFFEE_VERSION << Qt::endl;
        return Success;
    }
    if (call.command.isEmpty())
        return usageError(call, u"no command given."_s);
    for (const auto &[name, command] : kTableCommands) {
        if (call.command == name)
            return command(call);
    }
    if (isMachineCommand(call.command))
        return runMachineCommand(call);
    return usageError(call, u"unknown command \"%1\"."_s.arg(call.command));
}

} // namespace Toffee::Cli
