// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/table/exportdialog.h"

#include <QClipboard>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGuiApplication>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "model/formats/fileio.h"
#include "model/gcode/dialect.h"
#include "ui/common/appearance.h"
#include "ui/common/appsettings.h"

using namespace Qt::StringLiterals;

namespace Toffee {

ExportDialog::ExportDialog(const ToolTable &table, QWidget *parent)
    : QDialog(parent)
    , m_table(table)
    , m_dialect(new QComboBox(this))
    , m_tool(new QComboBox(this))
    , m_preview(new QPlainTextEdit(this))
    , m_problem(new QLabel(this))
    , m_save(new QPushButton(tr("Save…"), this))
    , m_copy(new QPushButton(tr("Copy"), this))
{
    setObjectName(u"exportDialog"_s);
    setWindowTitle(tr("Export for Controller"));
    m_dialect->setObjectName(u"exportDialectCombo"_s);
    m_dialect->setAccessibleName(tr("Controller"));
    for (const DialectInfo &info : dialects())
        m_dialect->addItem(info.name, info.key);
    m_tool->setObjectName(u"exportToolCombo"_s);
    m_tool->setAccessibleName(tr("Tool"));
    m_tool->addItem(tr("All tools"), -1);
    for (const Tool &t : table.tools())
        m_tool->addItem(u"T"_s + QString::number(t.number) + u"  "_s + t.description, t.number);
    m_preview->setObjectName(u"exportPreview"_s);
    m_preview->setAccessibleName(tr("The program that will be written"));
    m_preview->setReadOnly(true);
    m_preview->setLineWrapMode(QPlainTextEdit::NoWrap);
    useMonospace(m_preview);
    m_problem->setObjectName(u"exportProblem"_s);
    m_problem->setWordWrap(true);
    m_save->setObjectName(u"exportSaveButton"_s);
    m_copy->setObjectName(u"exportCopyButton"_s);

    auto *form = new QFormLayout;
    form->addRow(tr("Controller:"), m_dialect);
    form->addRow(tr("Tool:"), m_tool);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_copy, QDialogButtonBox::ActionRole);
    buttons->addButton(m_save, QDialogButtonBox::AcceptRole);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_preview, 1);
    layout->addWidget(m_problem);
    layout->addWidget(buttons);
    resize(640, 520);

    connect(m_dialect, &QComboBox::currentIndexChanged, this, &ExportDialog::updatePreview);
    connect(m_tool, &QComboBox::currentIndexChanged, this, &ExportDialog::updatePreview);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_save, &QPushButton::clicked, this, &ExportDialog::save);
    connect(
        m_copy, &QPushButton::clicked, this, [this] { QGuiApplication::clipboard()->setText(program()); });
    selectDialect(AppSettings().exportDialect());
    updatePreview();
}

void ExportDialog::selectDialect(const QString &key)
{
    const int index = m_dialect->findData(key);
    if (index >= 0)
        m_dialect->setCurrentIndex(index);
}

QString ExportDialog::program() const
{
    return m_preview->toPlainText();
}

void ExportDialog::updatePreview()
{
    const auto dialect = dialectFromKey(m_dialect->currentData().toString());
    if (!dialect)
        return;
    AppSettings().setExportDialect(m_dialect->currentData().toString());
    const int tool = m_tool->currentData().toInt();
    auto program = exportProgram(m_table, *dialect, tool < 0 ? std::nullopt : std::optional<int>(tool));
    m_preview->setPlainText(program ? program.value() : QString());
    m_problem->setText(program ? QString() : program.error().message);
    m_save->setEnabled(program.ok());
    m_copy->setEnabled(program.ok());
}

bool ExportDialog::saveTo(const QString &path)
{
    const QByteArray data = program().toUtf8();
    if (auto written = writeFileAtomically(path, [&data](const FileSink &sink) { return sink(data); });
        !written) {
        QMessageBox::warning(this, tr("Cannot export"), written.error().text());
        return false;
    }
    return true;
}

void ExportDialog::save()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save the Offset Program"),
        AppSettings().lastDirectory(), tr("G-code programs (*.nc *.ngc *.gcode *.pgm);;All files (*)"));
    if (!path.isEmpty() && saveTo(path))
        accept();
}

} // namespace Toffee
