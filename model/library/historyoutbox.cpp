// SPDX-License-Identifier: GPL-3.0-or-later
// The outbox of a station whose shared library is out of reach: kept in its own SQLite library, written back
// in the order it was made when the server returns.
#include "model/library/historyrecorder.h"

using namespace Qt::StringLiterals;

namespace Toffee {

Result<void> HistoryRecorder::keepInOutbox(const QString &kind, const QByteArray &payload)
{
    if (!m_outbox) {
        auto opened = Library::open(outboxLocation());
        if (!opened)
            return opened.error();
        m_outbox = opened.takeValue();
    }
    if (auto added = m_outbox->outboxAdd(
            { HistoryEvent::newId(), m_location.text(), kind, payload, QDateTime::currentDateTimeUtc() });
        !added)
        return added;
    countOutbox();
    return {};
}

void HistoryRecorder::countOutbox()
{
    const qsizetype before = m_outboxCount;
    m_outboxCount = 0;
    if (m_location.isShared()) {
        if (!m_outbox) {
            if (auto opened = Library::open(outboxLocation()))
                m_outbox = opened.takeValue();
        }
        if (m_outbox) {
            if (auto entries = m_outbox->outbox(m_location.text()))
                m_outboxCount = entries.value().size();
        }
    }
    if (m_outboxCount != before)
        Q_EMIT pendingChanged(pendingCount());
}

// Each entry is removed once written. A crash in between writes it again: its events are skipped by their
// ids, and its tools are found already so.
Result<void> HistoryRecorder::replayOutbox()
{
    auto entries = m_outbox->outbox(m_location.text());
    if (!entries)
        return entries.error();
    for (const OutboxEntry &entry : entries.value()) {
        if (entry.kind == u"events"_s) {
            auto events = eventsFromPayload(entry.payload);
            if (!events)
                return events.error();
            if (auto written = m_library->append(events.value()); !written)
                return written.error();
            if (auto removed = m_outbox->outboxRemove(entry.id); !removed)
                return removed;
            Q_EMIT recorded(events.value());
        } else {
            auto writes = toolsFromPayload(entry.payload);
            if (!writes)
                return writes.error();
            auto written = m_library->writeTools(writes.value().machine, writes.value().writes);
            if (!written)
                return written.error();
            if (auto removed = m_outbox->outboxRemove(entry.id); !removed)
                return removed;
            Q_EMIT replayed(writes.value().machine, written.value());
        }
        countOutbox();
    }
    countOutbox(); // another recorder on the same outbox may have sent what this one counted
    return {};
}

} // namespace Toffee
