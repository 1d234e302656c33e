// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

const QString kUsage = uR"(usage: toffee-cli [--json] COMMAND [ARGS]

Tool tables:
  show TABLE                 print a tool table (.json, .tbl or .csv)
  convert IN OUT             convert between formats, by extension or --to json|tbl|csv

Options:
  --json                     print one JSON object on stdout (errors too: {"error": message})
  --to FORMAT                convert: the output format (json, tbl, csv)
  --units mm|in              the units of a LinuxCNC .tbl file, which does not record them (default mm)
  --help                     this text

Exit codes: 0 success, 2 bad input or usage.
)"_s;

const QSet<QString> kValueOptions = { u"to"_s, u"units"_s };
const QSet<QString> kFlagOptions = { u"json"_s, u"help"_s };

int usageError(Invocation &call, const QString &message)
{
    fail(call, message, BadInput);
    call.err << '\n' << kUsage;
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

int run(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    Invocation call { {}, {}, {}, false, out, err };
    QStringList positional;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString &arg = arguments.at(i);
        if (!arg.startsWith(u"--"_s) || arg == u"--"_s) {
            positional << arg;
            continue;
        }
        QString name = arg.mid(2);
        QString value;
        if (const qsizetype eq = name.indexOf(u'='); eq >= 0) {
            value = name.mid(eq + 1);
            name.truncate(eq);
        } else if (kValueOptions.contains(name)) {
            if (i + 1 >= arguments.size()) {
                call.json = arguments.contains(u"--json"_s);
                return usageError(call, u"--%1 needs a value."_s.arg(name));
            }
            value = arguments.at(++i);
        }
        if (!kValueOptions.contains(name) && !kFlagOptions.contains(name)) {
            call.json = arguments.contains(u"--json"_s);
            return usageError(call, u"unknown option --%1."_s.arg(name));
        }
        call.options.insert(name, value);
    }
    call.json = call.has(u"json"_s);
    if (call.has(u"help"_s)) {
        out << kUsage;
        return Success;
    }
    if (positional.isEmpty())
        return usageError(call, u"no command given."_s);
    call.command = positional.takeFirst();
    call.arguments = positional;

    if (call.command == u"show")
        return showTable(call);
    if (call.command == u"convert")
        return convertTable(call);
    return usageError(call, u"unknown command \"%1\"."_s.arg(call.command));
}

} // namespace Toffee::Cli
