// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/connection/linuxcncaccessdialog.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

using namespace Qt::StringLiterals;

namespace Toffee {

LinuxCncAccessDialog::LinuxCncAccessDialog(
    const QString &machine, const AppSettings::LinuxCncAccess &access, QWidget *parent)
    : QDialog(parent)
    , m_ini(new QLineEdit(access.ini))
    , m_password(new QLineEdit(access.enablePassword))
{
    setObjectName(u"linuxCncAccessDialog"_s);
    setWindowTitle(tr("LinuxCNC Access for %1").arg(machine));
    m_ini->setObjectName(u"linuxCncIni"_s);
    m_ini->setPlaceholderText(tr("found by itself when LinuxCNC runs on this computer"));
    m_ini->setClearButtonEnabled(true);
    m_password->setObjectName(u"linuxCncPassword"_s);
    m_password->setEchoMode(QLineEdit::Password);
    m_password->setPlaceholderText(tr("LinuxCNC's default (EMCTOO)"));
    auto *browse = new QPushButton(tr("&Browse…"));
    browse->setObjectName(u"linuxCncIniBrowse"_s);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("LinuxCNC's INI"), m_ini->text(), tr("LinuxCNC configurations (*.ini);;All files (*)"));
        if (!path.isEmpty())
            m_ini->setText(path);
    });
    auto *iniRow = new QHBoxLayout;
    iniRow->addWidget(m_ini, 1);
    iniRow->addWidget(browse);
    auto *explain = new QLabel(
        tr("linuxcncrsh cannot read LinuxCNC's tool table, so Toffee reads the file its INI names ([EMCIO] "
           "TOOL_TABLE) for push, pull and the job check. Its enable password lets Toffee take control "
           "(linuxcncrsh --enablepw); it is kept on this computer and never shown or logged."));
    explain->setWordWrap(true);
    auto *form = new QFormLayout;
    // A row of a field and its button: the label is given its buddy, so that Alt+I reaches the field.
    auto *iniLabel = new QLabel(tr("&INI file:"));
    iniLabel->setBuddy(m_ini);
    form->addRow(iniLabel, iniRow);
    form->addRow(tr("&Enable password:"), m_password);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(explain);
    layout->addLayout(form);
    layout->addWidget(buttons);
    resize(560, sizeHint().height());
}

AppSettings::LinuxCncAccess LinuxCncAccessDialog::access() const
{
    return { m_ini->text().trimmed(), m_password->text() };
}

} // namespace Toffee
