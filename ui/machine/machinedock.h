// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDockWidget>

class QGroupBox;
class QLabel;

namespace Toffee {

class BreakTestPanel;
class ConnectionPanel;
class MachineConnection;
class OffsetEditor;
class ProbePanel;
class TloPanel;
class ToolDocument;

// The machine side of the window: connection, probing, manual offsets and the break test (the last two only
// where the machine's firmware has them). The live state (TloPanel) is made here but shown by the window in
// its always-visible strip.
class MachineDock final : public QDockWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(MachineDock)

public:
    MachineDock(MachineConnection *connection, ToolDocument *document, QWidget *parent = nullptr);

    [[nodiscard]] ConnectionPanel *connectionPanel() const { return m_connection; }
    [[nodiscard]] TloPanel *tloPanel() const { return m_tlo; }
    [[nodiscard]] ProbePanel *probePanel() const { return m_probe; }
    [[nodiscard]] OffsetEditor *offsetEditor() const { return m_offsets; }
    [[nodiscard]] BreakTestPanel *breakTestPanel() const { return m_breakTest; }
    // Nothing measured could be kept in the table (a library table this station may only read): probing,
    // setting and testing are off, `why` on each. Empty: on again.
    void setRecordingBlocked(const QString &why);

private:
    // What the connected machine's firmware cannot do is hidden, with a line that says why.
    void showFirmwareLimits();

    MachineConnection *m_machine;
    ConnectionPanel *m_connection;
    TloPanel *m_tlo;
    ProbePanel *m_probe;
    OffsetEditor *m_offsets;
    BreakTestPanel *m_breakTest;
    QGroupBox *m_probeGroup = nullptr;
    QGroupBox *m_offsetsGroup = nullptr;
    QGroupBox *m_breakTestGroup = nullptr;
    QLabel *m_limits;
};

} // namespace Toffee
