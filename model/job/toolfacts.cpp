// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/job/toolfacts.h"

#include <cmath>

#include "model/clock.h"
#include "model/library/library.h"
#include "model/numberformat.h"
#include "model/tooltable.h"
#include "model/translate.h"

namespace Toffee {

bool ToolFacts::isFresh(const QDateTime &now, int staleDays) const
{
    // A measurement from the future (a clock set wrong) is not fresh: nothing says when it was taken.
    if (!measuredAt.isValid() || Clock::isInFuture(measuredAt, now))
        return false;
    return measuredAt.secsTo(now) <= qint64(staleDays) * 24 * 3600;
}

Result<double> restorableTlo(int tool, const ToolFacts &facts, const QDateTime &now, int staleDays,
    std::optional<double> machineReferenceMz, ReferenceCheck check)
{
    if (!facts.inTable)
        return Error { tr("T%1 is not in the table: it is measured at its change.").arg(tool) };
    if (!facts.measuredTlo)
        return Error { tr("T%1 has no stored TLO: it is measured at its change.").arg(tool) };
    if (facts.source == TloSource::Manual)
        return Error {
            tr("T%1's TLO was set by hand, not measured: it is measured at its change.").arg(tool)
        };
    if (facts.source == TloSource::Pulled)
        return Error { tr(
            "T%1's TLO was read from the controller's table, not measured: it is measured at its change.")
                           .arg(tool) };
    if (facts.broken)
        return Error { tr("T%1 failed its last break test: it is measured at its change.").arg(tool) };
    if (Clock::isInFuture(facts.measuredAt, now))
        return Error { tr("T%1's stored TLO is dated %2, in the future: a clock was wrong, and when it was "
                          "measured is not known. It is measured at its change.")
                           .arg(tool)
                           .arg(facts.measuredAt.toUTC().toString(Qt::ISODate)) };
    if (!facts.isFresh(now, staleDays))
        return Error { tr(
            "T%1's stored TLO is older than the stale limit (%2 d): it is measured at its change.")
                           .arg(tool)
                           .arg(staleDays) };
    if (check == ReferenceCheck::Required && !machineReferenceMz)
        return Error { tr("the machine reports no reference (an uncalibrated reference of 0, or a firmware "
                          "that does not say), so T%1's stored TLO cannot be checked against it: it is "
                          "measured at its change.")
                           .arg(tool) };
    // A TLO is a difference to the reference it was measured against: without that reference nobody can
    // tell whether it still holds, at the machine or at a desk (the window's Restore refuses it too).
    if (!facts.referenceMz)
        return Error { tr("T%1's stored TLO does not say which reference it was measured against: it is "
                          "measured at its change.")
                           .arg(tool) };
    if (machineReferenceMz && facts.referenceMz
        && std::fabs(*facts.referenceMz - *machineReferenceMz) > facts.sameWithin)
        return Error { tr(
            "T%1's stored TLO was measured against reference MCS Z %2, but the machine's is %3: it "
            "is measured at its change.")
                           .arg(tool)
                           .arg(formatNumber(*facts.referenceMz, NumberFormat::command()),
                               formatNumber(*machineReferenceMz, NumberFormat::command())) };
    return *facts.measuredTlo;
}

QHash<int, ToolFacts> factsFromTable(const ToolTable &table)
{
    QHash<int, ToolFacts> facts;
    facts.reserve(table.size());
    for (const Tool &tool : table.tools()) {
        ToolFacts &f = facts[tool.number];
        f.inTable = true;
        // The TLO and its reference as the machine has them (millimetres), whatever the table's units.
        if (const auto stored = table.storedTlo(tool.number)) {
            f.measuredTlo = stored->tlo;
            f.referenceMz = stored->referenceMz;
            f.sameWithin = stored->sameWithin;
        }
        f.source = tool.tloSource;
        f.length = tool.totalLength();
        f.measuredAt = tool.measuredTlo ? tool.measuredAt : QDateTime();
        f.broken = tool.breakTestFailed;
        f.lifeLimitMinutes = tool.lifeLimitMinutes;
        f.lifeLimitUses = tool.lifeLimitUses;
        f.spreadLimit = table.probePlan(tool.number).spreadLimit;
    }
    return facts;
}

namespace {

// The newest event of these kinds for the tool, or nothing.
Result<std::optional<HistoryEvent>> newest(
    const Library &library, const QString &machine, int tool, const QList<EventKind> &kinds)
{
    HistoryQuery query;
    query.machine = machine;
    query.tool = tool;
    query.kinds = kinds;
    query.limit = 1;
    auto events = library.history(query);
    if (!events)
        return events.error();
    if (events.value().isEmpty())
        return std::optional<HistoryEvent>();
    return std::optional<HistoryEvent>(events.value().constLast());
}

} // namespace

Result<std::optional<double>> tloBeforeFailedBreakTest(
    const Library &library, const QString &machine, int tool)
{
    auto last = newest(library, machine, tool,
        { EventKind::Probe, EventKind::ManualSet, EventKind::NewCutter, EventKind::BreakTest });
    if (!last)
        return last.error();
    const std::optional<HistoryEvent> &event = last.value();
    if (!event || event->kind != EventKind::BreakTest || !event->failed.value_or(false))
        return std::optional<double>();
    return event->oldTlo;
}

std::function<Result<void>(QHash<int, ToolFacts> &, const QList<int> &)> libraryFacts(
    const Library *library, const QString &machine)
{
    if (!library)
        return {};
    return [library, machine](QHash<int, ToolFacts> &facts, const QList<int> &tools) {
        return addLibraryFacts(facts, *library, machine, tools);
    };
}

Result<void> addLibraryFacts(
    QHash<int, ToolFacts> &facts, const Library &library, const QString &machine, const QList<int> &tools)
{
    for (int tool : tools) {
        auto measured = newest(
            library, machine, tool, { EventKind::Probe, EventKind::ManualSet, EventKind::NewCutter });
        if (!measured)
            return measured.error();
        auto tested = newest(library, machine, tool, { EventKind::BreakTest });
        if (!tested)
            return tested.error();
        // A new cutter ends what the history knew of the old one: its TLO and its break tests. A TLO the
        // table still holds from before it is the old cutter's, and said so (the job check warns).
        if (measured.value() && measured.value()->kind == EventKind::NewCutter) {
            const QDateTime changed = measured.value()->at;
            if (tested.value() && tested.value()->at <= changed)
                tested.value().reset();
            measured.value().reset();
            if (const auto it = facts.find(tool); it != facts.end() && it->measuredTlo
                && !(it->measuredAt.isValid() && it->measuredAt > changed))
                it->newCutterAt = changed;
        }
        if (const auto it = facts.find(tool);
            it != facts.end() && (it->lifeLimitMinutes || it->lifeLimitUses)) {
            auto used = library.usedLife(machine, tool);
            if (!used)
                return used.error();
            it->used = used.value().value(tool);
        }
        if (!measured.value() && !tested.value())
            continue; // nothing to add: no entry made for it
        ToolFacts &f = facts[tool];
        if (const auto &m = measured.value(); m && m->tlo) {
            const bool sameTlo = f.measuredTlo && std::fabs(*f.measuredTlo - *m->tlo) <= f.sameWithin;
            if (!f.inTable) {
                f.measuredTlo = m->tlo;
                f.measuredAt = m->at;
                f.source = m->kind == EventKind::ManualSet ? TloSource::Manual
                    : m->kind == EventKind::Import         ? TloSource::Pulled
                                                           : TloSource::Probe;
                f.referenceMz = m->referenceMz;
            } else if (sameTlo && !f.measuredAt.isValid()) {
                f.measuredAt = m->at;
            } else if (!sameTlo && (!f.measuredAt.isValid() || m->at > f.measuredAt)) {
                f.libraryTlo = m->tlo;
                f.libraryMeasuredAt = m->at;
            }
        }
        const auto &m = measured.value();
        const auto &t = tested.value();
        // The newest touches on each edge: a probe's, or a later break test's.
        const HistoryEvent *newestMeasured = t && (!m || t->at > m->at) ? &*t : m ? &*m : nullptr;
        if (newestMeasured)
            f.lastSpread = newestMeasured->spread();
        if (!t || !t->failed.value_or(false))
            continue;
        // Only a probe clears a failed break test (an offset set by hand does not: the tool was not
        // measured).
        const bool probedSince = (m && m->kind == EventKind::Probe && m->at > t->at)
            || (f.inTable && f.source == TloSource::Probe && f.measuredAt.isValid() && f.measuredAt > t->at);
        if (!probedSince)
            f.broken = true;
    }
    return {};
}

} // namespace Toffee
