// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace Toffee {

class ToolTable;

// "Export for Controller…": the program that loads the table into the chosen controller, previewed before it
// is saved or copied.
class ExportDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ExportDialog)

public:
    ExportDialog(const ToolTable &table, QWidget *parent = nullptr);

    [[nodiscard]] QString program() const;
    void selectDialect(const QString &key);
    // Writes the previewed program to `path` through QSaveFile; false with a message box when it fails.
    bool saveTo(const QString &path);

private:
    void updatePreview();
    void save();

    const ToolTable &m_table;
    QComboBox *m_dialect;
    QComboBox *m_tool;
    QPlainTextEdit *m_preview;
    QLabel *m_problem;
    QPushButton *m_save;
    QPushButton *m_copy;
};

} // namespace Toffee
