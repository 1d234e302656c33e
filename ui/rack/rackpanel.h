// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QHash>
#include <QList>
#include <QPointer>
#include <QWidget>

#include "serial/carvera/rack/racksequence.h"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace Toffee {

class MachineConnection;
class ToolDocument;

// The Carvera's tool changer: which tool is in the spindle, what the table knows of each rack tool, and the
// three things that move the machine through the rack (Load Tool, Measure Rack, Check Rack), each asked about
// first, with progress and a Cancel. What the machine measures goes into the table and the history.
class RackPanel final : public QWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(RackPanel)

public:
    enum Column { SlotColumn, ToolColumn, StoredColumn, MeasuredColumn, ResultColumn, ColumnCount };

    RackPanel(MachineConnection *connection, ToolDocument *document, QWidget *parent = nullptr);

    // The rack as the "Rack holds:" field says, or nothing while its text does not parse.
    [[nodiscard]] std::optional<QList<int>> rack() const { return m_rack; }
    void loadTool(int tool, bool confirm = true);
    void measureRack(bool confirm = true);
    void checkRack(bool confirm = true);
    void cancel();
    // What the Machine menu's Rack actions may do now, as the panel's buttons (their tooltips say why not).
    [[nodiscard]] bool canMeasure() const;
    [[nodiscard]] bool canCheck() const;

Q_SIGNALS:
    // The buttons' enabled state may have changed.
    void stateChanged();

private:
    void buildLayout();
    void setupTable();
    void connectSignals();
    void rackEdited();
    void updateState();
    void refreshTable();
    void fillRow(int row, int tool);
    [[nodiscard]] QString resultText(const RackStep &step) const;
    [[nodiscard]] QString measuredText(int tool) const;
    void updateSpindle();
    [[nodiscard]] std::optional<QString> checkRefusal() const;
    [[nodiscard]] std::optional<double> machineReference() const;
    [[nodiscard]] QString loadQuestion(
        int tool, const std::optional<double> &stored, const QString &why) const;
    // `storedAge`: the stored TLO was taken (measured that long ago), not probed.
    void loadFinished(const SessionResult &r, int tool, const std::optional<QString> &storedAge);
    void runSequence(RackSequence::Mode mode, bool confirm);
    void stepChanged(int index);
    void stepRecorded(const SessionResult &r);
    void sequenceFinished(const SessionResult &outcome);
    void warnBroken(const SessionResult &outcome, const QString &notRun);
    void showProgress(bool running);

    MachineConnection *m_connection;
    ToolDocument *m_document;
    std::optional<QList<int>> m_rack;
    QHash<int, RackStep> m_results; // this session's sequence results, by tool
    QPointer<RackSequence> m_sequence;
    bool m_loading = false;
    QString m_recordFailure; // why a measurement could not be stored, which stopped the sequence
    std::optional<int> m_shownSpindle;
    QLabel *m_spindle;
    QLabel *m_firmware;
    QLineEdit *m_holds;
    QLabel *m_holdsError;
    QTableWidget *m_table;
    QSpinBox *m_toolSpin;
    QPushButton *m_load;
    QPushButton *m_measure;
    QPushButton *m_check;
    QDoubleSpinBox *m_tolerance;
    QCheckBox *m_useStored;
    QProgressBar *m_progress;
    QLabel *m_status;
    QPushButton *m_cancel;
    QLabel *m_result;
};

} // namespace Toffee
