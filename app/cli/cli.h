// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QHash>
#include <QStringList>
#include <QTextStream>

class QJsonObject;

namespace Toffee::Cli {

// Incomplete: it ran, but a check did not check everything (a tool the rack check or a prepared break test
// could not compare): never 0, so that a script does not take it for a pass.
enum ExitCode {
    Success = 0,
    Incomplete = 1,
    BadInput = 2,
    ToolBroken = 3,
    MachineError = 4,
    LinkFailure = 5
};

// One parsed command line and where its output goes. With --json, every command prints one JSON object on
// stdout, a failure included ({"error": message}); messages for people go to stderr either way.
struct Invocation
{
    QString command;
    QStringList arguments; // positional, after the command
    QHash<QString, QString> options; // --name value, and --flag with an empty value
    bool json = false;
    QTextStream &out;
    QTextStream &err;

    [[nodiscard]] bool has(const QString &option) const { return options.contains(option); }
    [[nodiscard]] QString option(const QString &name) const { return options.value(name); }
};

int run(const QStringList &arguments, QTextStream &out, QTextStream &err);
int fail(Invocation &call, const QString &message, ExitCode code);
void printJson(Invocation &call, const QJsonObject &object);

int showTable(Invocation &call);
int convertTable(Invocation &call);
int newCutter(Invocation &call);
int probingSettings(Invocation &call);
int importTools(Invocation &call);
int exportOffsets(Invocation &call);
int simulateProgram(Invocation &call);
int showHistory(Invocation &call);
int runLibrary(Invocation &call);
int runJob(Invocation &call);
int discoverMachines(Invocation &call);
[[nodiscard]] bool isMachineCommand(const QString &command);
int runMachineCommand(Invocation &call);

} // namespace Toffee::Cli
