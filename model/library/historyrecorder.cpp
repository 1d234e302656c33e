// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/historyrecorder.h"

#include <QThread>

#include "model/library/librarywatcher.h"

using namespace Qt::StringLiterals;

namespace Toffee {

HistoryRecorder::HistoryRecorder(QObject *parent)
    : QObject(parent)
{
    m_retry.setInterval(kRetryMs);
    connect(&m_retry, &QTimer::timeout, this, &HistoryRecorder::flush);
    // A shared library's server can go away between writes: the station says so before the operator's next
    // measurement finds out.
    m_health.setInterval(kRetryMs);
    connect(&m_health, &QTimer::timeout, this, &HistoryRecorder::checkConnection);
}

HistoryRecorder::~HistoryRecorder()
{
    spoolPending(); // closing the window loses nothing that waits
    delete m_watcher;
    if (m_probe)
        m_probe->wait(); // at most the connect timeout
}

void HistoryRecorder::startProbe()
{
    if (m_probe && m_probe->isRunning())
        return;
    m_probe.reset(QThread::create([this, location = m_location, options = m_options] {
        auto opened = Library::open(location, options); // this thread's connection, closed here
        m_probeError = opened ? QString() : opened.error().message;
    }));
    connect(m_probe.get(), &QThread::finished, this, [this] {
        if (!m_probeError.isEmpty()) {
            fail(m_probeError);
            return;
        }
        m_reachable = true;
        flush();
    });
    m_probe->start();
}

void HistoryRecorder::closeLibrary()
{
    delete std::exchange(m_watcher, nullptr);
    m_library.reset();
    m_health.stop();
}

Result<void> HistoryRecorder::setLocation(const LibraryLocation &location, Library::Options options)
{
    closeLibrary();
    // What waits in memory (the last library would not even open) goes to this one, as the operator's
    // measurements; what was kept on this computer stays with the library it was kept for.
    m_location = location;
    m_options = options;
    countOutbox();
    countSpool();
    auto opened = Library::open(location, options);
    if (!opened) {
        fail(opened.error().message);
        return opened.error();
    }
    attach(opened.takeValue());
    flush();
    Q_EMIT usesChanged();
    return {};
}

void HistoryRecorder::setOutboxLocation(const LibraryLocation &location)
{
    m_outbox.reset();
    m_outboxLocation = location;
    countOutbox();
}

LibraryLocation HistoryRecorder::outboxLocation() const
{
    return m_outboxLocation.isSet() ? m_outboxLocation : LibraryLocation::standard();
}

void HistoryRecorder::attach(std::unique_ptr<Library> library)
{
    m_library = std::move(library);
    m_watcher = new LibraryWatcher(m_library.get(), this);
    connect(m_watcher, &LibraryWatcher::changed, this, &HistoryRecorder::libraryChanged);
    if (m_location.isShared())
        m_health.start();
}

bool HistoryRecorder::ensureOpen()
{
    if (m_library)
        return true;
    if (!m_location.isSet())
        return false; // no library chosen: the events wait for one
    // A server that is down may take its whole connect timeout to say so: while it is, a thread of its own
    // asks, and the window waits for nothing.
    if (m_location.isShared() && m_down && !std::exchange(m_reachable, false)) {
        startProbe();
        return false;
    }
    auto opened = Library::open(m_location, m_options);
    if (!opened) {
        fail(opened.error().message);
        return false;
    }
    attach(opened.takeValue());
    return true;
}

// While the library is down, an event only joins the queue: the retry writes it, and the window does not wait
// a busy timeout per event.
void HistoryRecorder::record(const HistoryEvent &event)
{
    m_pending.append(event);
    if (!m_down)
        flush();
    else if (m_location.isShared())
        lose(m_lastError); // into the outbox at once: a crash now loses nothing
    else if (m_library)
        spoolPending(); // the library is there but refuses writes: kept on this computer at once
    Q_EMIT pendingChanged(pendingCount());
}

void HistoryRecorder::setSpoolFolder(const QString &folder)
{
    m_spool = Spool(folder);
    countSpool();
}

void HistoryRecorder::countSpool()
{
    const qsizetype before = m_spoolCount;
    m_spoolCount = m_location.isSet() ? m_spool.count(m_location) : 0;
    if (m_spoolCount != before)
        Q_EMIT pendingChanged(pendingCount());
}

void HistoryRecorder::spoolPending()
{
    if (m_pending.isEmpty() || !m_location.isSet())
        return;
    if (m_spool.keep(m_location, m_pending)) {
        m_pending.clear();
        countSpool();
    }
}

void HistoryRecorder::recordUse(const QList<ToolUse> &uses)
{
    m_pendingUse.append(uses);
    if (!m_down)
        flush();
}

bool HistoryRecorder::flush()
{
    const bool waiting
        = !m_pending.isEmpty() || !m_pendingUse.isEmpty() || m_outboxCount > 0 || m_spoolCount > 0;
    if (!waiting && (m_library || !m_location.isSet())) {
        m_retry.stop();
        if (m_library && std::exchange(m_down, false)) {
            m_lastError.clear();
            Q_EMIT available();
        }
        return true;
    }
    if (!ensureOpen()) {
        // A library that would not open (not a library at all, perhaps) keeps them in memory, to go to the
        // library the operator chooses next; closing the window keeps them in the spool.
        if (m_location.isShared() && !m_pending.isEmpty())
            lose(m_lastError);
        return false;
    }
    if (m_location.isShared() && m_outboxCount > 0) {
        if (auto replayed = replayOutbox(); !replayed) {
            lose(replayed.error().message);
            return false;
        }
    }
    if (m_spoolCount > 0) {
        auto sent = m_spool.send(*m_library, [this](const QList<HistoryEvent> &events) {
            countSpool();
            Q_EMIT recorded(events);
        });
        countSpool();
        if (!sent) {
            m_location.isShared() ? lose(sent.error().message) : failAndSpool(sent.error().message);
            return false;
        }
    }
    if (auto written = m_library->append(m_pending); !written) {
        m_location.isShared() ? lose(written.error().message) : failAndSpool(written.error().message);
        return false;
    }
    const QList<HistoryEvent> done = std::exchange(m_pending, {});
    if (auto written = m_library->appendUse(m_pendingUse); !written) {
        fail(written.error().message);
        if (!done.isEmpty())
            Q_EMIT recorded(done);
        return false;
    }
    const bool usesWritten = !m_pendingUse.isEmpty();
    m_pendingUse.clear();
    m_retry.stop();
    if (usesWritten)
        Q_EMIT usesChanged();
    if (!done.isEmpty())
        Q_EMIT recorded(done);
    Q_EMIT pendingChanged(pendingCount());
    if (m_down) {
        m_down = false;
        m_lastError.clear();
        Q_EMIT available();
    }
    return true;
}

Result<WriteOutcome> HistoryRecorder::writeTools(const ToolWrites &writes)
{
    if (!m_location.isShared()) {
        if (!ensureOpen())
            return Error { m_lastError };
        return m_library->writeTools(writes.machine, writes.writes);
    }
    if (m_outboxCount > 0 || !m_library)
        flush(); // what waits goes first, in the order it was made
    if (m_library && m_outboxCount == 0) {
        auto written = m_library->writeTools(writes.machine, writes.writes);
        if (written || !m_library->isConnectionLost())
            return written;
        lose(written.error().message);
    }
    if (auto kept = keepInOutbox(u"tools"_s, toolsPayload(writes)); !kept)
        return kept.error();
    WriteOutcome queued;
    queued.queued = true;
    return queued;
}

// A shared library's write failed: when the server is gone the link is dropped (the retry opens a new one),
// and the events that wait go to the outbox, where a crash of the station cannot take them.
void HistoryRecorder::lose(const QString &message)
{
    if (m_library && m_library->isConnectionLost())
        closeLibrary();
    // Out of memory before they are counted in the outbox: a count never has them twice.
    if (const QList<HistoryEvent> events = std::exchange(m_pending, {}); !events.isEmpty()) {
        if (!keepInOutbox(u"events"_s, eventsPayload(events)))
            m_pending = events;
    }
    spoolPending(); // the outbox could not take them (its own library locked, full): the spool's files
    fail(message);
}

void HistoryRecorder::failAndSpool(const QString &message)
{
    spoolPending();
    fail(message);
}

void HistoryRecorder::checkConnection()
{
    if (!m_library || !m_library->isConnectionLost())
        return;
    closeLibrary();
    fail(tr("The library (%1) cannot be reached: its server stopped answering. Toffee keeps what you record "
            "and writes it when the server is back.")
             .arg(m_location.displayName()));
}

void HistoryRecorder::fail(const QString &message)
{
    m_lastError = message;
    if (!m_retry.isActive())
        m_retry.start();
    if (m_down)
        return;
    m_down = true;
    Q_EMIT unavailable(message);
}

} // namespace Toffee
