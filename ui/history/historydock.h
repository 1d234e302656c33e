// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDockWidget>

#include "model/library/historyevent.h"
#include "model/library/weartrend.h"
#include "model/result.h"

class QLabel;
class QPushButton;
class QSplitter;
class QTableView;

namespace Toffee {

class HistoryRecorder;
class HistoryTableModel;

// One tool's history: a chart of its TLO over time (probes as points, break tests marked, failed ones in red,
// the wear trend with a band of ± the tolerance around it) and the measurements as a table; Export as CSV and
// Copy Chart. It reads the library the recorder writes, and follows what the recorder writes for that tool.
class HistoryDock final : public QDockWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(HistoryDock)

public:
    explicit HistoryDock(HistoryRecorder *recorder, QWidget *parent = nullptr);

    // The tool to show (-1: none), on `machine`, with the break-test tolerance for the band.
    void showTool(int tool, const QString &machine, double tolerance);
    [[nodiscard]] int tool() const { return m_tool; }
    [[nodiscard]] const QList<HistoryEvent> &events() const { return m_events; }
    // The chart (a QChartView of the chart module) once the panel has been seen; null before, or without
    // the module.
    [[nodiscard]] QWidget *chartView() const;
    // The CSV Export writes: the events as the library holds them.
    [[nodiscard]] QByteArray csv() const;
    [[nodiscard]] Result<void> exportCsv(const QString &path) const;
    [[nodiscard]] QPushButton *exportButton() const;
    void copyChart();

private:
    void reload();
    void fillChart(const std::optional<WearTrend> &trend, const QList<TrendPoint> &points);
    void fillTable();

    HistoryRecorder *m_recorder;
    QLabel *m_title;
    QWidget *m_view = nullptr;
    QLabel *m_chartPlace = nullptr; // where the chart goes, until it is made; says why it cannot be
    QSplitter *m_split;
    QTableView *m_table;
    HistoryTableModel *m_model;
    QPushButton *m_export;
    QPushButton *m_copy;
    int m_tool = -1;
    QString m_machine;
    double m_tolerance = 0.1;
    QList<HistoryEvent> m_events;
    bool m_stale = true; // the tool changed while the panel was not seen
    bool m_seen = false; // QDockWidget::visibilityChanged: shown, and not behind another panel's tab
};

} // namespace Toffee
