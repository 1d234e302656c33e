// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-emulator will serve the Carvera emulator on a pseudo-terminal (issue 3). Until the emulator exists
// it says so and fails, rather than pretending to be a machine.
#include <QCoreApplication>
#include <QTextStream>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QTextStream(stderr) << "toffee-emulator: the machine emulator is not built yet; nothing to serve.\n";
    return 2;
}
