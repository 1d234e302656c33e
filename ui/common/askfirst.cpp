// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/common/askfirst.h"

#include <QPushButton>

namespace Toffee {

bool askFirst(QWidget *parent, const AskFirst &ask)
{
    QMessageBox box(ask.icon, ask.title, ask.text, QMessageBox::Cancel, parent);
    if (!ask.boxName.isEmpty())
        box.setObjectName(ask.boxName);
    box.setInformativeText(ask.details);
    QPushButton *accept = box.addButton(ask.accept, QMessageBox::AcceptRole);
    accept->setObjectName(ask.acceptName);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    return box.clickedButton() == accept;
}

} // namespace Toffee
