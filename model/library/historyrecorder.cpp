// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/historyrecorder.h"

namespace Toffee {

HistoryRecorder::HistoryRecorder(QObject *parent)
    : QObject(parent)
{
    m_retry.setInterval(kRetryMs);
    connect(&m_retry, &QTimer::timeout, this, &HistoryRecorder::flush);
}

HistoryRecorder::~HistoryRecorder() = default;

Result<void> HistoryRecorder::setLocation(const LibraryLocation &location, Library::Options options)
{
    m_library.reset();
    m_location = location;
    m_options = options;
    auto opened = Library::open(location, options);
    if (!opened) {
        fail(opened.error().message);
        return opened.error();
    }
    m_library = opened.takeValue();
    flush();
    Q_EMIT usesChanged();
    return {};
}

// While the library is down, an event only joins the queue: the retry writes it, and the window does not wait
// a busy timeout per event.
void HistoryRecorder::record(const HistoryEvent &event)
{
    m_pending.append(event);
    if (!m_down)
        flush();
}

void HistoryRecorder::recordUse(const QList<ToolUse> &uses)
{
    m_pendingUse.append(uses);
    if (!m_down)
        flush();
}

bool HistoryRecorder::flush()
{
    if (m_pending.isEmpty() && m_pendingUse.isEmpty()) {
        m_retry.stop();
        return true;
    }
    if (!m_library) {
        if (m_location.path.isEmpty())
            return false; // no library chosen: the events wait for one
        auto opened = Library::open(m_location, m_options);
        if (!opened) {
            fail(opened.error().message);
            return false;
        }
        m_library = opened.takeValue();
    }
    if (auto written = m_library->append(m_pending); !written) {
        fail(written.error().message);
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
    if (m_down) {
        m_down = false;
        m_lastError.clear();
        Q_EMIT available();
    }
    return true;
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
