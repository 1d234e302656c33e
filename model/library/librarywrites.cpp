// SPDX-License-Identifier: GPL-3.0-or-later
// Writing a machine table's tools: each row only over the version the station read (no lost update), and each
// new measurement event onto its tool's row.
#include <QMap>
#include <QSqlQuery>

#include "model/library/library.h"

#include "model/clock.h"

using namespace Qt::StringLiterals;

namespace Toffee {

Result<WriteOutcome> Library::writeTools(const QString &machine, const QList<ToolWrite> &writes)
{
    // In the order of their numbers, as every writer takes them: two saves never wait for each other's rows
    // in opposite orders (a deadlock).
    QList<ToolWrite> ordered = writes;
    std::sort(
        ordered.begin(), ordered.end(), [](const auto &a, const auto &b) { return a.number < b.number; });
    if (auto begun = beginWrite(); !begun)
        return begun.error();
    auto fail = [this](const Error &error) {
        rollback();
        return error;
    };
    auto units = tableUnits(machine);
    if (!units)
        return fail(units.error());
    if (!units.value())
        return fail(Error { tr("The library has no tool table for %1.").arg(machine) });
    WriteOutcome outcome;
    for (const ToolWrite &write : ordered) {
        for (int attempt = 0;; ++attempt) {
            auto row = readRow(machine, write.number);
            if (!row)
                return fail(row.error());
            const qint64 current = row.value() ? row.value()->version : 0;
            const std::optional<Tool> theirs = row.value() ? row.value()->tool : std::nullopt;
            if (theirs == write.tool) {
                outcome.written.insert(write.number, current); // already so: nothing to write
                break;
            }
            ToolWrite next = write;
            if (current != write.baseVersion) {
                // Changed meanwhile: written only when the changes touch different fields. A write that does
                // not say what it was made over (no base, over a row that was there) cannot be merged.
                const bool baseKnown = write.base || write.baseVersion == 0;
                const auto merged = baseKnown ? mergeTool(write.base, theirs, write.tool)
                                              : std::optional<std::optional<Tool>>();
                if (!merged) {
                    outcome.conflicts.append({ write.number, theirs, write.tool, current,
                        row.value() ? row.value()->updatedBy : QString() });
                    break;
                }
                next.tool = *merged;
            }
            auto put = putRow(machine, *units.value(), next, current, row.value().has_value());
            if (!put)
                return fail(put.error());
            if (put.value()) {
                outcome.written.insert(write.number, current + 1);
                if (next.tool != write.tool)
                    outcome.merged.insert(write.number, next.tool);
                break;
            }
            if (attempt == kRaceRetries)
                return fail(Error {
                    tr("T%1 of %2 kept changing while it was written.").arg(write.number).arg(machine) });
        }
    }
    if (!outcome.written.isEmpty()) {
        if (auto said = announce({ machine }); !said)
            return fail(said.error());
    }
    if (auto done = commit(); !done)
        return done.error();
    return outcome;
}

// Inside append's transaction: each new event's recording applied to its tool's row, the tools of a machine
// in the order of their numbers (as writeTools takes them) and each tool's events in the order they happened.
// Whether `e` changes a table's tool: newest wins, by the time of measurement, whatever order events reach
// the library in (a station's outbox may send one late). The history keeps every event; an event dated in the
// future (a clock set wrong) orders nothing, nor does a tool's TLO dated in the future stop a real one.
bool Library::supersedes(const HistoryEvent &e, const Tool *current)
{
    const QDateTime now = Clock::now();
    if (Clock::isInFuture(e.at, now))
        return false;
    if (!current || !current->measuredTlo || !current->measuredAt.isValid()
        || Clock::isInFuture(current->measuredAt, now))
        return true;
    return e.at >= current->measuredAt;
}

Result<void> Library::applyToTables(const QList<HistoryEvent> &events)
{
    QMap<QString, QMap<int, QList<HistoryEvent>>> byTool;
    for (const HistoryEvent &e : events) {
        if (recordingOf(e))
            byTool[e.machine][e.tool].append(e);
    }
    for (auto machine = byTool.cbegin(); machine != byTool.cend(); ++machine) {
        auto units = tableUnits(machine.key());
        if (!units)
            return units.error();
        if (!units.value())
            continue; // the machine's table is a file, not in the library
        for (auto tool = machine->cbegin(); tool != machine->cend(); ++tool) {
            QList<HistoryEvent> ordered = tool.value();
            std::stable_sort(
                ordered.begin(), ordered.end(), [](const auto &a, const auto &b) { return a.at < b.at; });
            for (int attempt = 0;; ++attempt) {
                auto row = readRow(machine.key(), tool.key());
                if (!row)
                    return row.error();
                ToolTable table(*units.value());
                if (row.value() && row.value()->tool)
                    (void)table.insert(*row.value()->tool);
                for (const HistoryEvent &e : ordered) {
                    if (supersedes(e, table.find(tool.key())))
                        (void)table.record(*recordingOf(e));
                }
                const Tool *after = table.find(tool.key());
                const std::optional<Tool> next = after ? std::optional(*after) : std::nullopt;
                if (!next || (row.value() && row.value()->tool == next))
                    break;
                const qint64 current = row.value() ? row.value()->version : 0;
                auto put = putRow(machine.key(), *units.value(), { tool.key(), next, current }, current,
                    row.value().has_value());
                if (!put)
                    return put.error();
                if (put.value())
                    break;
                if (attempt == kRaceRetries)
                    return Error {
                        tr("T%1 of %2 kept changing while it was written.").arg(tool.key()).arg(machine.key())
                    };
            }
        }
    }
    return {};
}

} // namespace Toffee
