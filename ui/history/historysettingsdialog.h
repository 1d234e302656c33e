// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

#include "model/library/librarylocation.h"

class QLineEdit;
class QSpinBox;

namespace Toffee {

// Machine ▸ History Library…: which library the window records into (a file, or a shared PostgreSQL URL),
// this machine's name in it, and after how many days a measurement is stale. A library that does not open is
// said so, and the dialog stays.
class HistorySettingsDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(HistorySettingsDialog)

public:
    // Shows `current`, the library the window was asked to use, when set; else the one in the settings.
    explicit HistorySettingsDialog(QWidget *parent = nullptr, const LibraryLocation &current = {});

    [[nodiscard]] QString location() const; // "sqlite:PATH" or "postgresql://…"
    [[nodiscard]] QString machineName() const;
    [[nodiscard]] QString stationName() const;
    [[nodiscard]] int staleAfterDays() const;

    void accept() override;

private:
    void browse();

    QLineEdit *m_path;
    QLineEdit *m_machine;
    QLineEdit *m_station;
    QSpinBox *m_stale;
};

} // namespace Toffee
