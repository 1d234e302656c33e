// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

#include "ui/common/appsettings.h"

class QLineEdit;

namespace Toffee {

// Machine ▸ LinuxCNC Access…: how Toffee reaches a LinuxCNC beyond its address, kept for the machine on this
// computer: the INI it runs (its tool table's file; found by itself when LinuxCNC runs on this computer) and
// linuxcncrsh's enable password (empty: LinuxCNC's own default), typed hidden and never shown again.
class LinuxCncAccessDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LinuxCncAccessDialog)

public:
    LinuxCncAccessDialog(
        const QString &machine, const AppSettings::LinuxCncAccess &access, QWidget *parent = nullptr);
    [[nodiscard]] AppSettings::LinuxCncAccess access() const;

private:
    QLineEdit *m_ini;
    QLineEdit *m_password;
};

} // namespace Toffee
