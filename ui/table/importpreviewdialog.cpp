// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/table/importpreviewdialog.h"

#include <algorithm>

#include <QDialogButtonBox>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScreen>
#include <QScrollBar>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "model/camimport/importpreview.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// The list is as tall as this many rows need at most; the details area shows this many lines.
constexpr int kRowsShown = 12;
constexpr int kDetailLines = 5;
// A description wider than this many characters is cut short in the list (the details area has it whole).
constexpr int kDescriptionChars = 36;
// The role holding a row's full text for the details area.
constexpr int kDetailsRole = Qt::UserRole + 1;

QString changeText(ImportChange change)
{
    switch (change) {
    case ImportChange::New:
        return ImportPreviewDialog::tr("New");
    case ImportChange::Changed:
        return ImportPreviewDialog::tr("Changed");
    case ImportChange::Unchanged:
        return ImportPreviewDialog::tr("Unchanged");
    }
    return {};
}

} // namespace

ImportPreviewDialog::ImportPreviewDialog(
    const ImportPreview &preview, const QString &source, const QString &formatName, QWidget *parent)
    : QDialog(parent)
    , m_summary(new QLabel(this))
    , m_tools(new QTreeWidget(this))
    , m_details(new QPlainTextEdit(this))
    , m_import(new QPushButton(tr("&Import"), this))
    , m_cancel(new QPushButton(tr("Cancel"), this))
{
    setObjectName(u"importPreviewDialog"_s);
    setAccessibleName(tr("Import tools"));
    setWindowTitle(tr("Import Tools from %1").arg(QFileInfo(source).fileName()));
    m_summary->setObjectName(u"importSummary"_s);
    m_summary->setAccessibleName(tr("What the import does"));
    m_summary->setWordWrap(true);
    m_summary->setTextFormat(Qt::PlainText);
    const QString counts = tr("%1 (%2): %3.").arg(source, formatName, preview.summary());
    m_summary->setText(!preview.changesAnything()
            ? counts + u' ' + tr("The table already has these tools as the library describes them.")
            : preview.newCutters().isEmpty() ? counts + u' '
                + tr("Only descriptions, radii and the CAM's line in the notes change; measured TLOs, wear, "
                     "pockets and your notes stay as they are.")
                                             : counts + u' '
                + tr("Only descriptions, radii and the CAM's line in the notes change, except where the "
                     "library describes another cutter: that tool's TLO, length, wear and break mark end "
                     "(the history keeps the TLO) and it is measured before it cuts. Pockets and your notes "
                     "stay as they are."));
    m_tools->setObjectName(u"importToolList"_s);
    m_tools->setAccessibleName(tr("Tools in the library"));
    m_tools->setRootIsDecorated(false);
    m_tools->setAlternatingRowColors(true);
    m_tools->setHeaderLabels({ tr("Tool"), tr("Import"), tr("Description"), tr("Changes") });
    // Each change on a line of its own, in a column as wide as the longest one (the list scrolls sideways
    // when the screen is narrower); a long description gives way to them. The details area below has a
    // tool's description and changes whole, wrapped.
    m_tools->setUniformRowHeights(false);
    m_tools->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_tools->header()->setSectionResizeMode(DescriptionColumn, QHeaderView::Interactive);
    m_tools->header()->setStretchLastSection(false);
    m_details->setObjectName(u"importDetails"_s);
    m_details->setAccessibleName(tr("Changes and notes of the selected tool"));
    m_details->setReadOnly(true);
    m_details->setTabChangesFocus(true);
    m_details->setTextInteractionFlags(Qt::TextSelectableByKeyboard | Qt::TextSelectableByMouse);
    m_details->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    connect(m_tools, &QTreeWidget::currentItemChanged, this,
        [this](const QTreeWidgetItem *current) { showDetails(current); });
    fill(preview);

    m_import->setObjectName(u"importButton"_s);
    m_import->setAccessibleName(tr("Import the tools"));
    m_import->setEnabled(preview.changesAnything());
    m_import->setDefault(preview.changesAnything());
    m_cancel->setObjectName(u"importCancelButton"_s);
    m_cancel->setAccessibleName(tr("Cancel the import"));
    auto *buttons = new QDialogButtonBox(this);
    buttons->setObjectName(u"importButtons"_s);
    buttons->setAccessibleName(tr("Import or cancel"));
    buttons->addButton(m_import, QDialogButtonBox::AcceptRole);
    buttons->addButton(m_cancel, QDialogButtonBox::RejectRole);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_tools, 1);
    layout->addWidget(m_details);
    layout->addWidget(buttons);
    setTabOrder(m_tools, m_details);
    setTabOrder(m_details, m_import);
    setTabOrder(m_import, m_cancel);
    m_tools->setFocus();
    fitToContents();
}

void ImportPreviewDialog::showDetails(const QTreeWidgetItem *item)
{
    m_details->setPlainText(item ? item->data(ToolColumn, kDetailsRole).toString() : QString());
}

// As wide as the longest change needs and as tall as the rows do, within the screen: neither a change cut
// off when there is room for it, nor a short list in a dialog of empty space.
void ImportPreviewDialog::fitToContents()
{
    const QMargins margins = layout()->contentsMargins();
    const int frame = 2 * m_tools->frameWidth();
    // QTreeView's sizeHintForColumn is protected; QAbstractItemView's is public, and dispatches to it.
    const QAbstractItemView *view = m_tools;
    m_tools->setColumnWidth(DescriptionColumn,
        std::min(view->sizeHintForColumn(DescriptionColumn),
            kDescriptionChars * fontMetrics().averageCharWidth()));
    int listWidth = frame + m_tools->verticalScrollBar()->sizeHint().width();
    for (int column = 0; column < ColumnCount; ++column) {
        listWidth += column == DescriptionColumn
            ? m_tools->columnWidth(column)
            : std::max(view->sizeHintForColumn(column), m_tools->header()->sectionSizeHint(column));
    }
    int rowsHeight = 0;
    const int rows = std::min(m_tools->topLevelItemCount(), kRowsShown);
    for (int row = 0; row < rows; ++row)
        rowsHeight += m_tools->sizeHintForRow(row);
    int listHeight = frame + m_tools->header()->sizeHint().height() + std::max(rowsHeight, 1);
    const int lineHeight = m_details->fontMetrics().lineSpacing();
    m_tools->setMinimumHeight(
        frame + m_tools->header()->sizeHint().height() + std::min(rowsHeight, 3 * lineHeight) + 4);
    const int detailsHeight = 2 * m_details->frameWidth() + kDetailLines * lineHeight
        + int(2 * m_details->document()->documentMargin());
    m_details->setFixedHeight(detailsHeight);

    const QRect screenArea = screen()->availableGeometry();
    const int width = std::clamp(
        listWidth + margins.left() + margins.right(), 560, std::max(560, screenArea.width() * 9 / 10));
    if (listWidth > width - margins.left() - margins.right())
        listHeight += m_tools->horizontalScrollBar()->sizeHint().height();
    const int textWidth = width - margins.left() - margins.right();
    const int spacing = layout()->spacing();
    const int height = margins.top() + m_summary->heightForWidth(textWidth) + spacing + listHeight + spacing
        + detailsHeight + spacing + m_import->sizeHint().height() + margins.bottom();
    resize(width, std::min(height, screenArea.height() * 9 / 10));
}

void ImportPreviewDialog::fill(const ImportPreview &preview)
{
    QList<QTreeWidgetItem *> items;
    items.reserve(preview.tools().size());
    for (const ImportedTool &tool : preview.tools()) {
        auto *item = new QTreeWidgetItem;
        item->setText(ToolColumn, u"T"_s + QString::number(tool.number));
        item->setData(ToolColumn, Qt::UserRole, tool.number);
        item->setText(ChangeColumn, changeText(tool.change));
        item->setText(DescriptionColumn, tool.description);
        const QStringList lines = tool.fields + tool.notes;
        item->setText(FieldsColumn, lines.join(u'\n'));
        item->setToolTip(FieldsColumn, lines.join(u'\n'));
        QStringList details {
            tr("T%1 (%2): %3").arg(QString::number(tool.number), changeText(tool.change), tool.description)
        };
        for (const QString &line : lines)
            details << u"• "_s + line;
        if (lines.isEmpty())
            details << tr("The table already has this tool as the library describes it.");
        item->setData(ToolColumn, kDetailsRole, details.join(u'\n'));
        if (tool.change != ImportChange::Unchanged) {
            QFont bold = item->font(ChangeColumn);
            bold.setBold(true);
            item->setFont(ChangeColumn, bold);
        }
        items.append(item);
    }
    m_tools->addTopLevelItems(items);
    if (!items.isEmpty())
        m_tools->setCurrentItem(items.front());
    showDetails(m_tools->currentItem());
}

} // namespace Toffee
