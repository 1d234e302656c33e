// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/document/tooltablemodel.h"

#include <algorithm>
#include <cmath>

#include <QColor>
#include <QLocale>

#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/timetext.h"
#include "model/toolvalidation.h"

using namespace Qt::StringLiterals;

namespace Toffee {

ToolTableModel::ToolTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{ }

int ToolTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_table.size());
}

int ToolTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString ToolTableModel::formatLength(double value) const
{
    // The locale's decimal separator, as the spin boxes and the rest of the window use ("-33,388" in German).
    return formatNumber(value, NumberFormat::display(m_table.units()).inLocale());
}

QVariant ToolTableModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Tool &tool = m_table.at(index.row());
    if (role == ToolNumberRole)
        return tool.number;
    if (role != Qt::DisplayRole && role != Qt::EditRole && role != SortRole) {
        // A cell with nothing to explain shows its text as its tooltip (a long description, a note).
        if (QVariant look = decoration(tool, index.column(), role); look.isValid() || role != Qt::ToolTipRole)
            return look;
    }

    const bool display = role == Qt::DisplayRole || role == Qt::ToolTipRole;
    auto length = [&](double v) -> QVariant {
        return display ? QVariant(formatLength(v)) : QVariant(v);
    };
    switch (index.column()) {
    case NumberColumn:
        return tool.number;
    case PocketColumn:
        return tool.pocket;
    case DescriptionColumn:
        return tool.description;
    case LengthGeometryColumn:
        return length(tool.lengthGeometry);
    case LengthWearColumn:
        return length(tool.lengthWear);
    case TotalLengthColumn:
        return length(tool.totalLength());
    case RadiusGeometryColumn:
        return length(tool.radiusGeometry);
    case RadiusWearColumn:
        return length(tool.radiusWear);
    case MeasuredTloColumn: {
        if (role == SortRole)
            return tool.measuredTlo ? *tool.measuredTlo : -1e300;
        if (role == Qt::EditRole)
            return tool.measuredTlo ? QVariant(*tool.measuredTlo) : QVariant();
        QString text = tool.measuredTlo ? formatLength(*tool.measuredTlo) : tr("not measured");
        if (tool.measuredTlo && tool.tloSource == TloSource::Manual)
            text = tr("%1 (by hand)").arg(text);
        else if (tool.measuredTlo && tool.tloSource == TloSource::Pulled)
            text = tr("%1 (pulled)").arg(text);
        if (tool.breakTestFailed)
            text = tr("%1 — BROKEN?").arg(text);
        return text;
    }
    case MeasuredAtColumn:
        if (!tool.measuredAt.isValid())
            return {};
        if (role == SortRole || role == Qt::EditRole)
            return tool.measuredAt;
        if (role == Qt::ToolTipRole)
            return QLocale().toString(tool.measuredAt.toLocalTime(), QLocale::LongFormat);
        return isStale(tool) ? tr("%1 (stale)").arg(ageText(tool.measuredAt)) : ageText(tool.measuredAt);
    case ToolLifeColumn: {
        if (role == Qt::EditRole)
            return ToolLife::limitText(tool);
        const auto used = m_usedLife.constFind(tool.number);
        const UsedLife u = used == m_usedLife.cend() ? UsedLife() : *used;
        if (role == SortRole)
            return ToolLife::fraction(tool, u).value_or(0.0) * 1e9 + u.seconds;
        if (used == m_usedLife.cend() && !tool.lifeLimitMinutes && !tool.lifeLimitUses)
            return {};
        return ToolLife::usedText(tool, u);
    }
    case ProbingColumn:
        return ProbeSettings::text(tool.probing, tool.flutes, m_table.units());
    case NotesColumn:
        return role == Qt::DisplayRole ? QString(tool.notes).replace(u'\n', u' ') : tool.notes;
    default:
        return {};
    }
}

void ToolTableModel::setUsedLife(const QHash<int, UsedLife> &used)
{
    m_usedLife = used;
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0, ToolLifeColumn), index(rowCount() - 1, ToolLifeColumn));
}

void ToolTableModel::setStaleAfterDays(int days)
{
    m_staleAfterDays = std::max(1, days);
    refreshAges();
}

bool ToolTableModel::isStale(const Tool &tool, const QDateTime &now) const
{
    return tool.measuredAt.isValid() && tool.measuredAt.secsTo(now) > qint64(m_staleAfterDays) * 24 * 3600;
}

void ToolTableModel::refreshAges()
{
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0, MeasuredAtColumn), index(rowCount() - 1, MeasuredAtColumn));
}

QVariant ToolTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    // The TLO column holds what the machine measured and what was set on it by hand (marked so): not only
    // measurements, which its name once said.
    if (orientation == Qt::Horizontal && role == Qt::ToolTipRole && section == MeasuredTloColumn)
        return tr(
            "The tool length offset: measured on the tool setter, or set by hand (marked \"by hand\").");
    if (orientation == Qt::Horizontal && role == Qt::ToolTipRole && section == MeasuredAtColumn)
        return tr("When the TLO was measured or set.");
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case NumberColumn:
        return tr("Tool");
    case PocketColumn:
        return tr("Pocket");
    case DescriptionColumn:
        return tr("Description");
    case LengthGeometryColumn:
        return tr("Length");
    case LengthWearColumn:
        return tr("Length wear");
    case TotalLengthColumn:
        return tr("Total length");
    case RadiusGeometryColumn:
        return tr("Radius");
    case RadiusWearColumn:
        return tr("Radius wear");
    case MeasuredTloColumn:
        return tr("TLO");
    case MeasuredAtColumn:
        return tr("TLO recorded");
    case ToolLifeColumn:
        return tr("Tool life");
    case ProbingColumn:
        return tr("Probing");
    case NotesColumn:
        return tr("Notes");
    default:
        return {};
    }
}

Qt::ItemFlags ToolTableModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (!index.isValid())
        return f;
    // The total is computed and the measurement comes from the tool setter: neither is typed in.
    const int c = index.column();
    if (c != TotalLengthColumn && c != MeasuredTloColumn && c != MeasuredAtColumn)
        f |= Qt::ItemIsEditable;
    return f;
}

Result<Tool> ToolTableModel::editedTool(const Tool &tool, int column, const QVariant &value) const
{
    Tool edited = tool;
    const QString text = value.toString().trimmed();
    auto number = [&](const QString &what, double &field) -> Result<void> {
        QByteArray bytes = text.toUtf8();
        bytes.replace(',', '.'); // a decimal comma is what many operators type
        const auto v = value.typeId() == QMetaType::Double ? std::optional<double>(value.toDouble())
                                                           : parseDecimal(bytes);
        if (!v)
            return Error {
                tr("%1: \"%2\" is not a number; enter a value such as -12.345.").arg(what, excerpt(text))
            };
        field = *v;
        return {};
    };
    auto integer = [&](const QString &what, int &field) -> Result<void> {
        const auto v = parseInteger(text.toUtf8());
        if (!v || *v < INT_MIN || *v > INT_MAX)
            return Error { tr("%1: \"%2\" is not a whole number.").arg(what, excerpt(text)) };
        field = int(*v);
        return {};
    };

    Result<void> parsed;
    switch (column) {
    case NumberColumn:
        parsed = integer(tr("Tool"), edited.number);
        break;
    case PocketColumn:
        parsed = integer(tr("Pocket"), edited.pocket);
        break;
    case DescriptionColumn:
        edited.description = text;
        break;
    case LengthGeometryColumn:
        parsed = number(tr("Length"), edited.lengthGeometry);
        break;
    case LengthWearColumn:
        parsed = number(tr("Length wear"), edited.lengthWear);
        break;
    case RadiusGeometryColumn:
        parsed = number(tr("Radius"), edited.radiusGeometry);
        break;
    case RadiusWearColumn:
        parsed = number(tr("Radius wear"), edited.radiusWear);
        break;
    case NotesColumn:
        edited.notes = value.toString();
        break;
    case ToolLifeColumn:
        parsed = ToolLife::parseLimit(text, edited);
        break;
    case ProbingColumn: {
        const auto settings = ProbeSettings::parse(text, m_table.units());
        if (!settings)
            return settings.error();
        edited.probing = settings.value().settings;
        edited.flutes = settings.value().flutes;
        break;
    }
    default:
        return Error { tr("this column cannot be edited.") };
    }
    if (!parsed)
        return parsed.error();
    if (auto r = validateTool(edited, m_table.units()); !r)
        return r.error();
    if (edited.number != tool.number && m_table.contains(edited.number))
        return Error {
            tr("tool number %1 is already in the table; tool numbers must be unique.").arg(edited.number)
        };
    return edited;
}

bool ToolTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (role != Qt::EditRole
        || !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return false;
    const Tool before = m_table.at(index.row());
    auto after = editedTool(before, index.column(), value);
    if (!after) {
        Q_EMIT editRejected(after.error().message);
        return false;
    }
    if (after.value() == before)
        return true;
    if (m_editHandler) {
        m_editHandler(before, after.value());
        return true;
    }
    return replaceTool(before.number, after.value()).ok();
}

int ToolTableModel::pocketCount(int pocket) const
{
    if (pocket == 0)
        return 1;
    if (m_pocketsDirty) {
        m_pocketCounts.clear();
        for (const Tool &t : m_table.tools())
            ++m_pocketCounts[t.pocket];
        m_pocketsDirty = false;
    }
    return m_pocketCounts.value(pocket);
}

QList<int> ToolTableModel::toolsSharingPocket(int pocket, int except) const
{
    QList<int> numbers;
    if (pocket == 0 || pocketCount(pocket) < 2)
        return numbers;
    for (const Tool &t : m_table.tools()) {
        if (t.pocket == pocket && t.number != except)
            numbers << t.number;
    }
    return numbers;
}

void ToolTableModel::pocketsChanged(int pocket, int leftPocket, int number)
{
    // Only when another row's pocket became, or stopped being, shared is the column repainted: a table whose
    // pockets are all their own (the usual case) costs nothing more per edit.
    const bool shared = pocket >= 0 && pocketCount(pocket) > 1;
    const bool unshared = leftPocket > 0 && pocketCount(leftPocket) == 1;
    if ((shared || unshared) && !m_table.isEmpty())
        Q_EMIT dataChanged(index(0, PocketColumn), index(int(m_table.size()) - 1, PocketColumn),
            { Qt::ForegroundRole, Qt::ToolTipRole });
    if (shared)
        Q_EMIT pocketShared(number, pocket, toolsSharingPocket(pocket, number));
}

void ToolTableModel::resetTable(const ToolTable &table)
{
    beginResetModel();
    m_table = table;
    m_pocketsDirty = true;
    endResetModel();
}

Result<void> ToolTableModel::insertTool(const Tool &tool)
{
    if (auto r = m_table.checkInsert(tool); !r)
        return r;
    const int row = int(m_table.insertionIndex(tool.number));
    beginInsertRows({}, row, row);
    (void)m_table.insert(tool);
    if (!m_pocketsDirty)
        ++m_pocketCounts[tool.pocket];
    endInsertRows();
    pocketsChanged(tool.pocket, -1, tool.number);
    return {};
}

Result<void> ToolTableModel::replaceTool(int number, const Tool &tool)
{
    if (auto r = m_table.checkReplace(number, tool); !r)
        return r;
    const int oldRow = rowOfTool(number);
    const int oldPocket = m_table.at(oldRow).pocket;
    // A new number can move the row; a move (not remove + insert) keeps views' selection on the tool.
    const int destination = int(m_table.insertionIndex(tool.number));
    const bool moves = tool.number != number && destination != oldRow && destination != oldRow + 1;
    if (moves)
        beginMoveRows({}, oldRow, oldRow, {}, destination);
    (void)m_table.replace(number, tool);
    if (!m_pocketsDirty && tool.pocket != oldPocket) {
        --m_pocketCounts[oldPocket];
        ++m_pocketCounts[tool.pocket];
    }
    if (moves)
        endMoveRows();
    const int row = rowOfTool(tool.number);
    Q_EMIT dataChanged(index(row, 0), index(row, ColumnCount - 1)); // every role: text, marks, colours
    if (tool.pocket != oldPocket)
        pocketsChanged(tool.pocket, oldPocket, tool.number);
    return {};
}

bool ToolTableModel::removeTool(int number)
{
    const int row = rowOfTool(number);
    if (row < 0)
        return false;
    const int pocket = m_table.at(row).pocket;
    beginRemoveRows({}, row, row);
    m_table.remove(number);
    if (!m_pocketsDirty)
        --m_pocketCounts[pocket];
    endRemoveRows();
    pocketsChanged(-1, pocket, number);
    return true;
}

} // namespace Toffee
