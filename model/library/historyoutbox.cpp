// SPDX-License-Identifier: GPL-3.0-or-later
// The outbox of a station whose shared library is out of reach (outbox.h), as the window's recorder keeps it.
#include "model/library/historyrecorder.h"
#include "model/library/outbox.h"

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
    if (auto kept = Outbox::keep(*m_outbox, m_location, kind, payload); !kept)
        return kept;
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
            if (auto counted = Outbox::count(*m_outbox, m_location))
                m_outboxCount = counted.value();
        }
    }
    if (m_outboxCount != before)
        Q_EMIT pendingChanged(pendingCount());
}

Result<void> HistoryRecorder::replayOutbox()
{
    auto sent = Outbox::send(
        *m_outbox, *m_library,
        [this](const QList<HistoryEvent> &events) {
            countOutbox();
            Q_EMIT recorded(events);
        },
        [this](const QString &machine, const WriteOutcome &outcome) {
            countOutbox();
            Q_EMIT replayed(machine, outcome);
        });
    countOutbox(); // another recorder on the same outbox may have sent what this one counted
    return sent;
}

} // namespace Toffee
