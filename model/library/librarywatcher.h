// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QTimer>

namespace Toffee {

class Library;

// Says when another station changed the library. A shared library announces each change on its channel
// (PostgreSQL LISTEN/NOTIFY, through Qt's driver); an SQLite file is asked every few hundred milliseconds
// whether another connection wrote to it (its data_version), as SQLite has no notifications.
class LibraryWatcher final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LibraryWatcher)

public:
    static constexpr int kPollMs = 250;

    // Watches `library`, which must outlive the watcher.
    explicit LibraryWatcher(Library *library, QObject *parent = nullptr);
    ~LibraryWatcher() override;

Q_SIGNALS:
    // The machine whose table or history changed; empty when the library cannot say which.
    void changed(const QString &machine);
    // A shared library's announcement: which machine, the station that changed it, and when that station
    // said so (its clock, ms since the epoch; 0 when unknown).
    void announced(const QString &machine, const QString &station, qint64 saidAtMs);

private:
    void poll();

    Library *m_library;
    QTimer m_poll;
    qint64 m_dataVersion = -1;
};

} // namespace Toffee
