// SPDX-License-Identifier: GPL-3.0-or-later
// Tool life from a program: each tool's feed moves, lines and arcs, at their F; rapids apart.
#include <cmath>
#include <numbers>

#include <QTest>

#include "model/gcode/gcodeinterpreter.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

bool near(double a, double b)
{
    return std::fabs(a - b) < 1e-9;
}

} // namespace

class TestToolLife : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void countsEachToolsFeedMovesAtTheirFeed()
    {
        GCodeInterpreter fanuc(Dialect::Fanuc);
        const QByteArray program = "T1 M6\n"
                                   "G0 X0 Y0 Z5\n" // rapids: 5 mm from the start
                                   "G1 Z0 F300\n" // 5 mm at 300 mm/min: 1 s
                                   "X10 F600\n" // modal G1: 10 mm at 600: 1 s
                                   "G2 X10 Y0 I5 J0\n" // a whole circle of radius 5: 10π mm at 600
                                   "G0 Z5\n"
                                   "T2 M6\n"
                                   "G0 X0 Y0\n"
                                   "G1 Z0 F1200\n" // 5 mm at 1200: 0.25 s
                                   "G3 X10 Y10 R10\n" // a quarter circle of radius 10, counter-clockwise
                                   "G2 X20 Y0 Z-5 R-10 F100\n" // three quarters, with 5 mm of helix
                                   "M30\n";
        QVERIFY(fanuc.run(program));
        const auto &usage = fanuc.toolUsage();
        QCOMPARE(usage.size(), size_t(2));
        const double circle = 10.0 * std::numbers::pi;
        QVERIFY(near(usage.at(1).feedPathMm, 15.0 + circle));
        QVERIFY(near(usage.at(1).cuttingSeconds, 1.0 + 1.0 + circle / 600.0 * 60.0));
        const double quarter = 5.0 * std::numbers::pi;
        const double threeQuarters = std::hypot(15.0 * std::numbers::pi, 5.0);
        QVERIFY(near(usage.at(2).feedPathMm, 5.0 + quarter + threeQuarters));
        QVERIFY(near(usage.at(2).cuttingSeconds, 0.25 + quarter / 1200.0 * 60.0 + threeQuarters / 100.0 * 60.0));
        // Rapids: 5 (down to Z5 from 0), 5 (up), then X10 Y0 back to X0 Y0: 10.
        QVERIFY(near(fanuc.rapidDistance(), 20.0));
    }

    void takesTheArcsPlane()
    {
        GCodeInterpreter g18(Dialect::Fanuc);
        // G18: the arc is in Z-X, its centre given by K and I; half a circle of radius 5.
        QVERIFY(g18.run("T3 M6\nG18 G1 F60\nG2 X10 Z0 I5 K0\n"));
        QVERIFY(near(g18.toolUsage().at(3).feedPathMm, 5.0 * std::numbers::pi));
        QVERIFY(near(g18.toolUsage().at(3).cuttingSeconds, 5.0 * std::numbers::pi));
    }

    void refusesAnArcItCannotDraw()
    {
        GCodeInterpreter fanuc(Dialect::Fanuc);
        const auto tooShort = fanuc.run("G1 F100\nG2 X30 Y0 R10\n");
        QVERIFY(!tooShort);
        QVERIFY2(tooShort.error().message.contains(u"R10 cannot reach"_s), qPrintable(tooShort.error().message));
        QCOMPARE(tooShort.error().line, 2);
        GCodeInterpreter noCentre(Dialect::Fanuc);
        const auto none = noCentre.run("G2 X10 Y0 F100\n");
        QVERIFY(!none);
        QVERIFY(none.error().message.contains(u"centre (I J)"_s));
    }

    void keepsTheCarverasToolChangesAndAMoveBeforeAnyTool()
    {
        GCodeInterpreter carvera(Dialect::Carvera);
        QVERIFY(carvera.run("G1 X1 F60\nM6 T5\nG1 X3\n"));
        QVERIFY(near(carvera.toolUsage().at(-1).feedPathMm, 1.0)); // before any tool
        QVERIFY(near(carvera.toolUsage().at(5).cuttingSeconds, 2.0));
    }
};

QTEST_GUILESS_MAIN(TestToolLife)
#include "tst_toollife.moc"
