// SPDX-License-Identifier: GPL-3.0-or-later
// For tst_crashsafesave: saves table A and table B into PATH, one after the other, until it is killed.
//   toffee-save-worker PATH
#include <cstdio>

#include <QCoreApplication>

#include "model/formats/tablefile.h"
#include "tests/support/testtables.h"

using namespace Toffee;

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    if (argc != 2)
        return 2;
    const QString path = QString::fromLocal8Bit(argv[1]);
    const auto format = formatForPath(path);
    if (!format)
        return 2;
    const ToolTable tables[] = { Test::generatedTable(3000, 1), Test::generatedTable(3000, 2) };
    std::puts("saving");
    std::fflush(stdout);
    for (int i = 0;; ++i) {
        if (!saveTableFile(path, tables[i % 2], *format).ok())
            return 1;
    }
}
