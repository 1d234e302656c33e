// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace Toffee {

class MainWindow;

// toffee --self-test: the window connects to the built-in emulator, loads the example table, probes, renders
// once, and reports. A smoke test CI runs offscreen.
class SelfTest final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(SelfTest)

public:
    // `finished` gets 0 and a summary, or non-zero and the reason.
    SelfTest(MainWindow *window, std::function<void(int code, const QString &message)> finished,
        QObject *parent = nullptr);
    void start(const QElapsedTimer &sinceLaunch);

private:
    void fail(const QString &reason);
    void step(const QString &what);

    MainWindow *m_window;
    std::function<void(int, const QString &)> m_finished;
    QTimer m_watchdog;
    QString m_step;
    qint64 m_firstFrameMs = -1;
    bool m_done = false;
};

} // namespace Toffee
