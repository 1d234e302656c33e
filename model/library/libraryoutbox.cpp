// SPDX-License-Identifier: GPL-3.0-or-later
// A station's outbox, in its own SQLite library: what waits for a shared library it cannot reach.
#include <QSqlQuery>
#include <QVariant>

#include "model/library/library.h"

using namespace Qt::StringLiterals;

namespace Toffee {

Result<void> Library::outboxAdd(const OutboxEntry &entry)
{
    QSqlQuery query(database());
    query.prepare(u"INSERT INTO outbox (id, library, kind, payload, created_at) VALUES (?, ?, ?, ?, ?) ON "
                  "CONFLICT (id) DO NOTHING"_s);
    for (const QVariant &v : { QVariant(entry.id), QVariant(entry.library), QVariant(entry.kind),
             QVariant(QString::fromUtf8(entry.payload)),
             QVariant(entry.at.toUTC().toString(Qt::ISODateWithMs)) })
        query.addBindValue(v);
    if (!query.exec())
        return failure(tr("Keeping a change for later"), query);
    return {};
}

Result<QList<OutboxEntry>> Library::outbox(const QString &library) const
{
    QSqlQuery query(database());
    query.setForwardOnly(true);
    query.prepare(u"SELECT id, library, kind, payload, created_at FROM outbox WHERE library = ? ORDER BY "
                  "created_at, id"_s);
    query.addBindValue(library);
    if (!query.exec())
        return failure(tr("Reading the changes kept for later"), query);
    QList<OutboxEntry> out;
    while (query.next())
        out.append({ query.value(0).toString(), query.value(1).toString(), query.value(2).toString(),
            query.value(3).toString().toUtf8(),
            QDateTime::fromString(query.value(4).toString(), Qt::ISODateWithMs) });
    return out;
}

Result<void> Library::outboxRemove(const QString &id)
{
    QSqlQuery query(database());
    query.prepare(u"DELETE FROM outbox WHERE id = ?"_s);
    query.addBindValue(id);
    if (!query.exec())
        return failure(tr("Clearing a change written"), query);
    return {};
}

} // namespace Toffee
