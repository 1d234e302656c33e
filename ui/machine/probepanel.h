// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace Toffee {

class MachineConnection;
class ToolDocument;
struct SessionResult;

// Probe the tool in the spindle on the tool setter (after a confirmation: the machine moves), with progress
// and a Cancel that stops the machine; the result goes into the table. Also: restore a tool's known TLO.
class ProbePanel final : public QWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ProbePanel)

public:
    ProbePanel(MachineConnection *connection, ToolDocument *document, QWidget *parent = nullptr);

    // The tool whose known TLO "Restore" would set; from the table's selection.
    void setSelectedTool(int number);
    void probe(bool confirm = true);
    void restore(bool confirm = true);
    void cancel();

Q_SIGNALS:
    void finished(const Toffee::SessionResult &result);

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    // The result's words, the label as tall as they need (fitWrappedLabel).
    void setResult(const QString &text);
    void updateState();
    void report(const SessionResult &result, const QString &title);

    MachineConnection *m_connection;
    ToolDocument *m_document;
    int m_selectedTool = -1;
    QPushButton *m_probe;
    QPushButton *m_restore;
    QProgressBar *m_progress;
    QPushButton *m_cancel;
    QLabel *m_result;
};

} // namespace Toffee
