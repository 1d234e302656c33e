// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <optional>

#include <QDialog>

#include "model/toolsetter.h"

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace Toffee {

class MachineConnection;

// Machine ▸ Tool Setter…: where the machine's tool setter is and how Toffee's probing cycle touches it (a
// controller without a setter cycle of its own: grblHAL). Machine coordinates in mm, feeds in mm/min. OK only
// while the values make a cycle (ToolSetter::validate), which the dialog says otherwise. Connected to such a
// controller, it shows where the machine stands, jogs it (asked once first; Stop ends a jog) and takes the
// setter's X and Y from where it stands: an operator jogs the spindle over the setter's centre and says so.
class ToolSetterDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ToolSetterDialog)

public:
    // `connection`: the machine to jog and read the position of, when it is connected to a controller whose
    // setter is Toffee's; else the dialog only edits.
    ToolSetterDialog(const QString &machine, const ToolSetter &setter,
        MachineConnection *connection = nullptr, QWidget *parent = nullptr);
    static constexpr double kJogFeed = 1000.0; // mm/min

    [[nodiscard]] ToolSetter setter() const;

private:
    void check();
    [[nodiscard]] QWidget *machineBox(MachineConnection *connection);
    void updateMachine();
    void jog(int axis, double direction);
    void useWhereItStands();

    QDoubleSpinBox *m_x;
    QDoubleSpinBox *m_y;
    QDoubleSpinBox *m_zMin;
    QDoubleSpinBox *m_safeZ;
    QDoubleSpinBox *m_seek;
    QDoubleSpinBox *m_latch;
    QDoubleSpinBox *m_backoff;
    QLabel *m_problem;
    QDialogButtonBox *m_buttons;
    MachineConnection *m_connection = nullptr;
    QLabel *m_position = nullptr;
    QComboBox *m_step = nullptr;
    QList<QPushButton *> m_jogButtons;
    QPushButton *m_stop = nullptr;
    QPushButton *m_useHere = nullptr;
    QLabel *m_jogResult = nullptr;
    bool m_jogAsked = false;
    std::optional<std::array<double, 3>> m_here; // machine X Y Z, as last reported
};

} // namespace Toffee
