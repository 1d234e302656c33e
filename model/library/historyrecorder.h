// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include <QObject>
#include <QTimer>

#include "model/library/historyevent.h"
#include "model/library/library.h"

namespace Toffee {

// Writes measurement events to the library without ever holding up the table: an event the library cannot
// take now (locked for too long, a full disk, a read-only file, a library that would not open) waits in
// memory and is written when the library takes writes again. It says so once per outage, not once per event.
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
    // Null while the library is not open.
    [[nodiscard]] Library *library() const { return m_library.get(); }

    void record(const HistoryEvent &event);
    void recordUse(const QList<ToolUse> &uses);
    // Tries to write what waits, now; true when nothing waits any more.
    bool flush();
    [[nodiscard]] qsizetype pendingCount() const { return m_pending.size() + m_pendingUse.size(); }
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

private:
    void fail(const QString &message);

    LibraryLocation m_location;
    Library::Options m_options;
    std::unique_ptr<Library> m_library;
    QList<HistoryEvent> m_pending;
    QList<ToolUse> m_pendingUse;
    QTimer m_retry;
    bool m_down = false;
    QString m_lastError;
};

} // namespace Toffee
