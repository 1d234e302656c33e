// SPDX-License-Identifier: GPL-3.0-or-later
// The History panel's chart of one tool with 10,000 measurements: read, built and drawn (offscreen), median
// of 7.
//   QT_QPA_PLATFORM=offscreen toffee-bench-historychart [POINTS]
#include <algorithm>
#include <cstdio>

#include <QApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>

#include "model/library/historyrecorder.h"
#include "ui/history/historydock.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    const int points = argc > 1 ? QByteArray(argv[1]).toInt() : 10000;
    QTemporaryDir dir;
    HistoryRecorder recorder;
    if (!recorder.setLocation({ dir.filePath(u"library.sqlite"_s) }))
        return 1;
    const QDateTime start(QDate(2026, 1, 1), QTime(0, 0), Qt::UTC);
    QList<HistoryEvent> events;
    for (int i = 0; i < points; ++i) {
        HistoryEvent e;
        e.id = HistoryEvent::newId();
        e.machine = u"Carvera"_s;
        e.tool = 3;
        e.at = start.addSecs(qint64(i) * 600);
        e.kind = i % 20 == 19 ? EventKind::BreakTest : EventKind::Probe;
        e.tlo = -20.0 - i * 0.00001 - (i % 7) * 0.001;
        if (e.kind == EventKind::BreakTest) {
            e.newTlo = e.tlo;
            e.failed = i % 1000 == 999;
        }
        events.append(e);
    }
    (void)recorder.library()->append(events);
    HistoryDock dock(&recorder);
    dock.resize(1000, 600);
    dock.show(); // a panel not seen draws no chart
    QApplication::processEvents();
    QList<double> times;
    for (int run = 0; run < 7; ++run) {
        QElapsedTimer clock;
        clock.start();
        dock.showTool(3, u"Carvera"_s, 0.1);
        const QPixmap drawn = dock.grab();
        times.append(double(clock.nsecsElapsed()) / 1e6);
        if (drawn.isNull() || !dock.chartView()) {
            std::fprintf(stderr, "toffee-bench-historychart: no chart was drawn\n");
            return 1;
        }
        dock.showTool(-1, {}, 0.1);
    }
    std::sort(times.begin(), times.end());
    std::printf("| the History chart of one tool with %d measurements: read, built and drawn | %.1f ms "
                "(median of 7) |\n",
        points, times.at(times.size() / 2));
    return 0;
}
