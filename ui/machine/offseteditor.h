// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace Toffee {

class MachineConnection;
class ToolDocument;
struct TloReading;

// Sets the TLO by hand: directly (M493.3 Z), by a change to the current TLO (the seed's "add 2.9 mm"), or
// from a gauge of known height under the tip (M493.3 H). It shows the exact command and the resulting TLO
// first. What the machine then holds goes into the table as the tool's TLO, marked set by hand.
class OffsetEditor final : public QWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(OffsetEditor)

public:
    enum Mode { SetTlo, ChangeTlo, AboveZ0 };

    OffsetEditor(MachineConnection *connection, ToolDocument *document, QWidget *parent = nullptr);

    void setMode(Mode mode);
    void setValue(double value);
    [[nodiscard]] QString commandPreview() const;
    [[nodiscard]] QString resultPreview() const;
    void send(bool confirm = true);
    // The value's field, focused with its text selected: typing replaces it.
    void focusValue();

private:
    void updatePreview();
    [[nodiscard]] std::optional<double> targetTlo() const;

    MachineConnection *m_connection;
    ToolDocument *m_document;
    std::optional<double> m_currentTlo;
    QComboBox *m_mode;
    QDoubleSpinBox *m_value;
    QLabel *m_command;
    QLabel *m_result;
    QPushButton *m_send;
};

} // namespace Toffee
