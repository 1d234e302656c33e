// SPDX-License-Identifier: GPL-3.0-or-later
// Reading and writing a library: machines, events, tool use.
#include "model/library/library.h"

#include "model/clock.h"
#include "model/library/rowreader.h"
#include "model/limits.h"
#include "model/tooltable.h"

#include <QAtomicInt>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSqlDatabase>
#include <QSqlDriver>
#include <QSqlError>
#include <QSqlQuery>
#include <QVariant>

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

const QString kEventColumns = u"id, machine, tool, measured_at, kind, tlo, reference_mz, current_mz, "
                              u"tolerance, old_tlo, new_tlo, failed, "
                              u"touches, spread"_s;

QString timeText(const QDateTime &at)
{
    return at.toUTC().toString(Qt::ISODateWithMs);
}

QVariant nullable(std::optional<double> value)
{
    return value ? QVariant(*value) : QVariant(QMetaType::fromType<double>());
}

} // namespace

Result<void> Library::addMachine(const MachineRecord &machine)
{
    if (auto writable = checkWritable(); !writable)
        return writable;
    // Known as it is: nothing to write, so no write lock to wait for while another program holds one.
    {
        QSqlQuery known(database());
        known.prepare(u"SELECT dialect, connection FROM machines WHERE name = ?"_s);
        known.addBindValue(machine.name);
        if (known.exec() && known.next() && known.value(0).toString() == machine.dialect
            && known.value(1).toString() == machine.connection)
            return {};
    }
    QSqlQuery query(database());
    query.prepare(u"INSERT INTO machines (name, dialect, connection) VALUES (?, ?, ?) ON CONFLICT (name) DO "
                  "UPDATE SET dialect = excluded.dialect, connection = excluded.connection"_s);
    query.addBindValue(machine.name);
    query.addBindValue(machine.dialect);
    query.addBindValue(machine.connection);
    if (!query.exec())
        return failure(tr("Adding the machine %1").arg(machine.name), query);
    return {};
}

Result<QList<MachineRecord>> Library::machines() const
{
    QSqlQuery query(database());
    if (!query.exec(u"SELECT name, dialect, connection FROM machines ORDER BY name"_s))
        return failure(tr("Reading the machines"), query);
    QList<MachineRecord> out;
    while (query.next())
        out.append({ query.value(0).toString(), query.value(1).toString(), query.value(2).toString() });
    return out;
}

Result<void> Library::setToolSetter(const QString &machine, const ToolSetter &setter)
{
    if (auto writable = checkWritable(); !writable)
        return writable;
    if (auto valid = setter.validate(); !valid)
        return valid;
    QSqlQuery query(database());
    query.prepare(
        u"INSERT INTO machines (name, setter) VALUES (?, ?) ON CONFLICT (name) DO UPDATE SET setter = "
        "excluded.setter"_s);
    query.addBindValue(machine);
    query.addBindValue(setter.text());
    if (!query.exec())
        return failure(tr("Keeping %1's tool setter").arg(machine), query);
    return {};
}

Result<std::optional<ToolSetter>> Library::toolSetter(const QString &machine) const
{
    QSqlQuery query(database());
    query.prepare(u"SELECT setter FROM machines WHERE name = ?"_s);
    query.addBindValue(machine);
    if (!query.exec())
        return failure(tr("Reading %1's tool setter").arg(machine), query);
    if (!query.next() || query.value(0).toString().isEmpty())
        return std::optional<ToolSetter> {};
    // A value another program wrote that does not read is no setter: the operator sets it again.
    auto setter = ToolSetter::parse(query.value(0).toString());
    if (!setter)
        return Error { tr(
            "%1's tool setter in the library (\"%2\") does not read: %3 Set it again (Machine ▸ "
            "Tool Setter…).")
                           .arg(machine, query.value(0).toString(), setter.error().message) };
    return std::optional<ToolSetter>(setter.value());
}

Result<Library::MachineBinding> Library::bindMachine(
    const QString &machine, const QString &identity, bool rebind)
{
    QString bound;
    {
        QSqlQuery query(database());
        query.prepare(u"SELECT identity FROM machines WHERE name = ?"_s);
        query.addBindValue(machine);
        // A library older than identities, read-only here, has no such column: nothing is bound in it.
        if (query.exec() && query.next())
            bound = query.value(0).toString();
        else if (query.lastError().isValid() && !isReadOnly())
            return failure(tr("Reading which machine %1 is").arg(machine), query);
    }
    if (bound == identity)
        return MachineBinding { MachineBinding::Kind::Same, {} };
    if (!bound.isEmpty() && !rebind)
        return MachineBinding { MachineBinding::Kind::Other, bound };
    const MachineBinding result { bound.isEmpty() ? MachineBinding::Kind::New : MachineBinding::Kind::Same,
        {} };
    if (isReadOnly())
        return result;
    QSqlQuery query(database());
    query.prepare(u"INSERT INTO machines (name, identity) VALUES (?, ?) ON CONFLICT (name) DO UPDATE SET "
                  "identity = excluded.identity"_s);
    query.addBindValue(machine);
    query.addBindValue(identity);
    if (!query.exec())
        return failure(tr("Keeping which machine %1 is").arg(machine), query);
    return result;
}

Result<void> Library::ensureMachines(const QStringList &names)
{
    QSqlQuery query(database());
    query.prepare(u"INSERT INTO machines (name) VALUES (?) ON CONFLICT (name) DO NOTHING"_s);
    for (const QString &name : names) {
        query.addBindValue(name);
        if (!query.exec())
            return failure(tr("Adding the machine %1").arg(name), query);
    }
    return {};
}

// The rows of one batch, in one transaction with their machines: all of them or none.
Result<int> Library::insertAll(const QString &sql, const QStringList &machines, qsizetype count,
    const std::function<QString(QSqlQuery &, qsizetype)> &bind,
    const std::function<Result<void>(const QList<qsizetype> &)> &after)
{
    if (auto begun = beginWrite(); !begun)
        return begun.error();
    auto fail = [this](const Error &error) {
        rollback();
        return error;
    };
    if (auto added = ensureMachines(machines); !added)
        return fail(added.error());
    QSqlQuery query(database());
    query.prepare(sql);
    QList<qsizetype> inserted;
    for (qsizetype i = 0; i < count; ++i) {
        const QString what = bind(query, i);
        if (!query.exec())
            return fail(failure(what, query));
        if (query.numRowsAffected() > 0)
            inserted.append(i);
    }
    if (auto done = after(inserted); !done)
        return fail(done.error());
    if (!inserted.isEmpty()) {
        if (auto said = announce(machines); !said)
            return fail(said.error());
    }
    if (auto done = commit(); !done)
        return done.error();
    return int(inserted.size());
}

Result<int> Library::append(const QList<HistoryEvent> &events)
{
    if (events.isEmpty())
        return 0;
    for (const HistoryEvent &e : events) {
        if (auto valid = validateEvent(e); !valid)
            return Error { valid.error().message + u' ' + tr("Nothing of this batch was recorded.") };
    }
    QStringList machines;
    for (const HistoryEvent &e : events) {
        if (!machines.contains(e.machine))
            machines.append(e.machine);
    }
    const QString sql = u"INSERT INTO events ("_s + kEventColumns
        + u") VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?) ON CONFLICT (id) DO NOTHING"_s;
    return insertAll(
        sql, machines, events.size(),
        [&events](QSqlQuery &query, qsizetype i) {
            const HistoryEvent &e = events.at(i);
            query.addBindValue(e.id);
            query.addBindValue(e.machine);
            query.addBindValue(e.tool);
            query.addBindValue(timeText(e.at));
            query.addBindValue(eventKindName(e.kind));
            for (const auto &value : { e.tlo, e.referenceMz, e.currentMz, e.tolerance, e.oldTlo, e.newTlo })
                query.addBindValue(nullable(value));
            query.addBindValue(e.failed ? QVariant(int(*e.failed)) : QVariant(QMetaType::fromType<int>()));
            query.addBindValue(touchesText(e.touches));
            query.addBindValue(nullable(e.spread()));
            return tr("Recording T%1's %2").arg(e.tool).arg(eventKindName(e.kind));
        },
        [this, &events](const QList<qsizetype> &inserted) {
            QList<HistoryEvent> fresh;
            for (qsizetype i : inserted)
                fresh.append(events.at(i));
            return applyToTables(fresh);
        });
}

Result<int> Library::appendUse(const QList<ToolUse> &uses)
{
    if (uses.isEmpty())
        return 0;
    QStringList machines;
    for (const ToolUse &u : uses) {
        if (!machines.contains(u.machine))
            machines.append(u.machine);
    }
    const QString sql = u"INSERT INTO tool_use (id, machine, tool, recorded_at, program, cutting_seconds, "
                        "feed_path_mm) VALUES (?, ?, ?, ?, ?, ?, ?) ON CONFLICT (id) DO NOTHING"_s;
    return insertAll(
        sql, machines, uses.size(),
        [&uses](QSqlQuery &query, qsizetype i) {
            const ToolUse &u = uses.at(i);
            for (const QVariant &v :
                { QVariant(u.id), QVariant(u.machine), QVariant(u.tool), QVariant(timeText(u.at)),
                    QVariant(u.program), QVariant(u.cuttingSeconds), QVariant(u.feedPathMm) })
                query.addBindValue(v);
            return tr("Recording T%1's use").arg(u.tool);
        },
        [](const QList<qsizetype> &) { return Result<void>(); });
}

Result<QList<HistoryEvent>> Library::history(const HistoryQuery &q, QStringList *unreadable) const
{
    QStringList where;
    QVariantList values;
    if (!q.machine.isEmpty()) {
        where << u"machine = ?"_s;
        values << q.machine;
    }
    if (q.tool) {
        where << u"tool = ?"_s;
        values << *q.tool;
    }
    if (q.since.isValid()) {
        where << u"measured_at >= ?"_s;
        values << timeText(q.since);
    }
    if (!q.kinds.isEmpty()) {
        QStringList marks;
        for (EventKind kind : q.kinds) {
            marks << u"?"_s;
            values << eventKindName(kind);
        }
        where << u"kind IN ("_s + marks.join(u", "_s) + u")"_s;
    }
    // A library read as it is (read-only, not brought up to date) may be from before touches were kept.
    const auto version = schemaVersion();
    const bool touchesKept = !version || version.value() >= kTouchesVersion;
    QString sql = u"SELECT "_s
        + (touchesKept ? kEventColumns : QString(kEventColumns).replace(u"touches, spread"_s, u"'', NULL"_s))
        + u" FROM events"_s;
    if (!where.isEmpty())
        sql += u" WHERE "_s + where.join(u" AND "_s);
    // The newest `limit`, read newest first and turned round.
    sql += q.limit > 0 ? u" ORDER BY measured_at DESC, id DESC LIMIT ?"_s : u" ORDER BY measured_at, id"_s;
    if (q.limit > 0)
        values << q.limit;
    QSqlQuery query(database());
    query.setForwardOnly(true);
    query.prepare(sql);
    for (const QVariant &v : values)
        query.addBindValue(v);
    if (!query.exec())
        return failure(tr("Reading the history"), query);
    QList<HistoryEvent> out;
    while (query.next()) {
        QVariantList row;
        for (int i = 0; i < RowReader::kEventColumns; ++i)
            row.append(query.value(i));
        auto e = RowReader::event(row);
        if (!e) {
            // One row written wrong (by another program, by hand) is named and left out; the rest is read.
            if (unreadable && unreadable->size() < kMaxUnreadableNamed)
                unreadable->append(e.error().message);
            continue;
        }
        out.append(e.takeValue());
    }
    if (q.limit > 0)
        std::reverse(out.begin(), out.end());
    return out;
}

Result<QList<ToolUse>> Library::uses(const QString &machine, std::optional<int> tool) const
{
    QString sql
        = u"SELECT id, machine, tool, recorded_at, program, cutting_seconds, feed_path_mm FROM tool_use "
          "WHERE machine = ?"_s;
    if (tool)
        sql += u" AND tool = ?"_s;
    sql += u" ORDER BY recorded_at, id"_s;
    QSqlQuery query(database());
    query.setForwardOnly(true);
    query.prepare(sql);
    query.addBindValue(machine);
    if (tool)
        query.addBindValue(*tool);
    if (!query.exec())
        return failure(tr("Reading the tools' use"), query);
    QList<ToolUse> out;
    while (query.next()) {
        QVariantList row;
        for (int i = 0; i < 7; ++i)
            row.append(query.value(i));
        if (auto use = RowReader::use(row))
            out.append(use.takeValue());
    }
    return out;
}

Result<QHash<int, UsedLife>> Library::usedLife(const QString &machine, std::optional<int> tool) const
{
    QSqlQuery query(database());
    query.setForwardOnly(true);
    // Only times a program could take (text, infinities and NaN sort above 1e9 in both databases); only the
    // runs after the tool's newest new cutter (times are ISO 8601 UTC text, which sorts as time does), and
    // never one dated in the future (a clock set wrong), which would hide every real run before it.
    query.prepare(u"SELECT u.tool, SUM(u.cutting_seconds), COUNT(*) FROM tool_use u WHERE u.machine = ? "
                  "AND u.cutting_seconds >= 0 AND u.cutting_seconds <= 1e9"_s
        + (tool ? u" AND u.tool = ?"_s : QString())
        + u" AND u.recorded_at > COALESCE((SELECT MAX(e.measured_at) FROM events e WHERE e.machine = "
          "u.machine AND e.tool = u.tool AND e.kind = 'new_cutter' AND e.measured_at <= ?), '') "
          "GROUP BY u.tool"_s);
    query.addBindValue(machine);
    if (tool)
        query.addBindValue(*tool);
    query.addBindValue(timeText(Clock::now().addSecs(Clock::kMaxSkewSeconds)));
    if (!query.exec())
        return failure(tr("Reading the tools' use"), query);
    QHash<int, UsedLife> out;
    while (query.next()) {
        // A sum over rows someone else wrote: a tool or a total that is not one is left out.
        const auto number = RowReader::wholeNumber(query.value(0));
        const auto seconds = RowReader::finiteNumber(query.value(1));
        const auto uses = RowReader::wholeNumber(query.value(2));
        if (number && *number >= Limits::kMinToolNumber && *number <= Limits::kMaxToolNumber && seconds
            && *seconds >= 0 && uses && *uses >= 0)
            out.insert(int(*number), UsedLife { *seconds, int(std::min<qint64>(*uses, INT_MAX)) });
    }
    return out;
}

std::optional<double> keptReferenceMz(const Library *library, const QString &machine, const ToolTable &table)
{
    if (library) {
        HistoryQuery query;
        query.machine = machine;
        query.kinds = { EventKind::Probe };
        query.limit = 50; // the newest: every probe carries its reference
        if (const auto events = library->history(query)) {
            for (auto it = events.value().crbegin(); it != events.value().crend(); ++it) {
                if (it->referenceMz)
                    return it->referenceMz;
            }
        }
    }
    const Tool *newest = nullptr;
    for (const Tool &tool : table.tools()) {
        if (tool.referenceMz && tool.measuredAt.isValid()
            && (!newest || tool.measuredAt > newest->measuredAt))
            newest = &tool;
    }
    if (!newest)
        return std::nullopt;
    return table.storedTlo(newest->number)->referenceMz; // in millimetres, as the machine has it
}

} // namespace Toffee
