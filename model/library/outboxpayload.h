// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QList>

#include "model/library/historyevent.h"
#include "model/library/storedtable.h"

namespace Toffee {

// What an outbox entry carries, as JSON: measurement events with their ids, or one machine table's tool
// writes with the versions they were made over. Read back whole or refused.
[[nodiscard]] QByteArray eventsPayload(const QList<HistoryEvent> &events);
[[nodiscard]] Result<QList<HistoryEvent>> eventsFromPayload(const QByteArray &payload);

struct ToolWrites
{
    QString machine;
    Units units = Units::Millimetre;
    QList<ToolWrite> writes;
};
[[nodiscard]] QByteArray toolsPayload(const ToolWrites &writes);
[[nodiscard]] Result<ToolWrites> toolsFromPayload(const QByteArray &payload);

} // namespace Toffee
