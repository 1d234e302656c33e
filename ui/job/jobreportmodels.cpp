// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/job/jobreportmodels.h"

#include <QBrush>
#include <QColor>

#include "model/numberformat.h"
#include "model/timetext.h"

using namespace Qt::StringLiterals;

namespace Toffee {

JobToolsModel::JobToolsModel(QObject *parent)
    : QAbstractTableModel(parent)
{ }

void JobToolsModel::setReport(const JobReport &report, const QDateTime &now)
{
    beginResetModel();
    m_tools = report.tools;
    m_moreTools = report.moreTools;
    m_moreLoads = report.moreLoads;
    m_moreFromLine = report.moreFromLine;
    m_now = now;
    endResetModel();
}

int JobToolsModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_tools.size()) + (m_moreTools > 0 ? 1 : 0);
}

int JobToolsModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString JobToolsModel::text(const JobTool &tool, int column) const
{
    switch (column) {
    case NumberColumn:
        return u"T"_s + QString::number(tool.number);
    case LoadedColumn:
        return linesListed(tool.loadLines, tool.loads);
    case TloColumn:
        if (!tool.inTable)
            return tr("not in the table");
        if (!tool.tlo)
            return tr("not measured");
        return tool.setByHand ? tr("%1 (by hand)").arg(millimetres(*tool.tlo, false))
                              : millimetres(*tool.tlo, false);
    case MeasuredColumn:
        if (!tool.measuredAt.isValid())
            return QString();
        return tool.setByHand ? tr("set %1").arg(ageText(tool.measuredAt, m_now))
                              : ageText(tool.measuredAt, m_now);
    case CuttingColumn:
        return durationText(tool.cuttingSeconds);
    case PathColumn:
        return millimetres(tool.feedPathMm, false);
    case LowestZColumn:
        return tool.lowestZ ? millimetres(*tool.lowestZ, false) : QString();
    }
    return {};
}

// The last row: the tools beyond the list, counted.
QVariant JobToolsModel::moreData(int column, int role) const
{
    if (role == Qt::DisplayRole && column == NumberColumn)
        return tr("%1 more").arg(m_moreTools);
    if (role == Qt::DisplayRole && column == LoadedColumn)
        return tr("from line %1, %2 loads: counted, not listed").arg(m_moreFromLine).arg(m_moreLoads);
    if (role == Qt::ToolTipRole)
        return tr("The program loads %1 distinct tools: the first %2 are listed, the other %3 only counted. "
                  "Their findings are summed up, one for each kind.")
            .arg(qint64(m_tools.size()) + m_moreTools)
            .arg(m_tools.size())
            .arg(m_moreTools);
    return {};
}

QVariant JobToolsModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    if (index.row() == m_tools.size())
        return moreData(index.column(), role);
    const JobTool &tool = m_tools.at(index.row());
    if (role == Qt::DisplayRole)
        return text(tool, index.column());
    if (role == Qt::ToolTipRole && index.column() == MeasuredColumn && tool.measuredAt.isValid())
        return QLocale().toString(tool.measuredAt.toLocalTime(), QLocale::LongFormat);
    if (role == Qt::TextAlignmentRole && index.column() != NumberColumn && index.column() != LoadedColumn)
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ForegroundRole && index.column() == TloColumn
        && (!tool.inTable || !tool.tlo || tool.setByHand))
        return QBrush(QColor(0xd3, 0x2f, 0x2f));
    return {};
}

QVariant JobToolsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case NumberColumn:
        return tr("Tool");
    case LoadedColumn:
        return tr("Loaded at line");
    case TloColumn:
        return tr("TLO (mm)");
    case MeasuredColumn:
        return tr("Measured");
    case CuttingColumn:
        return tr("Cutting time");
    case PathColumn:
        return tr("Feed path (mm)");
    case LowestZColumn:
        return tr("Lowest cut Z (mm)");
    }
    return {};
}

JobFindingsModel::JobFindingsModel(QObject *parent)
    : QAbstractTableModel(parent)
{ }

void JobFindingsModel::setFindings(const QList<Finding> &findings)
{
    beginResetModel();
    m_findings = findings;
    endResetModel();
}

int JobFindingsModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_findings.size());
}

int JobFindingsModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant JobFindingsModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_findings.size())
        return {};
    const Finding &f = m_findings.at(index.row());
    const bool error = f.severity() == Severity::Error;
    if (role == LineRole)
        return f.line;
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case SeverityColumn:
            return error ? tr("Error") : tr("Warning");
        case LineColumn:
            return f.line;
        case ToolColumn:
            if (f.moreTools > 0)
                return tr("%1 tools").arg(f.moreTools);
            return f.tool >= 0 ? u"T"_s + QString::number(f.tool) : QString();
        case MessageColumn:
            return f.count > 1 ? tr("%1 (%2 times: lines %3)").arg(f.message).arg(f.count).arg(f.linesText())
                               : f.message;
        }
    }
    if (role == Qt::ToolTipRole && index.column() == MessageColumn)
        return f.message;
    if (role == Qt::ForegroundRole && index.column() == SeverityColumn)
        return QBrush(error ? QColor(0xd3, 0x2f, 0x2f) : QColor(0xe6, 0x7e, 0x00));
    return {};
}

QVariant JobFindingsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case SeverityColumn:
        return tr("Severity");
    case LineColumn:
        return tr("Line");
    case ToolColumn:
        return tr("Tool");
    case MessageColumn:
        return tr("Finding");
    }
    return {};
}

} // namespace Toffee
