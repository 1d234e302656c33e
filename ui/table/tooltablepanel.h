// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QLabel;
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
    // A table that may be read but not changed: no editing in the view, and `banner` above it says why.
    // Empty: editable again.
    void setReadOnly(const QString &banner);
    [[nodiscard]] bool isReadOnly() const;
    // A cell's editor is open (a reset of the model would close it, and lose what is typed).
    [[nodiscard]] bool isEditing() const;

private:
    void fitColumns();
    [[nodiscard]] int widthFor(const QModelIndex &index) const;

    ToolTableModel *m_model;
    QSortFilterProxyModel *m_proxy;
    QLabel *m_banner;
    QLineEdit *m_filter;
    QTableView *m_view;
};

} // namespace Toffee
