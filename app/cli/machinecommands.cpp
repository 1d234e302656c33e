// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli's machine commands: one connection, one operation, one result.
#include <algorithm>
#include <cmath>
#include <numeric>

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QTimer>

#include "app/cli/cli.h"
#include "model/formats/tablefile.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "serial/machineconnection.h"
#include "serial/machinesession.h"
#include "serial/serialporttransport.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

const QStringList kMachineCommands = { u"status"_s, u"report"_s, u"probe"_s, u"break-test"_s, u"set-tlo"_s,
    u"select-tool"_s, u"change-tool"_s, u"unlock"_s, u"link-test"_s };

ExitCode exitCodeFor(SessionResult::Outcome outcome)
{
    switch (outcome) {
    case SessionResult::Outcome::Success:
        return Success;
    case SessionResult::Outcome::Refused:
        return BadInput;
    case SessionResult::Outcome::ToolBroken:
        return ToolBroken;
    case SessionResult::Outcome::MachineError:
        return MachineError;
    case SessionResult::Outcome::LinkFailure:
        return LinkFailure;
    }
    return MachineError;
}

std::optional<double> decimalOption(Invocation &call, const QString &name)
{
    return parseDecimal(call.option(name).toUtf8());
}

QString mm(double v)
{
    return formatNumber(v, NumberFormat::fixed(3));
}

QJsonArray axes(const std::array<double, 3> &a)
{
    return { a[0], a[1], a[2] };
}

void printTlo(Invocation &call, const SessionResult &r)
{
    const int tool = r.tool.value_or(-1);
    if (call.json) {
        printJson(call,
            QJsonObject { { u"tool"_s, tool }, { u"reference_mz"_s, r.tlo->referenceMz },
                { u"current_mz"_s, r.tlo->currentMz }, { u"tlo"_s, r.tlo->tlo() } });
        return;
    }
    call.out << "T" << tool << ": TLO " << mm(r.tlo->tlo()) << " mm (current tool MCS Z "
             << mm(r.tlo->currentMz) << ", reference MCS Z " << mm(r.tlo->referenceMz) << ")" << Qt::endl;
}

void printStatus(Invocation &call, const MachineStatus &s)
{
    if (call.json) {
        printJson(call,
            QJsonObject { { u"state"_s, s.state }, { u"tool"_s, s.tool ? QJsonValue(*s.tool) : QJsonValue() },
                { u"tlo"_s, s.tlo ? QJsonValue(*s.tlo) : QJsonValue() }, { u"mpos"_s, axes(s.mpos) },
                { u"wpos"_s, axes(s.wpos) },
                { u"halt_reason"_s, s.haltReason ? QJsonValue(*s.haltReason) : QJsonValue() } });
        return;
    }
    call.out << s.state;
    if (s.haltReason)
        call.out << " (halted: " << haltReasonName(*s.haltReason) << ". " << haltRecovery(*s.haltReason)
                 << ")";
    if (s.tool)
        call.out << "  T" << *s.tool << "  TLO " << mm(s.tlo.value_or(0));
    call.out << "  MPos " << mm(s.mpos[0]) << ' ' << mm(s.mpos[1]) << ' ' << mm(s.mpos[2]) << "  WPos "
             << mm(s.wpos[0]) << ' ' << mm(s.wpos[1]) << ' ' << mm(s.wpos[2]) << Qt::endl;
}

void printBreakTest(Invocation &call, const SessionResult &r)
{
    const double diff = std::fabs(r.breakTest->newTlo - r.breakTest->oldTlo);
    const bool broken = r.outcome == SessionResult::Outcome::ToolBroken;
    if (call.json) {
        printJson(call,
            QJsonObject { { u"old_tlo"_s, r.breakTest->oldTlo }, { u"new_tlo"_s, r.breakTest->newTlo },
                { u"difference"_s, diff }, { u"tolerance"_s, r.tolerance }, { u"broken"_s, broken } });
    } else {
        call.out << "T" << r.tool.value_or(-1) << ": old TLO " << mm(r.breakTest->oldTlo) << ", new "
                 << mm(r.breakTest->newTlo) << ", difference " << mm(diff) << " (tolerance " << r.tolerance
                 << "): " << (broken ? "BROKEN" : "OK") << Qt::endl;
    }
    if (broken)
        call.err << "toffee-cli: " << r.message << Qt::endl;
}

} // namespace

bool isMachineCommand(const QString &command)
{
    return kMachineCommands.contains(command);
}

int runMachineCommand(Invocation &call)
{
    // Everything that can be refused is refused here, before the port is even opened.
    const QString command = call.command;
    const bool wantsTool = command == u"select-tool" || command == u"change-tool";
    if (call.arguments.size() != (wantsTool ? 1 : 0))
        return fail(call,
            wantsTool ? u"usage: toffee-cli ... %1 N"_s.arg(command)
                      : u"%1 takes no arguments."_s.arg(command),
            BadInput);
    if (call.has(u"port"_s) == call.has(u"emulator"_s))
        return fail(call, u"say which machine: --port DEVICE or --emulator."_s, BadInput);
    int tool = 0;
    if (wantsTool) {
        const auto n = parseInteger(call.arguments.front().toUtf8());
        if (!n || *n < INT_MIN || *n > INT_MAX)
            return fail(call, u"\"%1\" is not a tool number."_s.arg(call.arguments.front()), BadInput);
        tool = int(*n);
        if (auto r = MachineSession::validateToolNumber(tool); !r)
            return fail(call, r.error().message, BadInput);
    }
    int baud = SerialPortTransport::kDefaultBaud;
    if (call.has(u"baud"_s)) {
        const auto b = parseInteger(call.option(u"baud"_s).toUtf8());
        if (!b || *b < 50 || *b > 4000000)
            return fail(call, u"--baud must be a baud rate such as 115200."_s, BadInput);
        baud = int(*b);
    }
    int timeoutMs = 0;
    if (call.has(u"timeout"_s)) {
        const auto t = decimalOption(call, u"timeout"_s);
        if (!t || *t <= 0 || *t > 3600)
            return fail(call, u"--timeout must be a number of seconds, above 0."_s, BadInput);
        timeoutMs = int(*t * 1000);
    }
    double tolerance = MachineSession::kDefaultTolerance;
    if (command == u"break-test" && call.has(u"tolerance"_s)) {
        const auto t = decimalOption(call, u"tolerance"_s);
        if (!t)
            return fail(call, u"--tolerance must be a number of millimetres, such as 0.05."_s, BadInput);
        tolerance = *t;
        if (auto r = MachineSession::validateTolerance(tolerance); !r)
            return fail(call, r.error().message, BadInput);
    }
    std::optional<double> z;
    std::optional<double> aboveZ0;
    if (command == u"set-tlo") {
        if (call.has(u"z"_s) == call.has(u"above-z0"_s))
            return fail(call, u"set-tlo needs one of --z V or --above-z0 H."_s, BadInput);
        const QString name = call.has(u"z"_s) ? u"z"_s : u"above-z0"_s;
        const auto v = decimalOption(call, name);
        if (!v)
            return fail(call, u"--%1 must be a number of millimetres."_s.arg(name), BadInput);
        if (auto r = MachineSession::validateOffset(u"--"_s + name, *v); !r)
            return fail(call, r.error().message, BadInput);
        (name == u"z" ? z : aboveZ0) = *v;
    }
    int count = 1000;
    if (command == u"link-test" && call.has(u"count"_s)) {
        const auto c = parseInteger(call.option(u"count"_s).toUtf8());
        if (!c || *c < 1 || *c > 10000000)
            return fail(call, u"--count must be a whole number from 1 up."_s, BadInput);
        count = int(*c);
    }
    std::optional<ToolTable> table;
    const QString tablePath = call.option(u"table"_s);
    if (call.has(u"table"_s)) {
        auto loaded = loadTableFile(tablePath);
        if (!loaded)
            return fail(call, loaded.error().text(), BadInput);
        table = loaded.takeValue();
        // Found out before the machine moves, not after: a measurement that cannot be saved is lost.
        const QFileInfo info(tablePath);
        if (!info.isWritable() || !QFileInfo(info.absolutePath()).isWritable())
            return fail(call,
                u"%1 cannot be written (check its permissions and its folder's); nothing was sent to the "
                "machine."_s.arg(tablePath),
                BadInput);
    }

    const std::unique_ptr<LineTransport> transport
        = makeTransport({ call.has(u"emulator"_s), call.option(u"port"_s), baud });
    MachineLink link(transport.get());
    link.setTimeoutOverride(timeoutMs);
    MachineSession session(&link);
    QEventLoop loop;
    int exitCode = Success;

    bool recordFailed = false; // then the exit code says so (unless the tool is broken, which says more)
    auto finishWith = [&](const SessionResult &r) {
        if (!recordFailed || r.outcome == SessionResult::Outcome::ToolBroken)
            exitCode = exitCodeFor(r.outcome);
        if (!r.ok() && !(r.outcome == SessionResult::Outcome::ToolBroken && r.breakTest))
            fail(call, r.message, ExitCode(exitCode));
        loop.quit();
    };
    // What a successful probe, a manual offset or a break test means for the table, saved at once.
    auto record = [&](const SessionResult &r) {
        if (!table)
            return true;
        const int measured = r.tool.value_or(-1);
        if (!r.recording) {
            fail(call, u"the machine reports no tool in the spindle; nothing was recorded."_s, MachineError);
            exitCode = MachineError;
            recordFailed = true;
            return false;
        }
        Result<void> saved = table->record(*r.recording); // as the window records it
        if (saved)
            saved = saveTableFile(tablePath, *table, formatForPath(tablePath).value_or(TableFormat::Json));
        if (!saved) {
            fail(call,
                r.breakTest ? u"the break test ran on T%1 but could not be recorded: %2"_s.arg(measured).arg(
                    saved.error().text())
                    : command == u"set-tlo"
                    ? u"set T%1's TLO to %2 mm on the machine but could not record it: %3"_s.arg(measured)
                          .arg(mm(r.tlo->tlo()), saved.error().text())
                    : u"measured T%1 (TLO %2 mm) but could not record it: %3"_s.arg(measured).arg(
                        mm(r.tlo->tlo()), saved.error().text()),
                BadInput);
            exitCode = BadInput;
            recordFailed = true;
            return false;
        }
        return true;
    };
    auto printed = [&](auto print) {
        return [&, print](const SessionResult &r) {
            if (!r.ok() && !(r.outcome == SessionResult::Outcome::ToolBroken && r.breakTest))
                return finishWith(r);
            print(r);
            finishWith(r);
        };
    };

    auto operate = [&] {
        if (command == u"status")
            session.status(printed([&](const SessionResult &r) { printStatus(call, *r.status); }));
        else if (command == u"report")
            session.report(printed([&](const SessionResult &r) { printTlo(call, r); }));
        else if (command == u"probe" || command == u"change-tool") {
            auto done = [&](const SessionResult &r) {
                if (!r.ok())
                    return finishWith(r);
                if (record(r))
                    printTlo(call, r);
                loop.quit();
            };
            if (command == u"probe")
                session.probe(done);
            else
                session.changeTool(tool, done);
        } else if (command == u"break-test")
            session.breakTest(tolerance, printed([&](const SessionResult &r) {
                printBreakTest(call, r);
                if (r.breakTest)
                    record(r);
            }));
        else if (command == u"set-tlo") {
            auto print = printed([&](const SessionResult &r) {
                if (record(r))
                    printTlo(call, r);
            });
            if (z)
                session.setTlo(*z, print);
            else
                session.setTloAboveZ0(*aboveZ0, print);
        } else if (command == u"select-tool")
            session.selectTool(tool, printed([&](const SessionResult &r) {
                // M493.2 keeps the TLO of the tool measured before: say so, every time.
                const QString warning
                    = u"T%1 is active but the machine still uses the TLO it had before, which "
                      "is another tool's; probe T%1 (or set its TLO) before you cut."_s.arg(
                          r.tool.value_or(-1));
                if (call.json)
                    printJson(
                        call, QJsonObject { { u"tool"_s, r.tool.value_or(-1) }, { u"warning"_s, warning } });
                else
                    call.out << warning << Qt::endl;
            }));
        else if (command == u"unlock")
            session.unlock(printed([&](const SessionResult &r) { printStatus(call, *r.status); }));
        else if (command == u"link-test") {
            link.setPollInterval(0); // measure the commands alone
            auto times = std::make_shared<QList<double>>();
            auto clock = std::make_shared<QElapsedTimer>();
            auto next = std::make_shared<std::function<void()>>();
            *next = [&, times, clock, next] {
                if (times->size() == count) {
                    std::sort(times->begin(), times->end());
                    const double median = times->at(times->size() / 2);
                    const double p99
                        = times->at(std::min<qsizetype>(times->size() - 1, qsizetype(times->size() * 0.99)));
                    const double mean
                        = std::accumulate(times->cbegin(), times->cend(), 0.0) / double(times->size());
                    if (call.json)
                        printJson(call,
                            QJsonObject { { u"count"_s, count }, { u"median_ms"_s, median },
                                { u"p99_ms"_s, p99 }, { u"max_ms"_s, times->last() }, { u"mean_ms"_s, mean },
                                { u"link"_s, transport->description() } });
                    else
                        call.out << count << " round trips over " << transport->description() << ": median "
                                 << mm(median) << " ms, p99 " << mm(p99) << " ms, max " << mm(times->last())
                                 << " ms" << Qt::endl;
                    *next = nullptr; // break the cycle
                    return finishWith(SessionResult {});
                }
                clock->start();
                link.send("G90", MachineLink::kDefaultTimeoutMs,
                    [&, times, clock, next](const CommandReply &reply) {
                        if (!reply.ok()) {
                            SessionResult r;
                            r.outcome = reply.status == CommandReply::Status::Refused
                                ? SessionResult::Outcome::MachineError
                                : SessionResult::Outcome::LinkFailure;
                            r.message = reply.message;
                            *next = nullptr;
                            return finishWith(r);
                        }
                        times->append(double(clock->nsecsElapsed()) / 1e6);
                        (*next)();
                    });
            };
            (*next)();
        }
    };

    // Started from inside the loop, so that a failure reported at once still ends it.
    QTimer::singleShot(0, &loop, [&] {
        session.connectToMachine([&](const SessionResult &r) {
            if (!r.ok())
                return finishWith(r);
            operate();
        });
    });
    loop.exec();
    link.close();
    return exitCode;
}

} // namespace Toffee::Cli
