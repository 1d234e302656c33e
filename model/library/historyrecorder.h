// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include <QObject>
#include <QThread>
#include <QTimer>

#include "model/library/historyevent.h"
#include "model/library/library.h"
#include "model/library/outboxpayload.h"
#include "model/library/spool.h"

namespace Toffee {

class LibraryWatcher;

// A station's link to its library. It writes measurement events without ever holding up the table: an event
// the library cannot take now (locked for too long, a full disk, a read-only file, a damaged library, one
// that would not open) waits and is written when the library takes writes again, and it says so once per
// outage, not once per event. What waits is kept on this computer at once, so that it outlives a crash and
// the window's closing: for a shared library in the station's own SQLite library (the outbox), else (or when
// that cannot take it either) in the spool's files (spool.h); each event's id makes a replay write it once.
// It also writes machine tables, and says when another station changed the library.
class HistoryRecorder final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(HistoryRecorder)

public:
    static constexpr int kRetryMs = 2000;

    explicit HistoryRecorder(QObject *parent = nullptr);
    ~HistoryRecorder() override;

    // Opens the library there (closing any other). On failure the recorder keeps taking events and tries
    // again.
    Result<void> setLocation(const LibraryLocation &location, Library::Options options = {});
    [[nodiscard]] const LibraryLocation &location() const { return m_location; }
    // Where a shared library's outbox is kept: the standard SQLite library unless set.
    void setOutboxLocation(const LibraryLocation &location);
    [[nodiscard]] LibraryLocation outboxLocation() const;
    // Null while the library is not open.
    [[nodiscard]] Library *library() const { return m_library.get(); }

    void record(const HistoryEvent &event);
    void recordUse(const QList<ToolUse> &uses);
    // Writes a machine table's tools, or, with a shared library out of reach, keeps them in the outbox (the
    // outcome says queued): they are written when it returns, and their conflicts then come as replayed().
    [[nodiscard]] Result<WriteOutcome> writeTools(const ToolWrites &writes);
    // Tries to write what waits, now; true when nothing waits any more.
    bool flush();
    [[nodiscard]] qsizetype pendingCount() const
    {
        return m_pending.size() + m_pendingUse.size() + m_outboxCount + m_spoolCount;
    }
    // Where events the library cannot take are kept on this computer (Spool::defaultFolder() unless set).
    void setSpoolFolder(const QString &folder);
    [[nodiscard]] bool isAvailable() const { return !m_down; }
    [[nodiscard]] QString lastError() const { return m_lastError; }

Q_SIGNALS:
    void recorded(const QList<Toffee::HistoryEvent> &events);
    // Tool use was written, or a library opened: totals may have changed.
    void usesChanged();
    // The library stopped taking writes: what is wrong. Said once until it takes them again.
    void unavailable(const QString &message);
    // Everything that waited is written.
    void available();
    // How many changes wait for the library changed.
    void pendingChanged(qsizetype count);
    // Another station (or program) changed the machine's table or history; empty: any machine.
    void libraryChanged(const QString &machine);
    // Tool writes that waited in the outbox were written now: what was written, and the conflicts.
    void replayed(const QString &machine, const Toffee::WriteOutcome &outcome);

private:
    [[nodiscard]] bool ensureOpen();
    void attach(std::unique_ptr<Library> library);
    void closeLibrary();
    [[nodiscard]] Result<void> keepInOutbox(const QString &kind, const QByteArray &payload);
    [[nodiscard]] Result<void> replayOutbox();
    void lose(const QString &message);
    void fail(const QString &message);
    void failAndSpool(const QString &message);
    void countOutbox();
    void countSpool();
    // The events that wait in memory go to the spool, where neither a crash nor closing the window loses
    // them; those it cannot take stay in memory.
    void spoolPending();
    void checkConnection();
    void startProbe();

    LibraryLocation m_location;
    LibraryLocation m_outboxLocation;
    Library::Options m_options;
    std::unique_ptr<Library> m_library;
    std::unique_ptr<Library> m_outbox; // the station's own SQLite library, for a shared one
    LibraryWatcher *m_watcher = nullptr;
    QList<HistoryEvent> m_pending;
    QList<ToolUse> m_pendingUse;
    qsizetype m_outboxCount = 0;
    Spool m_spool;
    qsizetype m_spoolCount = 0; // events kept in the spool for this library
    QTimer m_retry;
    QTimer m_health;
    bool m_down = false;
    QString m_lastError;
    std::unique_ptr<QThread> m_probe; // asks a shared library that was down whether it is back
    QString m_probeError; // written by the probe's thread, read once it has finished
    bool m_reachable = false; // the probe found it back: the next open is quick
};

} // namespace Toffee
