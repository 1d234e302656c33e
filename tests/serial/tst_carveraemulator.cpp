// SPDX-License-Identifier: GPL-3.0-or-later
#include <QSignalSpy>
#include <QTest>

#include "model/gcode/gcodeinterpreter.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/machinereplies.h"
#include "tests/support/emulatorlines.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

class TestCarveraEmulator : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void followsTheSeedsWorkedExample()
    {
        CarveraEmulator emulator;
        QList<QByteArray> out = command(emulator, "M491");
        QVERIFY(out.contains("[PRB:-88.000,-9.000,-72.300:1]"));
        QCOMPARE(out.last(), QByteArray("ok"));
        QVERIFY(out.contains("Done ATC"));
        QCOMPARE(emulator.referenceMz(), -72.3); // the first tool probed becomes the reference
        QCOMPARE(command(emulator, "M493.2 T2"), QList<QByteArray> { "ok" });
        command(emulator, "M491");
        out = command(emulator, "M493.4");
        QCOMPARE(out.size(), 4);
        QCOMPARE(out.at(0), QByteArray("current tool offset [-105.688] , reference tool offset [-72.300]"));
        QCOMPARE(out.at(1), QByteArray("no one-off tool setter position offsets configured"));
        QCOMPARE(out.at(2), QByteArray("using default Tool setter position: X[-88.000] Y[-9.000] Z[-2.000]"));
        QVERIFY(qFuzzyCompare(emulator.tlo(), -33.388));
        // "Adding 2.9mm length to the current tool": -33.388 + 2.9 = -30.488
        out = command(emulator, "M493.3 Z-30.488");
        QCOMPARE(out.at(0), QByteArray("current tool offset [-102.788] , reference tool offset [-72.300]"));
        QVERIFY(status(emulator).contains("|T:2,-30.488,-1,0|"));
    }

    void aBrokenToolMeasuresShorter()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        QList<QByteArray> out = command(emulator, "M491.1 H0.05");
        QVERIFY(out.contains("Old: 0.000 , new: 0.000"));
        QVERIFY(!emulator.isHalted());
        emulator.breakTool(1, 0.5);
        out = command(emulator, "M491.1");
        QVERIFY(out.contains("Old: 0.000 , new: -0.500"));
        QVERIFY(out.contains("ERROR: Tool Break Check - check tool for breakage"));
        QCOMPARE(emulator.haltReason(), 4);
        QVERIFY(status(emulator).contains("|H:4>"));
        QVERIFY(status(emulator).startsWith("<Alarm|"));
    }

    void refusesATooSmallToleranceBeforeMoving()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        const QList<QByteArray> out = command(emulator, "M491.1 H0.01");
        QCOMPARE(out.front(), QByteArray("ERROR: Tool Break Check - tolerance set too small"));
        QVERIFY(!out.contains("M497.3")); // no probing script ran
        QCOMPARE(emulator.haltReason(), 4);
    }

    void needsAPreviousTloForTheBreakTest()
    {
        CarveraEmulator emulator;
        QCOMPARE(command(emulator, "M491.1").front(), QByteArray("No previous TLO included, aborting"));
        QVERIFY(!emulator.isHalted());
    }

    void locksWhileHaltedAndUnlocks()
    {
        CarveraEmulator emulator;
        emulator.halt(3);
        QCOMPARE(command(emulator, "M491"), QList<QByteArray> { "error:Alarm lock" });
        QCOMPARE(command(emulator, "M493.4"), QList<QByteArray> { "error:Alarm lock" });
        QCOMPARE(command(emulator, "M5"), QList<QByteArray> { "ok" }); // allowed while halted
        const QList<QByteArray> unlock { "[Caution: Unlocked]", "ok" };
        QCOMPARE(command(emulator, "$X"), unlock);
        QVERIFY(!emulator.isHalted());
        emulator.halt(1);
        QCOMPARE(command(emulator, "M999").front(),
            QByteArray("WARNING: After HALT you should HOME as position is currently unknown"));
        QVERIFY(!emulator.isHalted());
    }

    void selectingAToolNeedsT()
    {
        CarveraEmulator emulator;
        QCOMPARE(command(emulator, "M493.2").front(), QByteArray("ERROR: No tool was set!"));
        QCOMPARE(emulator.haltReason(), 7);
    }

    void aToolTooShortFailsToTrigger()
    {
        CarveraEmulator emulator;
        emulator.setToolLength(1, 2.0);
        const QList<QByteArray> out = command(emulator, "M491");
        QVERIFY(out.contains("ALARM: Probe failed to trigger within safety margin (135.00mm)"));
        QCOMPARE(emulator.haltReason(), 3);
    }

    void refusesProbingUnhomed()
    {
        CarveraEmulator emulator;
        emulator.setHomed(false);
        QCOMPARE(command(emulator, "M491").front(), QByteArray("Machine has not been homed"));
        QCOMPARE(emulator.haltReason(), 2);
    }

    void changesToolsAndSetsTloWithoutProbing()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        emulator.setToolLength(7, 44.312); // a tool with no rack slot: changed by hand
        QList<QByteArray> out = command(emulator, "M6 T7");
        QCOMPARE(out.at(0), QByteArray("Start dropping current tool: T1"));
        QCOMPARE(out.at(1), QByteArray("Start manually picking new tool: T7"));
        QVERIFY(qFuzzyCompare(emulator.tlo(), -33.388));
        out = command(emulator, "M6 T8 H-12.5");
        const QList<QByteArray> byHand { "Start dropping current tool: T7",
            "Start manually picking new tool: T8", "ok" };
        QCOMPARE(out, byHand);
        QCOMPARE(emulator.tool(), 8);
        QCOMPARE(emulator.tlo(), -12.5);
        out = command(emulator, "M6 T-5");
        QCOMPARE(out.front(), QByteArray("ALARM: Invalid tool: T-5"));
        QCOMPARE(emulator.haltReason(), 6);
    }

    void setsTloFromAGaugeAboveZ0()
    {
        CarveraEmulator emulator;
        command(emulator, "M491"); // reference -72.300, TLO 0
        command(emulator, "G53 G0 Z-40");
        command(emulator, "G10 L20 P1 Z0"); // work Z0 here
        command(emulator, "G53 G0 Z-37"); // 3 mm up: a 3 mm gauge under the tip
        const QList<QByteArray> out = command(emulator, "M493.3 H3.0");
        const auto r = parseTloReport(out.front());
        QVERIFY(r);
        QVERIFY2(std::fabs(r->tlo()) < 1e-9, out.front().constData());
    }

    void movesExactlyAsTheSharedInterpreterSays()
    {
        // The emulator's G-code runs through the interpreter `toffee-cli simulate` uses: same program, same
        // place.
        const QByteArray program
            = "M493.3 Z-33.388\nG10 L2 P1 X-100 Y-50 Z-60\nG90 G0 X10 Y5 Z2\nG91 G0 Z-1.5\nG90 G1 X0";
        CarveraEmulator emulator;
        for (const QByteArray &line : program.split('\n'))
            QCOMPARE(command(emulator, line).last(), QByteArray("ok"));
        GCodeInterpreter simulated(Dialect::Carvera);
        QVERIFY(simulated.run(program).ok());
        const auto report = parseStatusReport(status(emulator));
        QVERIFY(report);
        for (size_t i = 0; i < 3; ++i)
            QVERIFY2(std::fabs(report->mpos[i] - simulated.position()[i]) < 1e-4,
                qPrintable(u"axis %1: %2 vs %3"_s.arg(i).arg(report->mpos[i]).arg(simulated.position()[i])));
        QCOMPARE(simulated.position()[2], -60 + 2 - 1.5 - 33.388);
        QCOMPARE(
            command(emulator, "G43 H1").front(), QByteArray("error:Unsupported command - G43 H1")); // no G43
    }

    void theFixedReferenceProfileKeepsItsReference()
    {
        CarveraEmulator emulator;
        emulator.setProfile(CarveraEmulator::Profile::FixedReference, -70.0);
        command(emulator, "M491");
        QCOMPARE(emulator.referenceMz(), -70.0);
        QVERIFY(qFuzzyCompare(emulator.tlo(), -2.3));
    }

    void answersUnknownCommandsAndEmptyLines()
    {
        CarveraEmulator emulator;
        QCOMPARE(command(emulator, "M12345"), QList<QByteArray> { "error:Unsupported command - M12345" });
        QCOMPARE(command(emulator, ""), QList<QByteArray> { "ok" });
        QCOMPARE(command(emulator, ";"), QList<QByteArray> { "ok" });
    }

    void abortsAProbeWithCtrlX()
    {
        CarveraEmulator emulator;
        emulator.setTiming({ 5000, 0 });
        QSignalSpy lines(&emulator, &CarveraEmulator::lineSent);
        emulator.receiveLine("M491");
        QVERIFY(status(emulator).startsWith("<Run|"));
        emulator.receiveRealtime(0x18);
        QCOMPARE(lines.last().front().toByteArray(), QByteArray("ALARM: Abort during cycle"));
        QVERIFY(emulator.isHalted());
        QTest::qWait(50);
        QVERIFY(!lines.contains(QVariantList { QByteArray("ok") }));
    }

    void injectsFaults()
    {
        CarveraEmulator emulator;
        emulator.injectFault(CarveraEmulator::Fault::DropOk, "M493.4");
        QList<QByteArray> out = command(emulator, "G90");
        QCOMPARE(out, QList<QByteArray> { "ok" }); // the fault waits for its command
        out = command(emulator, "M493.4", 100);
        QCOMPARE(out.size(), 4); // the three report lines, then no terminator
        QCOMPARE(out.last(), QByteArray("TEST: no terminator"));
        emulator.injectFault(CarveraEmulator::Fault::Garble);
        out = command(emulator, "M493.4");
        QVERIFY(!parseTloReport(out.front()));
        QCOMPARE(out.last(), QByteArray("ok"));
        emulator.injectFault(CarveraEmulator::Fault::FailProbe);
        out = command(emulator, "M491");
        QVERIFY(out.contains("ALARM: Probe failed to trigger within safety margin (135.00mm)"));
        // Aimed at the break test, the fault leaves a plain probe alone (it once hit the first probe).
        QVERIFY(command(emulator, "$X").contains("[Caution: Unlocked]"));
        emulator.injectFault(CarveraEmulator::Fault::FailProbe, "M491.1");
        out = command(emulator, "M491");
        QVERIFY(!out.join('\n').contains("ALARM"));
        QCOMPARE(out.last(), QByteArray("ok"));
        out = command(emulator, "M491.1 H0.1");
        QVERIFY(out.join('\n').contains("ALARM: Probe failed to trigger"));
        QVERIFY(command(emulator, "$X").contains("[Caution: Unlocked]"));
        QSignalSpy closed(&emulator, &CarveraEmulator::linkClosed);
        emulator.injectFault(CarveraEmulator::Fault::CloseLink);
        emulator.receiveLine("$X");
        QCOMPARE(closed.size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestCarveraEmulator)
#include "tst_carveraemulator.moc"
