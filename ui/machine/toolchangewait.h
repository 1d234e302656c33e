// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QPointer>

class QMessageBox;
class QWidget;

namespace Toffee {

class MachineConnection;

// While a tool change waits for the person at the machine (a manual change), the window says so: which tool
// to put in, how to go on (the machine's cycle start or button, or Continue here where the controller takes
// it), how long it waits, and End the Change, which stops it on the machine. The box goes when the change
// ends, however it ends.
class ToolChangeWait final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ToolChangeWait)

public:
    ToolChangeWait(MachineConnection *connection, QWidget *window);

private:
    void waiting(int tool, int limitMs);

    MachineConnection *m_connection;
    QWidget *m_window;
    QPointer<QMessageBox> m_box;
};

} // namespace Toffee
