// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/aboutbox.h"

#include <QCoreApplication>
#include <QMessageBox>

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

struct About
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::About)
};

} // namespace

void showAbout(QWidget *parent)
{
    QMessageBox box(QMessageBox::Information, About::tr("About Toffee"),
        About::tr("Toffee %1").arg(QStringLiteral(TOFFEE_VERSION)), QMessageBox::Ok, parent);
    box.setObjectName(u"aboutBox"_s);
    box.setAccessibleName(About::tr("About Toffee"));
    box.setInformativeText(
        About::tr("The tool offset manager: a CNC machine's tool table and tool length offsets, "
                  "kept right.\n\nLicensed under the GNU General Public License, version 3 or "
                  "later."));
    box.exec();
}

} // namespace Toffee
