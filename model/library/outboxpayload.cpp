// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/outboxpayload.h"

#include <cmath>

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "model/formats/jsonscanner.h"
#include "model/library/rowreader.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QJsonValue number(std::optional<double> value)
{
    return value ? QJsonValue(*value) : QJsonValue();
}

std::optional<double> numberFrom(const QJsonValue &value)
{
    return value.isDouble() ? std::optional(value.toDouble()) : std::nullopt;
}

Error unreadable()
{
    return Error { QCoreApplication::translate("Toffee::Library",
        "An outbox entry cannot be read; it is kept "
        "as it is.") };
}

} // namespace

QByteArray eventsPayload(const QList<HistoryEvent> &events)
{
    QJsonArray list;
    for (const HistoryEvent &e : events)
        list.append(QJsonObject { { u"id"_s, e.id }, { u"machine"_s, e.machine }, { u"tool"_s, e.tool },
            { u"at"_s, e.at.toUTC().toString(Qt::ISODateWithMs) }, { u"kind"_s, eventKindName(e.kind) },
            { u"tlo"_s, number(e.tlo) }, { u"reference_mz"_s, number(e.referenceMz) },
            { u"current_mz"_s, number(e.currentMz) }, { u"tolerance"_s, number(e.tolerance) },
            { u"old_tlo"_s, number(e.oldTlo) }, { u"new_tlo"_s, number(e.newTlo) },
            { u"failed"_s, e.failed ? QJsonValue(*e.failed) : QJsonValue() },
            { u"touches"_s, touchesText(e.touches) } });
    return QJsonDocument(list).toJson(QJsonDocument::Compact);
}

Result<QList<HistoryEvent>> eventsFromPayload(const QByteArray &payload)
{
    if (!hasNoDuplicateKeys(payload))
        return unreadable();
    const QJsonDocument doc = QJsonDocument::fromJson(payload);
    if (!doc.isArray())
        return unreadable();
    return eventsFromJson(doc.array());
}

Result<HistoryEvent> eventFromJson(const QJsonValue &value)
{
    if (!value.isObject())
        return unreadable();
    const QJsonObject o = value.toObject();
    HistoryEvent e;
    e.id = o.value(u"id"_s).toString();
    e.machine = o.value(u"machine"_s).toString();
    const double tool = o.value(u"tool"_s).toDouble(-1.5);
    e.tool = tool == std::floor(tool) && std::fabs(tool) < 2e9 ? int(tool) : -2;
    e.at = QDateTime::fromString(o.value(u"at"_s).toString(), Qt::ISODateWithMs).toUTC();
    const auto kind = eventKindFromName(o.value(u"kind"_s).toString());
    if (!kind)
        return unreadable();
    e.kind = *kind;
    e.tlo = numberFrom(o.value(u"tlo"_s));
    e.referenceMz = numberFrom(o.value(u"reference_mz"_s));
    e.currentMz = numberFrom(o.value(u"current_mz"_s));
    e.tolerance = numberFrom(o.value(u"tolerance"_s));
    e.oldTlo = numberFrom(o.value(u"old_tlo"_s));
    e.newTlo = numberFrom(o.value(u"new_tlo"_s));
    if (o.value(u"failed"_s).isBool())
        e.failed = o.value(u"failed"_s).toBool();
    // An older station's entry has no touches; a damaged one is refused.
    if (const QJsonValue touches = o.value(u"touches"_s); !touches.isUndefined()) {
        const auto read = touches.isString() ? touchesFromText(touches.toString()) : std::nullopt;
        if (!read)
            return unreadable();
        e.touches = *read;
    }
    // Held to what the history takes (validateEvent): an entry altered on the disk is refused, not sent.
    if (auto valid = validateEvent(e); !valid)
        return valid.error();
    return e;
}

Result<QList<HistoryEvent>> eventsFromJson(const QJsonArray &events)
{
    QList<HistoryEvent> out;
    for (const QJsonValue &v : events) {
        auto e = eventFromJson(v);
        if (!e)
            return e.error();
        out.append(e.takeValue());
    }
    return out;
}

bool hasNoDuplicateKeys(QByteArrayView json)
{
    // JsonScanner refuses an object with a key twice at any depth; QJsonDocument would keep the last.
    JsonScanner scanner(json);
    Scalar whole;
    return scanner.value(whole) && scanner.atEnd();
}

QByteArray toolsPayload(const ToolWrites &writes)
{
    QJsonArray list;
    for (const ToolWrite &w : writes.writes) {
        const auto data = [&writes](const std::optional<Tool> &tool) {
            return tool ? QJsonValue(QString::fromUtf8(toolData(*tool, writes.units))) : QJsonValue();
        };
        list.append(QJsonObject { { u"number"_s, w.number }, { u"base_version"_s, w.baseVersion },
            { u"tool"_s, data(w.tool) }, { u"base"_s, data(w.base) } });
    }
    return QJsonDocument(QJsonObject { { u"machine"_s, writes.machine },
                             { u"units"_s, unitsSymbol(writes.units) }, { u"writes"_s, list } })
        .toJson(QJsonDocument::Compact);
}

Result<ToolWrites> toolsFromPayload(const QByteArray &payload)
{
    if (!hasNoDuplicateKeys(payload))
        return unreadable();
    const QJsonObject o = QJsonDocument::fromJson(payload).object();
    const auto units = unitsFromSymbol(o.value(u"units"_s).toString());
    if (!units || o.value(u"machine"_s).toString().isEmpty())
        return unreadable();
    ToolWrites out { o.value(u"machine"_s).toString(), *units, {} };
    for (const QJsonValue &v : o.value(u"writes"_s).toArray()) {
        const QJsonObject w = v.toObject();
        ToolWrite write { w.value(u"number"_s).toInt(), std::nullopt,
            qint64(w.value(u"base_version"_s).toDouble()) };
        for (const auto &[key, into] :
            { std::pair(u"tool"_s, &write.tool), std::pair(u"base"_s, &write.base) }) {
            if (!w.value(key).isString())
                continue;
            auto tool = toolFromData(w.value(key).toString().toUtf8(), out.units);
            if (!tool)
                return unreadable();
            *into = tool.value();
        }
        out.writes.append(std::move(write));
    }
    return out;
}

} // namespace Toffee
