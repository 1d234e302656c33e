// SPDX-License-Identifier: GPL-3.0-or-later
// Canned drilling cycles (G73, G81-G89) and the work offsets G54-G59, as a CAM post writes them.
#include <cmath>

#include <QTest>

#include "model/gcode/gcodeinterpreter.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

bool near(double a, double b)
{
    return std::fabs(a - b) < 1e-9;
}

// Runs `program`; every line must run.
bool runAll(GCodeInterpreter &interpreter, const QByteArray &program)
{
    int line = 0;
    for (const QByteArray &text : program.split('\n')) {
        if (auto r = interpreter.runLine(text, ++line); !r) {
            qWarning("%s", qPrintable(r.error().text()));
            return false;
        }
    }
    return true;
}

} // namespace

class TestCyclesAndOffsets : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void drillsEachHoleToItsDepth()
    {
        GCodeInterpreter fanuc(Dialect::Fanuc, { { 1, { 50.0, 0.0, 3.0, 0.0 } } });
        QVERIFY(runAll(fanuc, "T1 M6\nG43 H1 G0 X0 Y0 Z10\nG98 G81 X5 Y0 Z-6 R2 F120"));
        // To the hole at rapid (5), down to R (8), 8 mm at feed to -6, back to the initial 10 (16).
        QCOMPARE(fanuc.lastBlock().motion, BlockEffect::Motion::Feed);
        QVERIFY(near(fanuc.lastBlock().lowestZ, -6.0));
        QVERIFY(near(fanuc.workPosition()[2], 10.0));
        QVERIFY(near(fanuc.position()[2], 60.0)); // the length offset rides on the cycle's Z
        QVERIFY(near(fanuc.toolUsage().at(1).feedPathMm, 8.0));
        QVERIFY(near(fanuc.toolUsage().at(1).cuttingSeconds, 4.0));
        // The next X Y drills again, G99 returning to R; G80 ends it and X moves plainly.
        QVERIFY(runAll(fanuc, "G99 X10\nG80\nG0 X20"));
        QVERIFY(near(fanuc.toolUsage().at(1).feedPathMm, 16.0));
        QVERIFY(near(fanuc.workPosition()[0], 20.0));
        QVERIFY(near(fanuc.workPosition()[2], 2.0)); // left at R by the G99 hole
        QCOMPARE(fanuc.lastBlock().motion, BlockEffect::Motion::Rapid);
    }

    void readsIncrementalRAndZFromTheLevelAndR()
    {
        GCodeInterpreter linuxcnc(Dialect::LinuxCnc);
        // G91: R from the initial level (10 - 8 = 2), Z from R (2 - 5 = -3); X from where it is.
        QVERIFY(runAll(linuxcnc, "T1 M6\nG0 X0 Y0 Z10\nG91 G98 G83 X4 R-8 Z-5 Q1 F100"));
        QVERIFY(near(linuxcnc.lastBlock().lowestZ, -3.0));
        QVERIFY(near(linuxcnc.workPosition()[0], 4.0));
        QVERIFY(near(linuxcnc.workPosition()[2], 10.0));
        // A motion code ends the cycle: the next X is a plain G1.
        QVERIFY(runAll(linuxcnc, "G90 G1 X8 F100\nX9"));
        QVERIFY(near(linuxcnc.workPosition()[2], 10.0));
        QVERIFY(near(linuxcnc.workPosition()[0], 9.0));
    }

    void refusesACycleWithoutItsDepth()
    {
        GCodeInterpreter fanuc(Dialect::Fanuc);
        const auto r = fanuc.runLine("G81 X1 Y1 R2 F100", 4);
        QVERIFY(!r);
        QCOMPARE(r.error().line, 4);
        QVERIFY2(r.error().message.contains(u"G81 needs Z"_s), qPrintable(r.error().message));
    }

    void switchesBetweenTheWorkOffsets()
    {
        GCodeInterpreter fanuc(Dialect::Fanuc);
        QVERIFY(runAll(fanuc, "G10 L2 P2 X100 Z-10\nG10 L2 P1 X1\nG55 G0 X0 Z0"));
        QVERIFY(near(fanuc.position()[0], 100.0));
        QVERIFY(near(fanuc.position()[2], -10.0));
        QVERIFY(runAll(fanuc, "G54"));
        // The machine stays; its work position is now G54's.
        QVERIFY(near(fanuc.position()[0], 100.0));
        QVERIFY(near(fanuc.workPosition()[0], 99.0));
        QVERIFY(runAll(fanuc, "G0 X0"));
        QVERIFY(near(fanuc.position()[0], 1.0));
        const auto refused = fanuc.runLine("G10 L2 P7 X0", 9);
        QVERIFY(!refused);
        QVERIFY2(refused.error().message.contains(u"G54 to G59"_s), qPrintable(refused.error().message));
    }

    void takesWhatPostsWriteAroundTheMoves()
    {
        // LinuxCNC: absolute arc centres (G90.1) and back (G91.1), G59.1, a deleted block that runs.
        GCodeInterpreter linuxcnc(Dialect::LinuxCnc);
        QVERIFY(runAll(linuxcnc, "G10 L2 P7 X50\nG59.1 G90.1 G0 X0 Y0\nG1 F60\nG2 X10 Y0 I5 J0"));
        QVERIFY(near(linuxcnc.position()[0], 60.0));
        QVERIFY(near(
            linuxcnc.toolUsage().at(-1).feedPathMm, 5.0 * std::acos(-1.0))); // centre (5, 0): half a circle
        QVERIFY(runAll(linuxcnc, "G91.1 G2 X0 Y0 I-5 J0\n/G0 X3\n/2 G0 Y4"));
        QVERIFY(near(linuxcnc.workPosition()[0], 3.0));
        QVERIFY(near(linuxcnc.workPosition()[1], 4.0));
        // Inverse time (G93): each move takes a minute over F; G95: F a revolution at S.
        GCodeInterpreter fanuc(Dialect::Fanuc);
        QVERIFY(runAll(fanuc, "T1 M6\nG93 G1 X100 F2\nG95 S1000 G1 X110 F0.1\nG94 G30 G91 Z0\nG9 G61.1 G97"));
        QVERIFY(near(fanuc.toolUsage().at(1).cuttingSeconds, 30.0 + 6.0));
        QCOMPARE(fanuc.lastBlock().motion, BlockEffect::Motion::None);
        // A subprogram is not followed: the check says so instead of passing what it cannot see.
        const auto call = fanuc.runLine("M98 P2000", 7);
        QVERIFY(!call);
        QVERIFY2(call.error().message.contains(u"does not follow"_s), qPrintable(call.error().message));
    }
};

QTEST_GUILESS_MAIN(TestCyclesAndOffsets)
#include "tst_cyclesandoffsets.moc"
