// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/library/machinetabledialog.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

namespace Toffee {

MachineTableDialog::MachineTableDialog(
    const QStringList &machines, const QString &libraryName, QWidget *parent)
    : QDialog(parent)
    , m_list(new QListWidget(this))
{
    setObjectName(u"machineTableDialog"_s);
    setAccessibleName(tr("Open a machine's table"));
    setWindowTitle(tr("Open Machine Table"));
    auto *where = new QLabel(tr("Machine tables in %1:").arg(libraryName), this);
    where->setObjectName(u"machineTableLibraryLabel"_s);
    where->setAccessibleName(tr("Library"));
    where->setWordWrap(true);
    where->setTextFormat(Qt::PlainText);
    m_list->setObjectName(u"machineTableList"_s);
    m_list->setAccessibleName(tr("Machines"));
    m_list->addItems(machines);
    m_list->setCurrentRow(0);
    where->setBuddy(m_list);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel, this);
    buttons->setObjectName(u"machineTableButtons"_s);
    buttons->setAccessibleName(tr("Open or cancel"));
    buttons->button(QDialogButtonBox::Open)->setObjectName(u"machineTableOpenButton"_s);
    buttons->button(QDialogButtonBox::Open)->setAccessibleName(tr("Open the machine's table"));
    buttons->button(QDialogButtonBox::Cancel)->setAccessibleName(tr("Cancel"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_list, &QListWidget::itemActivated, this, &QDialog::accept);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(where);
    layout->addWidget(m_list, 1);
    layout->addWidget(buttons);
    // Wide enough for its title and a library's name on a line (a socket's folder has no space to wrap at).
    setMinimumWidth(std::max(420, fontMetrics().horizontalAdvance(where->text()) / 2 + 60));
}

QString MachineTableDialog::machine() const
{
    return m_list->currentItem() ? m_list->currentItem()->text() : QString();
}

void MachineTableDialog::setMachine(const QString &machine)
{
    const auto found = m_list->findItems(machine, Qt::MatchExactly);
    if (!found.isEmpty())
        m_list->setCurrentItem(found.front());
}

} // namespace Toffee
