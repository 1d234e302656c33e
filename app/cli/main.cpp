// SPDX-License-Identifier: GPL-3.0-or-later
#include <csignal>
#include <cstdio>

#include <QCoreApplication>
#include <QTextStream>

#include "app/cli/cli.h"
#include "app/cli/interrupt.h"

using namespace Qt::StringLiterals;

int main(int argc, char *argv[])
{
    // Over a file-size limit (ulimit -f) a write then fails with "File too large", which a save reports like
    // a full disk with the old file whole, instead of the process being killed in the middle of it.
    std::signal(SIGXFSZ, SIG_IGN);
    Toffee::Cli::installInterruptHandlers();
    QCoreApplication app(argc, argv);
    QCoreApplication::setOrganizationName(u"Toffee"_s);
    QCoreApplication::setApplicationName(u"toffee-cli"_s);
    QTextStream out(stdout);
    QTextStream err(stderr);
    QStringList arguments = QCoreApplication::arguments();
    arguments.removeFirst();
    return Toffee::Cli::run(arguments, out, err);
}
