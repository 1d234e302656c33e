// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/common/backgroundtask.h"

#include <QThread>
#include <QTimer>

namespace Toffee {

namespace {

constexpr int kReportMs = 50;

} // namespace

BackgroundTask::BackgroundTask(QObject *parent)
    : QObject(parent)
    , m_timer(new QTimer(this))
{
    m_timer->setInterval(kReportMs);
    connect(m_timer, &QTimer::timeout, this, &BackgroundTask::report);
}

BackgroundTask::~BackgroundTask()
{
    if (m_thread) {
        m_cancel = true;
        m_thread->wait();
        delete m_thread;
    }
}

bool BackgroundTask::start(Work work)
{
    if (m_thread)
        return false;
    m_done = 0;
    m_total = 0;
    m_cancel = false;
    m_thread = QThread::create([this, work = std::move(work)] {
        work([this](qint64 done, qint64 total) {
            m_done = done;
            m_total = total;
            return !m_cancel.load();
        });
    });
    connect(m_thread, &QThread::finished, this, &BackgroundTask::done);
    m_thread->start();
    m_timer->start();
    Q_EMIT progressed(0);
    return true;
}

void BackgroundTask::cancel()
{
    if (m_thread)
        m_cancel = true;
}

void BackgroundTask::stopThen(QObject *context, const std::function<void()> &then)
{
    if (!m_thread) {
        then();
        return;
    }
    m_cancel = true;
    connect(
        this, &BackgroundTask::finished, context, [then] { then(); }, Qt::SingleShotConnection);
}

void BackgroundTask::report()
{
    const qint64 total = m_total.load();
    Q_EMIT progressed(total > 0 ? int(m_done.load() * 1000 / total) : 0);
}

void BackgroundTask::done()
{
    m_timer->stop();
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
    report();
    Q_EMIT finished(m_cancel.load());
}

} // namespace Toffee
