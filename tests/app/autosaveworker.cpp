// SPDX-License-Identifier: GPL-3.0-or-later
// For tst_autosaverecovery: opens TABLE and edits it without end, tool after tool (T1000, T1001, ...), with
// AutoSave writing its copy into FOLDER as the window does, until it is killed.
//   toffee-autosave-worker FOLDER TABLE
#include <cstdio>

#include <QCoreApplication>

#include "model/document/autosave.h"
#include "model/document/tooldocument.h"
#include "tests/support/testtables.h"

using namespace Toffee;

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    if (argc != 3)
        return 2;
    ToolDocument document;
    if (!document.open(QString::fromLocal8Bit(argv[2])).ok())
        return 2;
    AutoSave autoSave(&document, QString::fromLocal8Bit(argv[1]));
    autoSave.setDelay(0);
    QObject::connect(&autoSave, &AutoSave::failed, &app, [](const QString &message) {
        std::fprintf(stderr, "%s\n", qPrintable(message));
        std::exit(1);
    });
    std::puts("editing");
    std::fflush(stdout);
    for (int number = 1000;; ++number) {
        if (!document.addTool(Test::tool(number, number / 100.0)).ok())
            return 1;
        QCoreApplication::processEvents(); // the autosave timer fires here, as in the window's event loop
    }
}
