// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/history/historysettingsdialog.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QSysInfo>

#include "model/library/library.h"
#include "ui/common/appsettings.h"

using namespace Qt::StringLiterals;

namespace Toffee {

HistorySettingsDialog::HistorySettingsDialog(QWidget *parent, const LibraryLocation &current)
    : QDialog(parent)
    , m_path(new QLineEdit(this))
    , m_machine(new QLineEdit(this))
    , m_station(new QLineEdit(this))
    , m_stale(new QSpinBox(this))
{
    setWindowTitle(tr("History Library"));
    setObjectName(u"historySettingsDialog"_s);
    const AppSettings settings;
    // The library the window was asked to use (--library, or a shared one it could not open and says so)
    // comes first: OK with it unchanged keeps the window where it is.
    const auto chosen = current.isSet() ? Result<LibraryLocation>(current)
                                        : LibraryLocation::parse(settings.libraryLocation());
    const LibraryLocation shown = chosen ? chosen.value() : LibraryLocation::standard();
    m_path->setText(shown.isShared() ? shown.text() : shown.path);
    m_path->setObjectName(u"libraryPathEdit"_s);
    m_path->setAccessibleName(tr("Library file or URL"));
    m_path->setPlaceholderText(tr("A file, or postgresql://user@server/database"));
    m_path->setToolTip(tr("An SQLite file for this computer, or a shared PostgreSQL database as "
                          "postgresql://user@host:port/dbname?sslmode=require. The password goes in the "
                          "PostgreSQL password file (~/.pgpass), never in the URL."));
    m_path->setMinimumWidth(420);
    // Empty: the machine is called after its kind once connected (Carvera, grblHAL, Emulator).
    m_machine->setText(settings.chosenMachineName());
    m_machine->setObjectName(u"machineNameEdit"_s);
    m_machine->setAccessibleName(tr("Machine name"));
    m_machine->setPlaceholderText(tr("Its kind: Carvera, grblHAL or Emulator"));
    m_machine->setToolTip(tr("The name this machine's history, reference and tool setter are kept under. "
                             "Left empty, the machine is called after its kind. A name stands for one "
                             "machine: another machine under it is asked about."));
    m_station->setText(settings.stationName());
    m_station->setObjectName(u"stationNameEdit"_s);
    m_station->setAccessibleName(tr("This station's name"));
    m_station->setPlaceholderText(QSysInfo::machineHostName());
    m_station->setToolTip(
        tr("Who this computer's changes are from in a shared library, as the other stations "
           "see it; empty: the computer's name."));
    m_stale->setRange(1, 365);
    m_stale->setSuffix(tr(" days"));
    m_stale->setValue(settings.staleAfterDays());
    m_stale->setObjectName(u"staleDaysSpin"_s);
    m_stale->setAccessibleName(tr("Stale after"));

    auto *browse = new QPushButton(tr("Browse…"), this);
    browse->setObjectName(u"libraryBrowseButton"_s);
    browse->setAccessibleName(tr("Choose a library file"));
    connect(browse, &QPushButton::clicked, this, &HistorySettingsDialog::browse);
    auto *pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(browse);
    auto *form = new QFormLayout;
    form->addRow(tr("Library file or URL:"), pathRow);
    form->addRow(tr("This machine's name:"), m_machine);
    form->addRow(tr("This station's name:"), m_station);
    form->addRow(tr("A measurement is stale after:"), m_stale);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
    // Tab follows the rows: Browse… beside the library, before the machine's name.
    setTabOrder(m_path, browse);
    setTabOrder(browse, m_machine);
    setTabOrder(m_machine, m_station);
    setTabOrder(m_station, m_stale);
}

QString HistorySettingsDialog::location() const
{
    const auto location = LibraryLocation::parse(m_path->text());
    return location ? location.value().text() : m_path->text().trimmed();
}

QString HistorySettingsDialog::machineName() const
{
    return m_machine->text().trimmed();
}

QString HistorySettingsDialog::stationName() const
{
    return m_station->text().simplified();
}

int HistorySettingsDialog::staleAfterDays() const
{
    return m_stale->value();
}

void HistorySettingsDialog::browse()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("History Library"), m_path->text(),
        tr("SQLite libraries (*.sqlite *.db);;All files (*)"), nullptr, QFileDialog::DontConfirmOverwrite);
    if (!path.isEmpty())
        m_path->setText(path);
}

// Checked before it is taken: a library that does not open stays out of the settings.
void HistorySettingsDialog::accept()
{
    const auto location = LibraryLocation::parse(m_path->text());
    auto opened
        = location ? Library::open(location.value()) : Result<std::unique_ptr<Library>>(location.error());
    if (!opened) {
        QMessageBox::warning(
            this, tr("History Library"), tr("This library cannot be used: %1").arg(opened.error().message));
        return;
    }
    QDialog::accept();
}

} // namespace Toffee
