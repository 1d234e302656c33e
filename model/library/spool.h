// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include <QCoreApplication>
#include <QJsonArray>
#include <QList>
#include <QString>

#include "model/library/historyevent.h"
#include "model/library/librarylocation.h"
#include "model/result.h"

namespace Toffee {

class Library;

// What this computer keeps for a library that cannot take it now: measurement events, one file per batch in
// a folder beside the station's own library (<AppDataLocation>/outbox). It needs no database, so it holds
// when the library is locked by another program, busy under another station's row lock, out of reach,
// damaged, or when the station's own SQLite library is the one that is locked.
//
// toffee-cli writes each measurement here before it asks the library (a write-ahead): a kill, Ctrl-C or a
// crash at any moment after the machine measured leaves it here, and the file is removed only once the
// library has it. What waits is sent, oldest first, the next time that library is opened; each event's id
// makes a second sending (after a crash between the library's commit and the file's removal) write nothing
// twice. A file that cannot be read is moved to outbox/quarantine, never deleted; an event in a file that the
// history cannot take goes there alone, its file's other events are sent.
//
// Each library has a folder of its own, named by its identity (LibraryLocation::identity: a symlink or a
// relative path names the same one), so that what waits for one costs nothing to another. Several senders
// at once (two toffee-cli, the window) each send what they find; a file another sent meanwhile is simply
// gone.
class Spool
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::Spool)

public:
    // A spool file is a few events: anything larger was not written by Toffee.
    static constexpr qint64 kMaxFileBytes = 1024 * 1024;
    // How many events one transaction of send() writes at most.
    static constexpr qsizetype kBatchEvents = 1000;

    explicit Spool(QString folder = defaultFolder());
    // <AppDataLocation>/outbox, beside LibraryLocation::standard().
    [[nodiscard]] static QString defaultFolder();
    [[nodiscard]] const QString &folder() const { return m_folder; }

    // Keeps the events for `target`, synced to the disk; the file's path, for removing it once written.
    [[nodiscard]] Result<QString> keep(
        const LibraryLocation &target, const QList<HistoryEvent> &events) const;
    // Removes a kept file once its events are written.
    [[nodiscard]] Result<void> remove(const QString &path) const;
    // How many events wait for `target`.
    [[nodiscard]] qsizetype count(const LibraryLocation &target) const;

    struct Sent
    {
        int events = 0; // events now in the library that waited here (new or already there)
        QStringList quarantined; // files that could not be read, moved aside
    };
    // Sends what waits for `library`, oldest first, each file removed once written. Stops at the first file
    // the library refuses (busy, locked, damaged: the same would happen to the next), keeping it and the
    // rest.
    [[nodiscard]] Result<Sent> send(
        Library &library, const std::function<void(const QList<HistoryEvent> &)> &written = {}) const;

private:
    struct Entry
    {
        QString path;
        QString library; // as written: the location's text
        QList<HistoryEvent> events; // those the history can take
        QJsonArray rejected; // those it cannot, as they were written
        QString why; // the first reason one was rejected
    };
    // The folder of what waits for `target`: <folder>/library-<hash of its identity>.
    [[nodiscard]] QString folderFor(const LibraryLocation &target) const;
    // What waits for `target`: its folder's files, oldest first, then files an older Toffee wrote at the top.
    [[nodiscard]] QStringList files(const LibraryLocation &target) const;
    // Nothing when the file is gone (another sender took it).
    [[nodiscard]] Result<std::optional<Entry>> read(const QString &path) const;
    void quarantine(const QString &path) const;
    // The rejected events of `entry` into the quarantine, as a file of their own.
    [[nodiscard]] bool quarantineRejected(const Entry &entry) const;

    QString m_folder;
};

} // namespace Toffee
