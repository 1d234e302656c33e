// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QDialog>
#include <QList>

class QLabel;
class QTableWidget;

namespace Toffee {

// One tool's TLO in the table file and in the controller's own table, and what a push or pull does to it.
struct OffsetDifference
{
    int tool = 0;
    std::optional<double> inFile;
    std::optional<double> inController;
    bool changes = false; // the push or pull writes this row
    QString what; // "written", "new tool", "unchanged", "beyond the controller's table", …
};

// Machine ▸ Push Offsets… / Pull Offsets…: what would change, tool by tool, before anything is written. The
// action's button is the default only when something changes.
class OffsetSyncDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(OffsetSyncDialog)

public:
    enum class Direction { Push, Pull };
    OffsetSyncDialog(Direction direction, const QString &controller, const QList<OffsetDifference> &rows,
        const QString &refusal, QWidget *parent = nullptr);

    [[nodiscard]] QTableWidget *table() const { return m_table; }

private:
    QTableWidget *m_table;
    QLabel *m_summary;
};

} // namespace Toffee
