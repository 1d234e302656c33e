// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QTimer>
#include <QWidget>

class QLabel;
class QPushButton;

namespace Toffee {

class MachineConnection;
struct MachineStatus;
struct TloReading;

// The machine as it is now: state, active tool, reference and current MCS Z, TLO. Marked stale when the
// status reports stop, with an Unlock button while the machine is halted.
class TloPanel final : public QWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(TloPanel)

public:
    explicit TloPanel(MachineConnection *connection, QWidget *parent = nullptr);

    [[nodiscard]] bool isStale() const { return m_stale; }
    void unlock();

private:
    void showStatus(const MachineStatus &status);
    void showOffsets(const TloReading &offsets, int tool);
    void checkStale();
    void clear();

    MachineConnection *m_connection;
    QLabel *m_state;
    QLabel *m_tool;
    QLabel *m_reference;
    QLabel *m_current;
    QLabel *m_tlo;
    QPushButton *m_unlock;
    QTimer m_staleTimer;
    bool m_stale = true;
};

} // namespace Toffee
