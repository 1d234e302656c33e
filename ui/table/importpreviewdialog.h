// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QLabel;
class QPlainTextEdit;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace Toffee {

class ImportPreview;

// File ▸ Import of a CAM library: each of its tools, new, changed (and how) or unchanged, before anything
// changes. The selected tool's changes and notes are shown whole below the list, for the keyboard and screen
// readers as much as for the eye. Import applies the merge; Cancel leaves the table as it was.
class ImportPreviewDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ImportPreviewDialog)

public:
    enum Column { ToolColumn, ChangeColumn, DescriptionColumn, FieldsColumn, ColumnCount };

    ImportPreviewDialog(const ImportPreview &preview, const QString &source, const QString &formatName,
        QWidget *parent = nullptr);

private:
    void fill(const ImportPreview &preview);
    void showDetails(const QTreeWidgetItem *item);
    void fitToContents();

    QLabel *m_summary;
    QTreeWidget *m_tools;
    QPlainTextEdit *m_details;
    QPushButton *m_import;
    QPushButton *m_cancel;
};

} // namespace Toffee
