// SPDX-License-Identifier: GPL-3.0-or-later
#include <QApplication>
#include <QCommandLineParser>

#include "mainwindow.h"

using namespace Qt::StringLiterals;

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(u"Toffee"_s);
    QApplication::setApplicationName(u"Toffee"_s);
    QApplication::setApplicationDisplayName(u"Toffee"_s);
    QApplication::setApplicationVersion(QStringLiteral(TOFFEE_VERSION));
    QApplication::setDesktopFileName(u"org.toffee.Toffee"_s);

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "Toffee, the tool offset manager."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        u"table"_s, QApplication::translate("main", "A tool table to open."), u"[table]"_s);
    parser.process(app);

    Toffee::MainWindow window;
    if (!parser.positionalArguments().isEmpty())
        window.openFile(parser.positionalArguments().constFirst());
    window.show();
    return QApplication::exec();
}
