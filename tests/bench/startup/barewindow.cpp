// SPDX-License-Identifier: GPL-3.0-or-later
// The yardstick of toffee-bench-startup: a bare Qt 6 main window, built with the same compiler, flags and Qt
// as Toffee, so that what Toffee adds to start-up is measured side by side and not against a remembered
// number.
#include <QApplication>
#include <QMainWindow>

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QMainWindow window;
    // Toffee's own first size: the same backing store, the same pixels for the server to map.
    window.resize(1280, 720);
    window.show();
    return QApplication::exec();
}
