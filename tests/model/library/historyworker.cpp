// SPDX-License-Identifier: GPL-3.0-or-later
// A second program writing to a library, for tst_library: `historyworker LIBRARY MACHINE TOOL COUNT` appends
// COUNT probe events one transaction at a time and prints each id once its transaction has committed.
#include <cstdio>

#include <QCoreApplication>

#include "model/library/library.h"

using namespace Toffee;

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    if (args.size() != 5)
        return 2;
    auto library = Library::open({ args.at(1) }, Library::Options { 10000 });
    if (!library) {
        std::fprintf(stderr, "%s\n", qPrintable(library.error().message));
        return 1;
    }
    const int tool = args.at(3).toInt();
    const int count = args.at(4).toInt();
    for (int i = 0; i < count; ++i) {
        HistoryEvent e;
        e.id = HistoryEvent::newId();
        e.machine = args.at(2);
        e.tool = tool;
        e.at = QDateTime::currentDateTimeUtc();
        e.kind = EventKind::Probe;
        e.tlo = -i * 0.001;
        if (auto written = library.value()->append({ e }); !written) {
            std::fprintf(stderr, "%s\n", qPrintable(written.error().message));
            return 1;
        }
        std::printf("%s\n", qPrintable(e.id));
        std::fflush(stdout);
    }
    return 0;
}
