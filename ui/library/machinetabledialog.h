// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QListWidget;

namespace Toffee {

// File ▸ Open Machine Table…: the machines whose tool table the library holds, to choose one.
class MachineTableDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(MachineTableDialog)

public:
    MachineTableDialog(const QStringList &machines, const QString &libraryName, QWidget *parent = nullptr);

    [[nodiscard]] QString machine() const;
    void setMachine(const QString &machine);

private:
    QListWidget *m_list;
};

} // namespace Toffee
