// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QLineEdit;
class QSortFilterProxyModel;
class QTableView;

namespace Toffee {

class ToolTableModel;

// The tool table in the centre of the window: a filter line above a sortable, editable view.
class ToolTablePanel final : public QWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ToolTablePanel)

public:
    explicit ToolTablePanel(ToolTableModel *model, QWidget *parent = nullptr);

    [[nodiscard]] QTableView *view() const { return m_view; }
    [[nodiscard]] QLineEdit *filterEdit() const { return m_filter; }
    // Tool numbers of the selected rows, whatever the sort and filter.
    [[nodiscard]] QList<int> selectedToolNumbers() const;
    void selectTool(int number);

private:
    void fitColumns();

    ToolTableModel *m_model;
    QSortFilterProxyModel *m_proxy;
    QLineEdit *m_filter;
    QTableView *m_view;
};

} // namespace Toffee
