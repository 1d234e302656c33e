// SPDX-License-Identifier: GPL-3.0-or-later
// A machine's setter repeatability, kept with the machine: {"tool": 3, "at": "…Z", "touches": [-80, …]}.
#include <cmath>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSqlQuery>
#include <QVariant>

#include "model/library/library.h"
#include "model/probing.h"

using namespace Qt::StringLiterals;

namespace Toffee {

double SetterRepeatability::spread() const
{
    return spreadOf(touches);
}

Result<void> Library::setRepeatability(const QString &machine, const SetterRepeatability &measured)
{
    if (auto writable = checkWritable(); !writable)
        return writable;
    if (measured.touches.size() < 2 || !touchesFromText(touchesText(measured.touches))
        || !measured.at.isValid())
        return Error { tr(
            "A setter's repeatability takes 2 to %1 touches, each a machine position, and a time.")
                           .arg(ProbeSettings::kMaxTouches) };
    QJsonArray touches;
    for (double z : measured.touches)
        touches.append(z);
    const QJsonObject o { { u"tool"_s, measured.tool },
        { u"at"_s, measured.at.toUTC().toString(Qt::ISODateWithMs) }, { u"touches"_s, touches } };
    QSqlQuery query(database());
    query.prepare(
        u"INSERT INTO machines (name, repeatability) VALUES (?, ?) ON CONFLICT (name) DO UPDATE SET "
        "repeatability = excluded.repeatability"_s);
    query.addBindValue(machine);
    query.addBindValue(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)));
    if (!query.exec())
        return failure(tr("Keeping %1's setter repeatability").arg(machine), query);
    return {};
}

Result<std::optional<SetterRepeatability>> Library::repeatability(const QString &machine) const
{
    QSqlQuery query(database());
    query.prepare(u"SELECT repeatability FROM machines WHERE name = ?"_s);
    query.addBindValue(machine);
    // A library from before repeatabilities, read as it is, has none.
    if (!query.exec() || !query.next() || query.value(0).toString().isEmpty())
        return std::optional<SetterRepeatability> {};
    const QJsonObject o = QJsonDocument::fromJson(query.value(0).toString().toUtf8()).object();
    SetterRepeatability r;
    r.tool = o.value(u"tool"_s).toInt(-1);
    r.at = QDateTime::fromString(o.value(u"at"_s).toString(), Qt::ISODateWithMs).toUTC();
    for (const QJsonValue &z : o.value(u"touches"_s).toArray())
        r.touches << z.toDouble(std::nan(""));
    // Another program's value that does not read is said, not guessed at.
    if (r.tool < 0 || !r.at.isValid() || r.touches.size() < 2 || !touchesFromText(touchesText(r.touches)))
        return Error { tr("%1's setter repeatability in the library does not read; measure it again "
                          "(toffee-cli measure-repeatability).")
                           .arg(machine) };
    return std::optional(r);
}

} // namespace Toffee
