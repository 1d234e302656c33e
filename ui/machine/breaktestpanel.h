// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace Toffee {

class MachineConnection;
class ToolDocument;
struct SessionResult;

// The tool-break test (M491.1): a tolerance that cannot go under the firmware's 0.02 mm, the old, new and
// difference, and an unmistakable alarm with an Unlock when the tool is broken.
class BreakTestPanel final : public QWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BreakTestPanel)

public:
    BreakTestPanel(MachineConnection *connection, ToolDocument *document, QWidget *parent = nullptr);
    // What the confirmation warns about the TLO the test compares against (empty when nothing): set by hand,
    // not in the table, or not the table's value.
    [[nodiscard]] QString referenceWarning() const;

    [[nodiscard]] double tolerance() const;
    void run(bool confirm = true);
    // Forgets the last verdict (another tool, or the tool measured again).
    void clearResult();

Q_SIGNALS:
    void finished(const Toffee::SessionResult &result);
    // The operator chose Unlock in the broken-tool alarm.
    void unlockRequested();

private:
    void updateState();
    void showResult(const SessionResult &result);
    void raiseBrokenAlarm(const SessionResult &result);

    MachineConnection *m_connection;
    ToolDocument *m_document;
    QDoubleSpinBox *m_tolerance;
    QPushButton *m_run;
    QLabel *m_old;
    QLabel *m_new;
    QLabel *m_difference;
    QLabel *m_verdict;
    int m_testedTool = -1;
    bool m_comparedWithHandSet = false;
};

} // namespace Toffee
