// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QList>

#include "model/library/storedtable.h"

class QComboBox;
class QTableWidget;

namespace Toffee {

// The tools another station changed since this one read them, which the library refused to overwrite: per
// tool, theirs (with the station that wrote it) beside mine, and a choice of which the library keeps. Only
// the fields that differ are listed, so the difference is what the eye finds first.
class ConflictDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ConflictDialog)

public:
    enum Column { ToolColumn, TheirsColumn, MineColumn, ChoiceColumn, ColumnCount };

    ConflictDialog(const QList<ToolConflict> &conflicts, Units units, QWidget *parent = nullptr);
    ~ConflictDialog() override;

    [[nodiscard]] const QList<ToolConflict> &conflicts() const { return m_conflicts; }
    // The operator's choice for tool `number`: true keeps this station's version.
    [[nodiscard]] bool keepsMine(int number) const;
    void setKeepsMine(int number, bool keep);

    // A tool's side as the dialog shows it: the fields that differ from `other`, one a line.
    [[nodiscard]] static QString describe(
        const std::optional<Tool> &tool, const std::optional<Tool> &other, Units units);

protected:
    void showEvent(QShowEvent *event) override;

private:
    void fill(Units units);

    QList<ToolConflict> m_conflicts;
    QTableWidget *m_table;
    QList<QComboBox *> m_choices; // one per conflict, in the same order
    QMetaObject::Connection m_scrollToFocus; // a choice reached with Tab is scrolled into view
};

} // namespace Toffee
