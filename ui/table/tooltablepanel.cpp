// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/table/tooltablepanel.h"

#include <algorithm>

#include <QApplication>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

#include "model/document/tooltablemodel.h"
#include "model/limits.h"
#include "model/numberformat.h"
#include "ui/table/tooltabledelegate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

ToolTablePanel::ToolTablePanel(ToolTableModel *model, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_proxy(new QSortFilterProxyModel(this))
    , m_banner(new QLabel(this))
    , m_filter(new QLineEdit(this))
    , m_view(new QTableView(this))
{
    m_proxy->setSourceModel(model);
    m_proxy->setSortRole(ToolTableModel::SortRole);
    m_proxy->setFilterKeyColumn(-1);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);

    m_filter->setObjectName(u"toolFilter"_s);
    m_filter->setAccessibleName(tr("Filter tools"));
    m_filter->setPlaceholderText(tr("Filter tools (number, description, notes…)"));
    m_filter->setClearButtonEnabled(true);
    connect(m_filter, &QLineEdit::textChanged, m_proxy, &QSortFilterProxyModel::setFilterFixedString);

    m_view->setObjectName(u"toolTable"_s);
    m_view->setAccessibleName(tr("Tool table"));
    m_view->setModel(m_proxy);
    m_view->setItemDelegate(new ToolTableDelegate(m_view));
    m_view->setSortingEnabled(true);
    m_view->sortByColumn(ToolTableModel::NumberColumn, Qt::AscendingOrder);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setAlternatingRowColors(true);
    m_banner->setObjectName(u"readOnlyBanner"_s);
    m_banner->setAccessibleName(tr("Read-only"));
    m_banner->setTextFormat(Qt::PlainText);
    m_banner->setWordWrap(true);
    // An amber strip with its own text colour: seen at a glance, and as readable in the dark palette.
    m_banner->setStyleSheet(u"QLabel { background: #fff1c2; color: #3d2e00; padding: 6px; "
                            "border: 1px solid #d9b44a; }"_s);
    setReadOnly({});
    m_view->setWordWrap(false);
    m_view->setTabKeyNavigation(false); // Tab moves on to the next control, not through every cell
    m_view->setTextElideMode(Qt::ElideRight);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 8);
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    // What an operator at the machine looks for first comes first: the TLO and when it was measured sit
    // beside the description, not past the right edge of a narrow window.
    QHeaderView *header = m_view->horizontalHeader();
    header->moveSection(
        header->visualIndex(ToolTableModel::MeasuredTloColumn), ToolTableModel::DescriptionColumn + 1);
    header->moveSection(
        header->visualIndex(ToolTableModel::MeasuredAtColumn), ToolTableModel::DescriptionColumn + 2);
    header->setSectionsMovable(true);
    connect(model, &QAbstractItemModel::modelReset, this, &ToolTablePanel::fitColumns);
    // A TLO that grows a mark ("— BROKEN?") and a tool life that comes from the history are never cut off:
    // their columns widen to them.
    connect(model, &QAbstractItemModel::dataChanged, this,
        [this](const QModelIndex &topLeft, const QModelIndex &bottomRight) {
            for (const int column :
                { int(ToolTableModel::MeasuredTloColumn), int(ToolTableModel::ToolLifeColumn) }) {
                if (topLeft.column() > column || bottomRight.column() < column)
                    continue;
                int needed = 0;
                for (int row = topLeft.row(); row <= bottomRight.row(); ++row) {
                    const QModelIndex shown = m_proxy->mapFromSource(topLeft.model()->index(row, column));
                    if (shown.isValid())
                        needed = std::max(needed, widthFor(shown));
                }
                if (needed > m_view->columnWidth(column))
                    m_view->setColumnWidth(column, needed);
            }
        });
    fitColumns();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_banner);
    layout->addWidget(m_filter);
    layout->addWidget(m_view);
}

void ToolTablePanel::setReadOnly(const QString &banner)
{
    m_banner->setText(banner);
    m_banner->setVisible(!banner.isEmpty());
    m_view->setEditTriggers(banner.isEmpty() ? QAbstractItemView::DoubleClicked
                | QAbstractItemView::EditKeyPressed | QAbstractItemView::AnyKeyPressed
                                             : QAbstractItemView::NoEditTriggers);
}

bool ToolTablePanel::isReadOnly() const
{
    return !m_banner->text().isEmpty();
}

bool ToolTablePanel::isEditing() const
{
    // An editor is a child of the view's viewport with the focus; the view's own focus is not editing.
    const QWidget *focus = QApplication::focusWidget();
    return focus && focus != m_view && m_view->isAncestorOf(focus);
}

namespace {

// The rows measured for a column's width: a real table has a few dozen; a hostile one is not measured whole.
constexpr int kMeasuredRows = 2000;

} // namespace

void ToolTablePanel::fitColumns()
{
    // Fit to the data, but keep free text from pushing the numbers off screen.
    m_view->resizeColumnsToContents();
    const int text = m_view->fontMetrics().averageCharWidth();
    m_view->setColumnWidth(ToolTableModel::DescriptionColumn,
        std::clamp(m_view->columnWidth(ToolTableModel::DescriptionColumn), 24 * text, 40 * text));
    // Room for a TLO set by hand ("-999.999 (by hand)"); a broken mark widens the column when it comes
    // (keepTloWhole), so that the table shows more columns at 1024 px than the rare longest text would allow.
    const int tlo = m_view->fontMetrics().horizontalAdvance(
                        ToolTableModel::tr("%1 (by hand)").arg(millimetres(-Limits::kMaxGeometryMm, false)))
        + 2 * text;
    m_view->setColumnWidth(ToolTableModel::MeasuredTloColumn,
        std::max(m_view->columnWidth(ToolTableModel::MeasuredTloColumn), tlo));
    // resizeColumnsToContents measures only the rows on screen, none while the table is hidden: a mark
    // already in the table when it was filled ("— BROKEN?") was cut off. Every row is measured for the marked
    // columns.
    for (const int column : { int(ToolTableModel::MeasuredTloColumn), int(ToolTableModel::ToolLifeColumn) }) {
        int needed = m_view->columnWidth(column);
        for (int row = 0; row < std::min(m_proxy->rowCount(), kMeasuredRows); ++row)
            needed = std::max(needed, widthFor(m_proxy->index(row, column)));
        m_view->setColumnWidth(column, needed);
    }
}

// The width a cell's text needs whole: the item's size hint fell a few pixels short of what the style draws
// it in ("6.500 (by hand) — BROKE…" in a column exactly as wide as the hint), so the text's own advance and
// the same two characters of room the TLO column is given for "(by hand)".
int ToolTablePanel::widthFor(const QModelIndex &index) const
{
    const int text = m_view->fontMetrics().horizontalAdvance(index.data().toString())
        + 2 * m_view->fontMetrics().averageCharWidth();
    return std::max(m_view->sizeHintForIndex(index).width(), text);
}

QList<int> ToolTablePanel::selectedToolNumbers() const
{
    QList<int> numbers;
    const auto rows = m_view->selectionModel()->selectedRows();
    for (const QModelIndex &row : rows)
        numbers.append(row.data(ToolTableModel::ToolNumberRole).toInt());
    return numbers;
}

void ToolTablePanel::selectTool(int number)
{
    const int row = m_model->rowOfTool(number);
    if (row < 0)
        return;
    const QModelIndex index = m_proxy->mapFromSource(m_model->index(row, ToolTableModel::NumberColumn));
    if (!index.isValid())
        return;
    m_view->selectionModel()->setCurrentIndex(
        index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    m_view->scrollTo(index);
}

} // namespace Toffee
