// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDockWidget>

namespace Toffee {

class BreakTestPanel;
class ConnectionPanel;
class MachineConnection;
class OffsetEditor;
class ProbePanel;
class TloPanel;
class ToolDocument;

// The machine side of the window: connection, probing, manual offsets and the break test. The live state
// (TloPanel) is made here but shown by the window in its always-visible strip.
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

private:
    ConnectionPanel *m_connection;
    TloPanel *m_tlo;
    ProbePanel *m_probe;
    OffsetEditor *m_offsets;
    BreakTestPanel *m_breakTest;
};

} // namespace Toffee
