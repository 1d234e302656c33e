// SPDX-License-Identifier: GPL-3.0-or-later
// The yardstick of toffee-bench-startup: a bare Qt 6 main window, built with the same compiler, flags and Qt
// as Toffee, so that what Toffee adds to start-up is measured side by side and not against a remembered
// number.
// With --label it shows one line of text as well: the least any window with words in it pays (the font
// configuration, a font file, the text engine), told beside the bare window's figures.
#include <QApplication>
#include <QLabel>
#include <QMainWindow>

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QMainWindow window;
    if (QApplication::arguments().contains(QStringLiteral("--label")))
        window.setCentralWidget(new QLabel(QStringLiteral("Toffee"), &window));
    // Toffee's own first size: the same backing store, the same pixels for the server to map.
    window.resize(1280, 720);
    window.show();
    return QApplication::exec();
}
