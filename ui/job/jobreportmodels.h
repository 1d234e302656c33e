// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QAbstractTableModel>
#include <QDateTime>

#include "model/job/jobreport.h"

namespace Toffee {

// The tools a checked program loads, in the order of first use: a snapshot of the report, replaced whole. The
// tools beyond the report's list, counted, are one last row that says so.
class JobToolsModel final : public QAbstractTableModel
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(JobToolsModel)

public:
    enum Column {
        NumberColumn,
        LoadedColumn,
        TloColumn,
        MeasuredColumn,
        CuttingColumn,
        PathColumn,
        LowestZColumn,
        ColumnCount
    };

    explicit JobToolsModel(QObject *parent = nullptr);
    void setReport(const JobReport &report, const QDateTime &now);

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(
        int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    [[nodiscard]] QString text(const JobTool &tool, int column) const;
    [[nodiscard]] QVariant moreData(int column, int role) const;

    QList<JobTool> m_tools;
    qint64 m_moreTools = 0;
    qint64 m_moreLoads = 0;
    int m_moreFromLine = 0;
    QDateTime m_now;
};

// What a check found, in line order: severity, line, tool, what.
class JobFindingsModel final : public QAbstractTableModel
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(JobFindingsModel)

public:
    enum Column { SeverityColumn, LineColumn, ToolColumn, MessageColumn, ColumnCount };
    static constexpr int LineRole = Qt::UserRole + 1;

    explicit JobFindingsModel(QObject *parent = nullptr);
    void setFindings(const QList<Finding> &findings);
    [[nodiscard]] const Finding &finding(int row) const { return m_findings.at(row); }

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(
        int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    QList<Finding> m_findings;
};

} // namespace Toffee
