// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>

#include <QAbstractTableModel>
#include <QHash>

#include "model/clock.h"
#include "model/toollife.h"
#include "model/tooltable.h"

namespace Toffee {

// The tool table for views. Edits from a view are validated here; when an edit handler is installed
// (the document's undo stack) the change goes through it, and only the public API below changes the table.
class ToolTableModel final : public QAbstractTableModel
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ToolTableModel)

public:
    enum Column {
        NumberColumn,
        PocketColumn,
        DescriptionColumn,
        LengthGeometryColumn,
        LengthWearColumn,
        TotalLengthColumn,
        RadiusGeometryColumn,
        RadiusWearColumn,
        MeasuredTloColumn,
        MeasuredAtColumn, // shown as an age ("3 h ago"), marked stale when older than the limit
        // What the cutter has cut since it went in (the history library's program runs), against its life
        // limit; the limit is what is edited ("90 min, 40 uses").
        ToolLifeColumn,
        // How the tool is measured on the setter ("X 20, 4 edges, spread 0.03"; empty: once at the centre).
        ProbingColumn,
        NotesColumn,
        ColumnCount
    };
    enum Role {
        SortRole = Qt::UserRole + 1, // numbers as numbers, for QSortFilterProxyModel::setSortRole
        ToolNumberRole,
    };
    using EditHandler = std::function<void(const Tool &before, const Tool &after)>;

    explicit ToolTableModel(QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

    [[nodiscard]] const ToolTable &table() const { return m_table; }
    [[nodiscard]] int rowOfTool(int number) const { return int(m_table.indexOf(number)); }

    void resetTable(const ToolTable &table);
    Result<void> insertTool(const Tool &tool);
    Result<void> replaceTool(int number, const Tool &tool);
    bool removeTool(int number);

    // What an edit of `column` to `value` (text as typed, or a number) would make of `tool`.
    [[nodiscard]] Result<Tool> editedTool(const Tool &tool, int column, const QVariant &value) const;

    void setEditHandler(EditHandler handler) { m_editHandler = std::move(handler); }

    // The other tools in `pocket` (pocket 0, the spindle of a random changer, is never shared).
    [[nodiscard]] QList<int> toolsSharingPocket(int pocket, int except) const;

    // Tool life from the history library: what each tool's cutter has done since it went in (a tool missing
    // has done nothing recorded).
    void setUsedLife(const QHash<int, UsedLife> &used);
    [[nodiscard]] UsedLife usedLife(int number) const { return m_usedLife.value(number); }
    // A measurement older than this many days is stale; "now" moves on, so the ages are redrawn on
    // refreshAges.
    void setStaleAfterDays(int days);
    [[nodiscard]] int staleAfterDays() const { return m_staleAfterDays; }
    [[nodiscard]] bool isStale(const Tool &tool, const QDateTime &now = Clock::now()) const;
    void refreshAges();
    static constexpr int kDefaultStaleDays = 7;

Q_SIGNALS:
    // An edit from a view was refused; the message says why and what to enter instead.
    void editRejected(const QString &message);
    // A tool was added or changed into a pocket another tool already has: allowed, but worth a word
    // (LinuxCNC's random tool changer needs each tool in its own pocket).
    void pocketShared(int number, int pocket, const QList<int> &others);

private:
    [[nodiscard]] QString formatLength(double value) const;
    [[nodiscard]] QVariant decoration(const Tool &tool, int column, int role) const;
    [[nodiscard]] QString tloToolTip(const Tool &tool) const;

    [[nodiscard]] int pocketCount(int pocket) const;
    // After tool `number` moved into `pocket` (or -1) from `leftPocket` (or -1).
    void pocketsChanged(int pocket, int leftPocket, int number);

    ToolTable m_table;
    EditHandler m_editHandler;
    mutable QHash<int, int> m_pocketCounts; // built when first needed after a change
    QHash<int, UsedLife> m_usedLife;
    int m_staleAfterDays = kDefaultStaleDays;
    mutable bool m_pocketsDirty = true;
};

} // namespace Toffee
