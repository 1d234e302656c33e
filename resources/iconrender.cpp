// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-render-icon SVG SIZE PNG: the application icon at one of the hicolor theme's sizes, made at build
// time from the one SVG (Qt's SVG image plugin, which the window needs anyway).
#include <cstdio>

#include <QGuiApplication>
#include <QImage>
#include <QImageReader>

int main(int argc, char *argv[])
{
    QGuiApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    if (args.size() != 4) {
        std::fprintf(stderr, "usage: toffee-render-icon SVG SIZE PNG\n");
        return 2;
    }
    const int size = args.at(2).toInt();
    QImageReader reader(args.at(1));
    reader.setScaledSize(QSize(size, size));
    const QImage image = reader.read();
    if (image.isNull() || !image.save(args.at(3), "PNG")) {
        std::fprintf(
            stderr, "toffee-render-icon: %s: %s\n", qPrintable(args.at(1)), qPrintable(reader.errorString()));
        return 1;
    }
    return 0;
}
