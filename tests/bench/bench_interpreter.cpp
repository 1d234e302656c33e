// SPDX-License-Identifier: GPL-3.0-or-later
// The G-code interpreter on a 1,000,000-line program per dialect: lines per second (best of 3).
//   toffee-bench-interpreter [LINES]
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTextStream>

#include "model/gcode/gcodeinterpreter.h"

using namespace Toffee;

namespace {

// Realistic blocks: N numbers, comments, motion with offsets switched on and off, offsets written now and
// then.
QByteArray program(Dialect dialect, int lines)
{
    QByteArray out;
    out.reserve(qsizetype(lines) * 28);
    int written = 0;
    if (dialect == Dialect::Aerotech) {
        out += "G44 X Y Z\nCutterCompensationSetOffsets([1, -2, 3])\n";
        written = 2;
    }
    const bool g10 = dialect == Dialect::Fanuc || dialect == Dialect::AllenBradley9;
    for (int i = 0; written < lines; ++i, ++written) {
        const QByteArray n = QByteArray::number(i % 1000);
        const QByteArray h = QByteArray::number(i % 10 + 1);
        QByteArray block;
        switch (i % 8) {
        case 0:
            if (dialect == Dialect::Aerotech)
                block = "G143 G1 X" + n + " Y5";
            else if (dialect == Dialect::LinuxCnc)
                block = "G43 H" + h;
            else if (dialect == Dialect::Fagor8055M)
                block = "D" + h + " G43";
            else if (dialect == Dialect::Carvera)
                block = "M493.3 Z-" + h;
            else
                block = "G43 H" + h + " G0 Z50";
            break;
        case 1:
            block = "N" + QByteArray::number(i) + " G1 X" + QByteArray::number((i % 1000) * 0.5, 'f', 3)
                + " Y-12.5 F800";
            break;
        case 2:
            block = "(finishing pass " + n + ")";
            break;
        case 3:
            block = "G1 Z" + QByteArray::number(-(i % 1000) * 0.01, 'f', 3);
            break;
        case 4:
            block = g10 ? "G90 G10 L11 P" + h + " R-0.01" : QByteArray("G1 X10 Y10");
            break;
        case 5:
            block = "G0 X" + n + " Y" + n + " Z5.000";
            break;
        case 6:
            if (dialect == Dialect::Aerotech)
                block = "G149 G1 X0 Y0";
            else if (dialect == Dialect::Fagor8055M)
                block = "G44";
            else if (dialect == Dialect::Carvera)
                block = "G0 X0";
            else
                block = "G49";
            break;
        default:
            block = "G1 X1.5 Y2.5 Z-0.25 ; a comment";
        }
        out += block;
        out += '\n';
    }
    return out;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const int lines = argc > 1 ? QByteArray(argv[1]).toInt() : 1000000;
    QTextStream out(stdout);
    out << "| dialect | lines | best of 3 (ms) | lines per second |\n|---|---:|---:|---:|\n";
    for (Dialect dialect : { Dialect::Fanuc, Dialect::AllenBradley9, Dialect::Fagor8055M, Dialect::LinuxCnc,
             Dialect::Aerotech, Dialect::Carvera }) {
        const QByteArray text = program(dialect, lines);
        const qint64 count = text.count('\n');
        OffsetTable offsets;
        for (int t = 1; t <= 10; ++t)
            offsets[t] = { 50.0 + t, -0.01 * t, 3.0, 0.0 };
        double best = 1e300;
        for (int run = 0; run < 3; ++run) {
            GCodeInterpreter interpreter(dialect, offsets);
            interpreter.setRecordMoves(false);
            QElapsedTimer timer;
            timer.start();
            const auto result = interpreter.run(text);
            const double ms = double(timer.nsecsElapsed()) / 1e6;
            if (!result.ok()) {
                QTextStream(stderr) << dialectInfo(dialect).key << ": " << result.error().text() << '\n';
                return 1;
            }
            best = std::min(best, ms);
        }
        out << "| " << dialectInfo(dialect).key << " | " << count << " | " << QString::number(best, 'f', 1)
            << " | " << QString::number(double(count) / best * 1000.0, 'f', 0) << " |\n";
        out.flush();
    }
    return 0;
}
