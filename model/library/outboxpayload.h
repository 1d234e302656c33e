// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QList>

class QJsonArray;
class QJsonValue;

#include "model/library/historyevent.h"
#include "model/library/storedtable.h"

namespace Toffee {

// What an outbox entry carries, as JSON: measurement events with their ids, or one machine table's tool
// writes with the versions they were made over. Read back whole or refused.
[[nodiscard]] QByteArray eventsPayload(const QList<HistoryEvent> &events);
[[nodiscard]] Result<QList<HistoryEvent>> eventsFromPayload(const QByteArray &payload);
[[nodiscard]] Result<QList<HistoryEvent>> eventsFromJson(const QJsonArray &events);
// One event of such a list, held to what the history takes (validateEvent).
[[nodiscard]] Result<HistoryEvent> eventFromJson(const QJsonValue &event);
// True when no JSON object in `json` has a key twice (and it is JSON at all): what Toffee reads is refused
// rather than read as whichever of two values a parser keeps.
[[nodiscard]] bool hasNoDuplicateKeys(QByteArrayView json);

struct ToolWrites
{
    QString machine;
    Units units = Units::Millimetre;
    QList<ToolWrite> writes;
};
[[nodiscard]] QByteArray toolsPayload(const ToolWrites &writes);
[[nodiscard]] Result<ToolWrites> toolsFromPayload(const QByteArray &payload);

} // namespace Toffee
