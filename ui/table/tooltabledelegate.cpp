// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/table/tooltabledelegate.h"

#include <QLineEdit>

#include "model/numberformat.h"
#include "model/toolvalidation.h"

namespace Toffee {

QWidget *ToolTableDelegate::createEditor(
    QWidget *parent, const QStyleOptionViewItem &, const QModelIndex &index) const
{
    auto *editor = new QLineEdit(parent);
    editor->setFrame(false);
    editor->setObjectName(QStringLiteral("cellEditor"));
    editor->setAccessibleName(index.model()->headerData(index.column(), Qt::Horizontal).toString());
    return editor;
}

void ToolTableDelegate::setEditorData(QWidget *editor, const QModelIndex &index) const
{
    const QVariant value = index.data(Qt::EditRole);
    auto *line = static_cast<QLineEdit *>(editor);
    line->setText(value.typeId() == QMetaType::Double ? formatNumber(value.toDouble()) : value.toString());
    line->selectAll();
}

void ToolTableDelegate::setModelData(
    QWidget *editor, QAbstractItemModel *model, const QModelIndex &index) const
{
    model->setData(index, static_cast<QLineEdit *>(editor)->text(), Qt::EditRole);
}

} // namespace Toffee
