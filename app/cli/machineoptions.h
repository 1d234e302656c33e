// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QJsonObject>

#include "app/cli/cli.h"
#include "model/gcode/dialect.h"
#include "model/library/library.h"
#include "model/result.h"
#include "model/tooltable.h"
#include "serial/machineconnection.h"

namespace Toffee::Cli {

// A machine command's options, each checked before the port is even opened: what can be refused is refused
// without touching the machine.
struct MachineOptions
{
    ConnectionTarget target;
    int tool = 0; // select-tool and change-tool
    double tolerance = 0.0; // break-test
    std::optional<double> z; // set-tlo --z
    std::optional<double> aboveZ0; // set-tlo --above-z0
    int count = 1000; // link-test
    std::optional<ToolTable> table; // --table, loaded, and writable
    QString tablePath;
    // The history library every measurement is recorded in (none with --no-history), opened before the
    // machine moves; and the machine's name in it (--machine).
    std::unique_ptr<Library> library;
    QString machine;
    // Which machine it is, once its controller is known; whether the library sees it for the first time.
    MachineIdentity identity;
    bool newMachine = false;
    QList<int> rack; // --rack: the tools the machine's rack holds (1-6, a C1's, by default)
    bool useStoredTlo = false; // change-tool: a manual change takes the tool's fresh stored TLO
    int staleDays = 7; // --stale-days: what "fresh" means
    // probe, break-test, change-tool: --touches N and --offset X,Y for this command, over the tool's own
    // settings (the table's).
    std::optional<int> touches;
    std::optional<std::pair<double, double>> offset;
    bool sameEdge = false; // measure-repeatability: every touch on the same edge

    // How `tool` is probed: the table's settings, with this command's overrides.
    [[nodiscard]] ProbePlan probePlan(int tool) const;
};

// The rack commands (rack, measure-rack, check-rack) on a connected machine. `record` keeps a measurement or
// a verdict as every machine command does (false when it could not, which stops the sequence); `finish` ends
// the run with the whole result, and `incomplete` true when a check compared not every tool (exit 1). False
// when the command did not start.
bool startRackCommand(Invocation &call, MachineOptions &options, MachineConnection &connection,
    std::function<bool(const SessionResult &)> record,
    std::function<void(const SessionResult &, bool incomplete)> finish);
// change-tool --use-stored-tlo: the TLO the change takes, or nothing (a probe) with the reason on stderr.
[[nodiscard]] std::optional<double> storedTloForChange(
    Invocation &call, const MachineOptions &options, const MachineConnection &connection);
[[nodiscard]] bool isRackCommand(const QString &command);
// What the machine said it runs, and what that firmware can do: {"kind", "version", "break_test",
// "manual_offset"}.
[[nodiscard]] QJsonObject firmwareJson(const FirmwareInfo &firmware);

// The library --library names (or the standard one), opened; nothing with --no-history.
[[nodiscard]] Result<std::unique_ptr<Library>> openLibraryOption(const Invocation &call);

// For commands that only read the history: --library's (which must open), else the standard library when one
// exists (a check creates no library); nothing with --no-history or when there is none.
[[nodiscard]] Result<std::unique_ptr<Library>> openExistingLibrary(const Invocation &call);
// What this computer kept for the library (its outbox folder, and a shared library's outbox table) is sent
// (sharedoutbox.cpp), and what happened is said on `err`.
void sendWaiting(Library &library, QTextStream &err);

// The machine's dialect as the library knows it, unless --dialect says otherwise; the Carvera by default.
// Nothing when --dialect names no dialect.
[[nodiscard]] std::optional<Dialect> programDialect(
    const Invocation &call, const Library *library, const QString &machine);

[[nodiscard]] Result<MachineOptions> readMachineOptions(const Invocation &call);
// Parts of it (machinetarget.cpp): a decimal option's value; exactly one machine named; the target read from
// --port, --host, --emulator, --protocol, --controller, --ini, --setter, --baud and --timeout.
[[nodiscard]] std::optional<double> decimalOption(const Invocation &call, const QString &name);
[[nodiscard]] Result<void> choosePort(const Invocation &call, MachineOptions &options);
[[nodiscard]] Result<void> readTarget(const Invocation &call, MachineOptions &options);
// Once the controller is known (MachineConnection's preparer), before anything of its own is sent: the
// machine's name (--machine, else the identity's default), bound to its identity in the library (another
// machine under the name is refused; one seen for the first time is said on stderr and adopts no reference),
// entered with that controller's dialect, and grblHAL given its tool setter and the reference Toffee kept for
// the machine (in options.target).
[[nodiscard]] Result<void> prepareForController(
    const Invocation &call, MachineOptions &options, const MachineIdentity &identity);

} // namespace Toffee::Cli
