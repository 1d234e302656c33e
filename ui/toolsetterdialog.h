// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

#include "model/toolsetter.h"

class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;

namespace Toffee {

// Machine ▸ Tool Setter…: where the machine's tool setter is and how Toffee's probing cycle touches it (a
// controller without a setter cycle of its own: grblHAL). Machine coordinates in mm, feeds in mm/min. OK only
// while the values make a cycle (ToolSetter::validate), which the dialog says otherwise.
class ToolSetterDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ToolSetterDialog)

public:
    explicit ToolSetterDialog(const QString &machine, const ToolSetter &setter, QWidget *parent = nullptr);

    [[nodiscard]] ToolSetter setter() const;

private:
    void check();

    QDoubleSpinBox *m_x;
    QDoubleSpinBox *m_y;
    QDoubleSpinBox *m_zMin;
    QDoubleSpinBox *m_safeZ;
    QDoubleSpinBox *m_seek;
    QDoubleSpinBox *m_latch;
    QDoubleSpinBox *m_backoff;
    QLabel *m_problem;
    QDialogButtonBox *m_buttons;
};

} // namespace Toffee
