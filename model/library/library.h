// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <memory>

#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QString>

#include "model/library/historyevent.h"
#include "model/library/librarylocation.h"
#include "model/result.h"

class QSqlDatabase;
class QSqlQuery;

namespace Toffee {

// The history library: machines, every measurement event, and what each tool cut, in an SQLite file through
// Qt SQL (docs/LIBRARY.md has every table and column). The SQL is what PostgreSQL runs too. One Library is
// one connection, for the thread that opened it; the window and toffee-cli can each hold one on the same file
// at once (WAL, and a busy timeout).
class Library
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::Library)
    Q_DISABLE_COPY_MOVE(Library)

public:
    // The schema this Toffee writes. A library with a higher version is refused, never altered.
    static constexpr int kSchemaVersion = 1;
    struct Options
    {
        int busyTimeoutMs = 5000; // how long a write waits for another program's to finish
    };

    // Opens the library, creating it (and its folder) when it does not exist, and brings its schema up to
    // date in one transaction.
    [[nodiscard]] static Result<std::unique_ptr<Library>> open(const LibraryLocation &location);
    [[nodiscard]] static Result<std::unique_ptr<Library>> open(
        const LibraryLocation &location, Options options);
    ~Library();

    [[nodiscard]] const LibraryLocation &location() const { return m_location; }

    // Adds the machine, or updates its dialect and connection.
    [[nodiscard]] Result<void> addMachine(const MachineRecord &machine);
    [[nodiscard]] Result<QList<MachineRecord>> machines() const;
    // Appends the events in one transaction (their machines added as needed): all or none. An event whose id
    // is already there is skipped, so writing a batch again after an unclear failure duplicates nothing.
    // Returns how many were new.
    [[nodiscard]] Result<int> append(const QList<HistoryEvent> &events);
    [[nodiscard]] Result<int> appendUse(const QList<ToolUse> &uses);
    // Oldest first.
    [[nodiscard]] Result<QList<HistoryEvent>> history(const HistoryQuery &query) const;
    [[nodiscard]] Result<QList<ToolUse>> uses(const QString &machine, std::optional<int> tool) const;
    // Each tool's total cutting time on the machine, in seconds.
    [[nodiscard]] Result<QHash<int, double>> cuttingTotals(const QString &machine) const;

private:
    Library(LibraryLocation location, QString connection);
    [[nodiscard]] QSqlDatabase database() const;
    [[nodiscard]] Result<void> prepare();
    [[nodiscard]] Result<void> migrate(int version);
    [[nodiscard]] Result<int> schemaVersion() const;
    [[nodiscard]] Error failure(const QString &what, const QSqlQuery &query) const;
    [[nodiscard]] Result<void> ensureMachines(const QStringList &names);
    [[nodiscard]] Result<int> insertAll(const QString &sql, const QStringList &machines, qsizetype count,
        const std::function<QString(QSqlQuery &, qsizetype)> &bind);

    LibraryLocation m_location;
    QString m_connection;
};

} // namespace Toffee
