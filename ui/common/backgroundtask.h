// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <atomic>
#include <functional>

#include <QObject>

class QThread;
class QTimer;

namespace Toffee {

// Runs one long piece of work (a job check, a preparation) on a thread of its own, so that the window keeps
// answering: the work reports how far it is and asks whether to go on; the window reads that a few times a
// second, never waiting for the work. Cancel asks the work to stop at its next report; destroying the task
// cancels it and waits for it.
class BackgroundTask final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BackgroundTask)

public:
    // Told how far the work is (`done` of `total`); false when it is to stop.
    using Progress = std::function<bool(qint64 done, qint64 total)>;
    using Work = std::function<void(const Progress &progress)>;

    explicit BackgroundTask(QObject *parent = nullptr);
    ~BackgroundTask() override;

    // Starts `work`; false when a piece of work is still running.
    bool start(Work work);
    void cancel();
    // Cancels the work and calls `then` once it has stopped (at once when none runs): a dialog closing.
    void stopThen(QObject *context, const std::function<void()> &then);
    [[nodiscard]] bool isRunning() const { return m_thread != nullptr; }
    [[nodiscard]] bool isCancelled() const { return m_cancel.load(); }

Q_SIGNALS:
    // How far, in thousandths.
    void progressed(int permille);
    // The work returned (what it made is the work's to hand over); `cancelled` when Cancel asked it to stop.
    void finished(bool cancelled);

private:
    void report();
    void done();

    QThread *m_thread = nullptr;
    QTimer *m_timer;
    std::atomic<qint64> m_done { 0 };
    std::atomic<qint64> m_total { 0 };
    std::atomic<bool> m_cancel { false };
};

} // namespace Toffee
