// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/outbox.h"

#include "model/clock.h"

using namespace Qt::StringLiterals;

namespace Toffee::Outbox {

Result<void> keep(
    Library &outbox, const LibraryLocation &target, const QString &kind, const QByteArray &payload)
{
    return outbox.outboxAdd({ HistoryEvent::newId(), target.text(), kind, payload, Clock::now() });
}

Result<qsizetype> count(const Library &outbox, const LibraryLocation &target)
{
    auto entries = outbox.outbox(target.text());
    if (!entries)
        return entries.error();
    return entries.value().size();
}

Result<void> send(Library &outbox, Library &target,
    const std::function<void(const QList<HistoryEvent> &)> &events,
    const std::function<void(const QString &, const WriteOutcome &)> &tools)
{
    auto entries = outbox.outbox(target.location().text());
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
