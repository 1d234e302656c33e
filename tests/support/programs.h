// SPDX-License-Identifier: GPL-3.0-or-later
// A CAM program of any length, for the streaming tests and the benchmarks: tool changes now and then, rapids,
// plunges, feeds, arcs and comments, as a post-processor writes them.
#pragma once

#include <QFile>
#include <QString>

namespace Toffee::Test {

// Writes `lines` lines of a Carvera program (FANUC-like with `g43`: G43 H after each change) to `path`.
inline bool writeCamProgram(const QString &path, qint64 lines, bool g43 = false)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return false;
    QByteArray chunk;
    chunk.reserve(1 << 20);
    chunk += "(a CAM program written by the tests)\nG21 G90 G17 G94\n";
    qint64 written = 2;
    for (qint64 i = 0; written < lines - 1; ++i, ++written) {
        // One place for the eight blocks of a pass, so that the arcs join the lines they start from.
        const qint64 pass = i / 8;
        const QByteArray x = QByteArray::number(double(pass % 1000) * 0.05, 'f', 3);
        const QByteArray y = QByteArray::number(double(pass % 777) * 0.05, 'f', 3);
        if (i % 200000 == 0) {
            const QByteArray t = QByteArray::number(i / 200000 % 6 + 1);
            if (g43)
                chunk += "T" + t + " M6\nG43 H" + t + " G0 Z15\n";
            else
                chunk += "M6 T" + t + "\nM3 S12000\n";
            ++written;
            continue;
        }
        switch (i % 8) {
        case 0:
            chunk += "G0 X" + x + " Y" + y + " Z5\n";
            break;
        case 1:
            chunk += "G1 Z-" + QByteArray::number(double(i % 100) * 0.01, 'f', 3) + " F300\n";
            break;
        case 2:
            chunk += "G1 X" + x + " Y-12.5 F800\n";
            break;
        case 3:
            chunk += "G2 X" + QByteArray::number(double(pass % 1000) * 0.05 + 5.0, 'f', 3) + " Y-12.5 R2.5\n";
            break;
        case 4:
            chunk += "(pass " + QByteArray::number(i) + ")\n";
            break;
        case 5:
            chunk += "G3 X" + x + " Y-12.5 I-2.5 J0\n";
            break;
        default:
            chunk += "G1 X1.5 Y2.5 Z-0.25\n";
        }
        if (chunk.size() > (1 << 20) - 256) {
            if (file.write(chunk) != chunk.size())
                return false;
            chunk.clear();
        }
    }
    chunk += "M30\n";
    return file.write(chunk) == chunk.size() && file.flush();
}

} // namespace Toffee::Test
