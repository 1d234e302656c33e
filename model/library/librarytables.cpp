// SPDX-License-Identifier: GPL-3.0-or-later
// Machine tables in the library: read, created, written tool by tool against each row's version, and kept up
// to date by every new measurement event.
#include <QMap>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QSysInfo>
#include <QVariant>

#include "model/clock.h"
#include "model/library/library.h"
#include "model/library/rowreader.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QString timeText(const QDateTime &at)
{
    return at.toUTC().toString(Qt::ISODateWithMs);
}

// The columns RowReader::ToolRow reads, the data only when it is not longer than the bound bound to the first
// "?" (a row of 100 MB is never fetched), and its length.
const QString kToolRowColumns = u"number, version, deleted, CASE WHEN length(data) <= ? THEN data END, "
                                "length(data), updated_by, updated_at"_s;

RowReader::ToolRow toolRow(const QSqlQuery &query, int first)
{
    return { query.value(first), query.value(first + 1), query.value(first + 2), query.value(first + 3),
        query.value(first + 4), query.value(first + 5), query.value(first + 6) };
}

QVariant tloOf(const std::optional<Tool> &tool)
{
    return tool && tool->measuredTlo ? QVariant(*tool->measuredTlo) : QVariant(QMetaType::fromType<double>());
}

} // namespace

QString Library::station() const
{
    return m_options.station.isEmpty() ? QSysInfo::machineHostName() : m_options.station;
}

QSqlDriver *Library::driver() const
{
    return database().driver();
}

bool Library::isConnectionLost() const
{
    QSqlQuery probe(database());
    return !probe.exec(u"SELECT 1"_s);
}

Result<void> Library::checkWritable() const
{
    return checkWritableFor(m_readOnly);
}

Result<void> Library::checkWritableFor(bool readOnly) const
{
    if (!readOnly)
        return {};
    return Error { m_location.isShared()
            ? tr("The library (%1) is read-only for %2: this role may read the tools but not change them. "
                 "Ask whoever runs the server for write rights (docs/LIBRARY.md).")
                  .arg(m_location.displayName(), m_location.user.isEmpty() ? tr("you") : m_location.user)
            : tr("%1 is read-only: it cannot be written.").arg(m_location.path) };
}

Result<void> Library::announce(const QStringList &machines)
{
    if (!m_location.isShared())
        return {}; // SQLite readers see the file's data_version change (LibraryWatcher)
    QSqlQuery query(database());
    query.prepare(u"SELECT pg_notify(?, ?)"_s);
    // "machine<TAB>station<TAB>ms since the epoch": who changed which machine's table, and when it was said.
    const QString tail = u'\t' + station() + u'\t' + QString::number(Clock::now().toMSecsSinceEpoch());
    for (const QString &machine : machines) {
        query.addBindValue(QString(kChannel));
        query.addBindValue(QString(machine + tail));
        if (!query.exec())
            return failure(tr("Announcing the change"), query);
    }
    return {};
}

Result<QStringList> Library::tableMachines() const
{
    QSqlQuery query(database());
    if (!query.exec(u"SELECT machine FROM machine_tables ORDER BY machine"_s))
        return failure(tr("Reading the machine tables"), query);
    QStringList out;
    while (query.next())
        out << query.value(0).toString();
    return out;
}

Result<std::optional<Units>> Library::tableUnits(const QString &machine) const
{
    QSqlQuery query(database());
    query.prepare(u"SELECT units FROM machine_tables WHERE machine = ?"_s);
    query.addBindValue(machine);
    if (!query.exec())
        return failure(tr("Reading %1's table").arg(machine), query);
    if (!query.next())
        return std::optional<Units>();
    const auto units = query.value(0).isNull() ? std::nullopt : unitsFromSymbol(query.value(0).toString());
    if (!units)
        return Error { tr(
            "%1: %2's table says its units are %3, neither mm nor in; it was written by another "
            "program or by hand, and is not opened.")
                           .arg(m_location.displayName(), machine, RowReader::shown(query.value(0))) };
    return std::optional(*units);
}

Result<StoredTable> Library::readTable(const QString &machine) const
{
    auto units = tableUnits(machine);
    if (!units)
        return units.error();
    if (!units.value())
        return Error { tr("The library has no tool table for %1.").arg(machine) };
    StoredTable out { machine, *units.value(), {} };
    QSqlQuery query(database());
    query.setForwardOnly(true);
    query.prepare(u"SELECT "_s + kToolRowColumns + u" FROM tools WHERE machine = ? ORDER BY number"_s);
    query.addBindValue(RowReader::kMaxToolDataChars);
    query.addBindValue(machine);
    if (!query.exec())
        return failure(tr("Reading %1's table").arg(machine), query);
    // Every row is read and checked: a table with one wrong row is not opened, and the message names each
    // wrong row, not only the first.
    QStringList unreadable;
    qsizetype moreUnreadable = 0;
    while (query.next()) {
        auto row = RowReader::tool(toolRow(query, 0), out.units);
        if (!row) {
            if (unreadable.size() < kMaxUnreadableNamed)
                unreadable << row.error().message;
            else
                ++moreUnreadable;
            continue;
        }
        out.rows.append(row.takeValue());
    }
    if (!unreadable.isEmpty()) {
        QString list = unreadable.join(u"; "_s);
        if (moreUnreadable > 0)
            list += u"; "_s + tr("and %1 more").arg(moreUnreadable);
        return Error { tr("%1: %2's table has rows Toffee cannot read, so it is not opened and nothing was "
                          "written: %3. They were written by another program or by hand; put the table back "
                          "from a backup, or have whoever changed them correct them (docs/LIBRARY.md).")
                           .arg(m_location.displayName(), machine, list),
            0 };
    }
    return out;
}

Result<std::optional<StoredTool>> Library::readRow(const QString &machine, int number) const
{
    QSqlQuery query(database());
    // Read to be written, inside the writer's transaction: on PostgreSQL the row is locked until the commit,
    // so the version read is still the row's when it is written (without the lock, stations saving the same
    // tool at full speed could keep overtaking each other). SQLite's IMMEDIATE transaction already excludes
    // every other writer.
    const QString lock = m_location.isShared() ? u" FOR UPDATE OF tools"_s : QString();
    query.prepare(u"SELECT "_s + kToolRowColumns
        + u", units FROM tools JOIN machine_tables USING (machine) WHERE machine = ? AND number = ?"_s
        + lock);
    query.addBindValue(RowReader::kMaxToolDataChars);
    query.addBindValue(machine);
    query.addBindValue(number);
    if (!query.exec())
        return failure(tr("Reading T%1 of %2").arg(number).arg(machine), query);
    if (!query.next())
        return std::optional<StoredTool>();
    const auto units = unitsFromSymbol(query.value(7).toString());
    if (!units)
        return Error { tr("%1: %2's table has units %3, neither mm nor in.")
                           .arg(m_location.displayName(), machine, RowReader::shown(query.value(7))) };
    auto row = RowReader::tool(toolRow(query, 0), *units);
    if (!row)
        return Error { tr("%1: %2's %3. Nothing was written to it.")
                           .arg(m_location.displayName(), machine, row.error().message) };
    return std::optional(row.takeValue());
}

// True when the row was written; false when another station's write got there first.
Result<bool> Library::putRow(
    const QString &machine, Units units, const ToolWrite &write, qint64 currentVersion, bool exists)
{
    QSqlQuery query(database());
    query.prepare(exists
            ? u"UPDATE tools SET version = ?, deleted = ?, data = ?, tlo = ?, updated_at = ?, "
              "updated_by = ? WHERE machine = ? AND number = ? AND version = ?"_s
            : u"INSERT INTO tools (version, deleted, data, tlo, updated_at, updated_by, machine, "
              "number) VALUES (?, ?, ?, ?, ?, ?, ?, ?) ON CONFLICT (machine, number) DO NOTHING"_s);
    for (const QVariant &v : { QVariant(currentVersion + 1), QVariant(write.tool ? 0 : 1),
             QVariant(write.tool ? QString::fromUtf8(toolData(*write.tool, units)) : u""_s),
             tloOf(write.tool), QVariant(timeText(Clock::now())), QVariant(station()), QVariant(machine),
             QVariant(write.number) })
        query.addBindValue(v);
    if (exists)
        query.addBindValue(currentVersion);
    if (!query.exec())
        return failure(tr("Writing T%1 of %2").arg(write.number).arg(machine), query);
    return query.numRowsAffected() == 1;
}

Result<StoredTable> Library::createTable(const QString &machine, const ToolTable &table)
{
    if (auto begun = beginWrite(); !begun)
        return begun.error();
    auto fail = [this](const Error &error) {
        rollback();
        return error;
    };
    QSqlQuery query(database());
    query.prepare(u"INSERT INTO machines (name) VALUES (?) ON CONFLICT (name) DO NOTHING"_s);
    query.addBindValue(machine);
    if (!query.exec())
        return fail(failure(tr("Adding the machine %1").arg(machine), query));
    query.prepare(u"INSERT INTO machine_tables (machine, units, created_at) VALUES (?, ?, ?) ON CONFLICT "
                  "(machine) DO NOTHING"_s);
    query.addBindValue(machine);
    query.addBindValue(unitsSymbol(table.units()));
    query.addBindValue(timeText(Clock::now()));
    if (!query.exec())
        return fail(failure(tr("Adding %1's table").arg(machine), query));
    if (query.numRowsAffected() != 1)
        return fail(Error { tr("The library already has a tool table for %1: open it, or choose another "
                               "name.")
                                .arg(machine) });
    for (const Tool &tool : table.tools()) {
        auto put = putRow(machine, table.units(), { tool.number, tool, 0 }, 0, false);
        if (!put)
            return fail(put.error());
    }
    if (auto said = announce({ machine }); !said)
        return fail(said.error());
    if (auto done = commit(); !done)
        return done.error();
    return readTable(machine);
}

} // namespace Toffee
