// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QDateTime>
#include <QTimer>
#include <QWidget>

#include "serial/machine/machinereplies.h"

class QLabel;
class QPushButton;

namespace Toffee {

class MachineConnection;
class ToolDocument;

// The firmware's state word ("Idle", "Run", …) in the window's language.
[[nodiscard]] QString machineStateName(const QString &state);

// The machine as it is now, in a strip across the top of the window that no scrolling or dock hides: state
// (in words, red while halted, with what to do and an Unlock button), the active tool, its TLO and where
// that TLO came from (measured, set by hand, not measured, or not the value the table holds for the tool),
// and the reference and current MCS Z. Greyed and marked stale when the status reports stop.
class TloPanel final : public QWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(TloPanel)

public:
    TloPanel(MachineConnection *connection, ToolDocument *document, QWidget *parent = nullptr);

    [[nodiscard]] bool isStale() const { return m_stale; }
    // What the TLO readout's note says: "measured …", "set by hand …", "not measured", …
    [[nodiscard]] QString tloNote() const;
    // Asks first when the tool in the spindle is marked broken, unless `confirm` is false (the broken-tool
    // alarm's own Unlock, which is that question).
    void unlock(bool confirm = true);

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    // The halt banner wraps at the strip's width: as many lines as its words need there, never wider.
    void fitHalt();
    void showStatus(const MachineStatus &status);
    void showOffsets(const TloReading &offsets, int tool);
    void showHalt();
    void updateTlo();
    void checkStale();
    void layOut();
    void clear();

    MachineConnection *m_connection;
    ToolDocument *m_document;
    QLabel *m_state;
    QLabel *m_tool;
    QLabel *m_tlo;
    QLabel *m_tloNote;
    QLabel *m_reference;
    QLabel *m_current;
    QLabel *m_halt;
    QPushButton *m_unlock;
    QTimer m_staleTimer;
    QString m_lastStateText; // the state as the last report said it, before any note of its age
    bool m_stale = true;
    std::optional<int> m_activeTool;
    std::optional<double> m_machineTlo;
    std::optional<TloReading> m_offsets;
    QDateTime m_connectedAt; // a TLO of the table from before it is only said to match the machine's
};

} // namespace Toffee
