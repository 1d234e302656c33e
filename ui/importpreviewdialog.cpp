// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/importpreviewdialog.h"

#include <QDialogButtonBox>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "model/camimport/importpreview.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

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
    m_summary->setText(preview.changesAnything()
            ? counts + u' '
                + tr("Only descriptions, radii and the CAM's line in the notes change; measured TLOs, wear, "
                     "pockets and your notes stay as they are.")
            : counts + u' ' + tr("The table already has these tools as the library describes them."));
    m_tools->setObjectName(u"importToolList"_s);
    m_tools->setAccessibleName(tr("Tools in the library"));
    m_tools->setRootIsDecorated(false);
    m_tools->setAlternatingRowColors(true);
    m_tools->setHeaderLabels({ tr("Tool"), tr("Import"), tr("Description"), tr("Changes") });
    m_tools->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_tools->header()->setStretchLastSection(true);
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
    layout->addWidget(buttons);
    setTabOrder(m_tools, m_import);
    setTabOrder(m_import, m_cancel);
    m_tools->setFocus();
    resize(720, 440);
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
        item->setText(FieldsColumn, tool.fields.join(u"; "_s));
        item->setToolTip(FieldsColumn, tool.fields.join(u'\n'));
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
}

} // namespace Toffee
