// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/outbox.h"

#include <algorithm>

#include "model/clock.h"

using namespace Qt::StringLiterals;

namespace Toffee::Outbox {

Result<void> keep(
    Library &outbox, const LibraryLocation &target, const QString &kind, const QByteArray &payload)
{
    return outbox.outboxAdd({ HistoryEvent::newId(), target.identity(), kind, payload, Clock::now() });
}

namespace {

// What waits for `target`: kept under its identity, or under its text by an older Toffee.
Result<QList<OutboxEntry>> entriesFor(const Library &outbox, const LibraryLocation &target)
{
    auto entries = outbox.outbox(target.identity());
    if (!entries || target.identity() == target.text())
        return entries;
    auto older = outbox.outbox(target.text());
    if (!older)
        return older.error();
    QList<OutboxEntry> all = older.takeValue() + entries.takeValue();
    std::stable_sort(
        all.begin(), all.end(), [](const OutboxEntry &a, const OutboxEntry &b) { return a.at < b.at; });
    return all;
}

} // namespace

Result<qsizetype> count(const Library &outbox, const LibraryLocation &target)
{
    auto entries = entriesFor(outbox, target);
    if (!entries)
        return entries.error();
    return entries.value().size();
}

Result<void> send(Library &outbox, Library &target,
    const std::function<void(const QList<HistoryEvent> &)> &events,
    const std::function<void(const QString &, const WriteOutcome &)> &tools)
{
    auto entries = entriesFor(outbox, target.location());
    if (!entries)
        return entries.error();
    for (const OutboxEntry &entry : entries.value()) {
        if (entry.kind == u"events"_s) {
            auto read = eventsFromPayload(entry.payload);
            if (!read)
                return read.error();
            if (auto written = target.append(read.value()); !written)
                return written.error();
            if (auto removed = outbox.outboxRemove(entry.id); !removed)
                return removed;
            events(read.value());
        } else {
            auto writes = toolsFromPayload(entry.payload);
            if (!writes)
                return writes.error();
            auto written = target.writeTools(writes.value().machine, writes.value().writes);
            if (!written)
                return written.error();
            if (auto removed = outbox.outboxRemove(entry.id); !removed)
                return removed;
            tools(writes.value().machine, written.value());
        }
    }
    return {};
}

} // namespace Toffee::Outbox
