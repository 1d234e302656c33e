// SPDX-License-Identifier: GPL-3.0-or-later
// The emulator answers as the Carvera's community firmware answers: the transcripts here are the firmware's
// own, recorded from it (../shared/peers/carvera, 2026-11-25) on the same C1 configuration, with tool 1 as
// long as the simulator's tools (it triggers the setter at MCS Z -108.425).
#include <QSignalSpy>
#include <QTest>

#include "model/gcode/gcodeinterpreter.h"
#include "serial/carvera/carverareplies.h"
#include "serial/emulator/carveraemulator.h"
#include "tests/support/emulatorlines.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

// The simulator's tools all trigger at -108.425 (a fast probe 0.010 lower first).
constexpr double kSimulatedToolLength = 41.575;

QList<QByteArray> lines(const char *text)
{
    return QByteArray(text).split('\n');
}

} // namespace

class TestCarveraEmulator : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void answersTheShellAsTheFirmwareDoes()
    {
        CarveraEmulator emulator;
        // `version` is the shell's: one line, no "ok".
        QCOMPARE(command(emulator, "version"), QList<QByteArray> { "version = 2.1.0c-emulator" });
        QVERIFY(parseVersion("version = 2.1.0c-emulator")->kind == FirmwareInfo::Kind::Community);
        // $X on a machine that is not halted: not a word.
        QCOMPARE(command(emulator, "$X"), QList<QByteArray> {});
        QCOMPARE(command(emulator, "echo echo"), QList<QByteArray> { "error:Unsupported command - echo" });
        QCOMPARE(command(emulator, ""), QList<QByteArray> { "ok" });
        QCOMPARE(command(emulator, ";"), QList<QByteArray> { "ok" });
    }

    void probesMeasuresAndSetsAsTheFirmwareDoes()
    {
        CarveraEmulator emulator;
        emulator.setToolLength(1, kSimulatedToolLength);
        QCOMPARE(command(emulator, "M493.4"),
            lines("current tool offset [0.000] , reference tool offset [-115.340]\n"
                  "no one-off tool setter position offsets configured\n"
                  "using default Tool setter position: X[-4.965] Y[-54.480] "
                  "Z[-154.400]\n"
                  "ok"));
        // The command's own "ok" at once, each line of the script echoed with its "ok", "Done ATC" at the
        // end.
        QCOMPARE(command(emulator, "M491"),
            lines("Saved XY position: X-2.000 Y-2.000\n"
                  "ok\n"
                  "M497.3\nok\n"
                  "G53 G0 Z-3.000\nok\n"
                  "G53 G0 X-4.965 Y-54.480\nok\n"
                  "G38.6 Z-154.400 F600.000\n"
                  "[PRB:-4.965,-54.480,-108.435:1]\nok\n"
                  "G91 G0 Z2.000\nok\n"
                  "G38.6 Z-3.000 F150.000\n"
                  "[PRB:-4.965,-54.480,-108.425:1]\nok\n"
                  "M493.1 R1\nok\n"
                  "G53 G0 Z-3.000\nok\n"
                  "Return to XY position: X-2.000 Y-2.000\n"
                  "Done ATC"));
        QVERIFY(status(emulator).contains("|T:1,6.915,-1,0|"));
        QCOMPARE(command(emulator, "M493.4").front(),
            QByteArray("current tool offset [-108.425] , reference tool offset [-115.340]"));
        // M493.3 Z: the TLO is Z, and so is the "current tool offset" printed (not reference + Z).
        QCOMPARE(command(emulator, "M493.3 Z-10.5"),
            lines("current tool offset [-10.500] , reference tool offset [-115.340]\nok"));
        QVERIFY(status(emulator).contains("|T:1,-10.500,-1,0|"));
        // M493.2 changes the tool, not the TLO in force.
        QCOMPARE(command(emulator, "M493.2 T5"), QList<QByteArray> { "ok" });
        QVERIFY(status(emulator).contains("|T:5,-10.500,-1,0|"));
        QCOMPARE(emulator.referenceMz(), CarveraEmulator::kFactoryReferenceMz); // probing never moves it
    }

    // M493.3 H adds to the "current tool offset", which after an M493.3 Z is no MCS Z: 115.340 mm off, as on
    // the firmware (Toffee itself never sends M493.3 H: it works the TLO out and sends M493.3 Z).
    void setsTloFromAGaugeAboveZ0AsTheFirmwareDoes()
    {
        CarveraEmulator emulator;
        emulator.setToolLength(1, kSimulatedToolLength);
        command(emulator, "M491"); // TLO 6.915, WPos Z -3 - 6.915 = -9.915
        QCOMPARE(command(emulator, "M493.3 H3").front(),
            QByteArray("current tool offset [-121.340] , reference tool offset [-115.340]"));
        QVERIFY2(status(emulator).contains("|T:1,-6.000,-1,0|"), status(emulator).constData()); // right
        command(emulator, "M493.3 Z6.915");
        QCOMPARE(command(emulator, "M493.3 H3").front(),
            QByteArray("current tool offset [-6.000] , reference tool offset [-115.340]"));
        QVERIFY(status(emulator).contains("|T:1,109.340,-1,0|")); // the firmware's error, 115.340 off
    }

    void aFailedBreakTestHaltsWithTheNewLengthInForce()
    {
        CarveraEmulator emulator;
        emulator.setToolLength(1, kSimulatedToolLength);
        command(emulator, "M491");
        command(emulator, "M493.3 Z109.34");
        QCOMPARE(command(emulator, "M491.1 H0.05"),
            lines("Saved XY position: X-2.000 Y-2.000\n"
                  "ok\n"
                  "M5\nok\n"
                  "M497.3\nok\n"
                  "G53 G0 Z-3.000\nok\n"
                  "G53 G0 X-4.965 Y-54.480\nok\n"
                  "G38.6 Z-154.400 F600.000\n"
                  "[PRB:-4.965,-54.480,-108.435:1]\nok\n"
                  "G91 G0 Z2.000\nok\n"
                  "G38.6 Z-3.000 F150.000\n"
                  "[PRB:-4.965,-54.480,-108.425:1]\nok\n"
                  "M493.1 R1\nok\n"
                  "G53 G0 Z-3.000\nok\n"
                  "G53 G0 Z-20.000\nok\n"
                  "M491.2 H0.050 , P109.340\n"
                  "Old: 109.340 , new: 6.915\n"
                  "ERROR: Tool Break Check - check tool for breakage\n"
                  "Halt Happened at Line: 0,percent: 0, time: 0\n"
                  "ok"));
        const QByteArray report = status(emulator);
        QVERIFY2(report.startsWith("<Alarm|MPos:-4.9650,-54.4800,-20.0000,"), report.constData());
        QVERIFY(report.contains("|T:1,6.915,-1,0|")); // the broken length, not 109.340
        QVERIFY(report.contains("|H:4|"));
        QCOMPARE(command(emulator, "G90"), QList<QByteArray> { "error:Alarm lock" });
        QCOMPARE(command(emulator, "M493.4"), QList<QByteArray> { "error:Alarm lock" });
        QCOMPARE(command(emulator, "$X"),
            lines("Halt Happened at Line: 0,percent: 0, time: 0\n[Caution: Unlocked]\nok"));
        QVERIFY(!emulator.isHalted());
    }

    void aBreakTestThatPassesEndsWithDoneAtc()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        const QList<QByteArray> out = command(emulator, "M491.1 H0.05");
        QVERIFY(out.contains("M491.2 H0.050 , P43.040"));
        QVERIFY(out.contains("Old: 43.040 , new: 43.040"));
        QCOMPARE(out.last(), QByteArray("Done ATC"));
        QVERIFY(!emulator.isHalted());
        emulator.breakTool(1, 0.5);
        QVERIFY(command(emulator, "M491.1").contains("Old: 43.040 , new: 42.540"));
        QCOMPARE(emulator.haltReason(), 4);
    }

    void refusesATooSmallToleranceBeforeMoving()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        QCOMPARE(command(emulator, "M491.1 H0.01"),
            lines("ERROR: Tool Break Check - tolerance set too small\n"
                  "Halt Happened at Line: 0,percent: 0, time: 0\nok"));
        QCOMPARE(emulator.haltReason(), 4);
    }

    // "No previous TLO" is a TLO of exactly 0: the whole probe runs, the new length is taken, nothing is
    // compared, and the machine does not halt.
    void aTloOfZeroIsNoPreviousTlo()
    {
        CarveraEmulator emulator;
        const QList<QByteArray> out = command(emulator, "M491.1");
        QVERIFY(out.contains("M491.2 H0.100 , P0.000"));
        QVERIFY(out.contains("No previous TLO included, aborting"));
        QCOMPARE(out.last(), QByteArray("Done ATC"));
        QVERIFY(!emulator.isHalted());
        QCOMPARE(emulator.tlo(), 43.04);
    }

    // The firmware's M491.1 takes T0 and T9 on for its wireless probe: it measures, then halts (H:12).
    void breakTestingToolNineOrAboveHaltsAsTheFirmwareDoes()
    {
        CarveraEmulator emulator;
        command(emulator, "M493.2 T10");
        command(emulator, "M491");
        const QList<QByteArray> out = command(emulator, "M491.1");
        QVERIFY(out.contains("ERROR: Wireless probe dead or not set, please charge or set first!"));
        QCOMPARE(emulator.haltReason(), 12);
    }

    void locksWhileHaltedAndUnlocks()
    {
        CarveraEmulator emulator;
        emulator.halt(3);
        QCOMPARE(command(emulator, "M491"), QList<QByteArray> { "error:Alarm lock" });
        QCOMPARE(command(emulator, "M5"), QList<QByteArray> { "ok" }); // allowed while halted
        QVERIFY(command(emulator, "$X").contains("[Caution: Unlocked]"));
        QVERIFY(!emulator.isHalted());
        emulator.halt(1);
        QCOMPARE(command(emulator, "M999"),
            lines("Halt Happened at Line: 0,percent: 0, time: 0\n"
                  "WARNING: After HALT you should HOME as position is currently unknown\nok"));
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
        emulator.setToolLength(1, -5.0);
        const QList<QByteArray> out = command(emulator, "M491");
        // The community firmware's G38.6 stops untriggered at the end of its travel (ZProbe::calibrate_Z).
        QVERIFY(out.contains("[PRB:-4.965,-54.480,-154.400:0]"));
        QVERIFY(out.contains("ERROR: Calibrate fail!"));
        QCOMPARE(emulator.haltReason(), 4);
        // The stock firmware's words are CARVERA.md's.
        CarveraEmulator stock;
        stock.setFirmware(CarveraEmulator::Firmware::Stock);
        stock.setToolLength(1, -5.0);
        QVERIFY(command(stock, "M491")
                    .contains("ALARM: Probe failed to trigger within safety margin (151.40mm)"));
        QCOMPARE(stock.haltReason(), 3);
    }

    void refusesProbingUnhomed()
    {
        CarveraEmulator emulator;
        emulator.setHomed(false);
        const QList<QByteArray> out = command(emulator, "M491");
        QVERIFY(out.contains("ERROR: Machine has not been homed. Use M888 to disable homed check"));
        QCOMPARE(emulator.haltReason(), 2);
        CarveraEmulator stock;
        stock.setFirmware(CarveraEmulator::Firmware::Stock);
        stock.setHomed(false);
        QVERIFY(command(stock, "M491").contains("Machine has not been homed"));
        QCOMPARE(stock.haltReason(), 2);
    }

    void changesToolsAsTheFirmwareDoes()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        QList<QByteArray> out = command(emulator, "M6 T2");
        QCOMPARE(out.mid(0, 4),
            lines("Saved XY position: X-2.000 Y-2.000\nStart dropping current tool: T1\n"
                  "Start picking new tool: T2\nok"));
        QVERIFY(out.contains("ATC loosed!"));
        QVERIFY(out.contains("ATC clamped!"));
        QVERIFY(out.contains("[PRB:-4.965,-54.480,-105.688:1]"));
        QCOMPARE(out.last(), QByteArray("Done ATC"));
        QCOMPARE(emulator.tool(), 2);
        QCOMPARE(emulator.tlo(), 9.652);
        // M6 to the tool in the spindle: a bare "ok".
        QCOMPARE(command(emulator, "M6 T2"), QList<QByteArray> { "ok" });
        // A tool with no slot is changed by hand; with H its TLO is taken without probing.
        out = command(emulator, "M6 T8 H-12.5");
        QVERIFY(out.contains("Start manually picking new tool: T8"));
        QVERIFY(out.contains("Tool is now installed and TLO set as -12.500."));
        QVERIFY(out.contains("current tool offset [-12.500] , reference tool offset [-115.340]"));
        QCOMPARE(out.last(), QByteArray("Done ATC"));
        QCOMPARE(emulator.tool(), 8);
        QCOMPARE(emulator.tlo(), -12.5);
        out = command(emulator, "M6 T-1");
        QVERIFY(out.contains("Start manually dropping current tool: T8"));
        QCOMPARE(out.last(), QByteArray("Done ATC"));
        QCOMPARE(emulator.tool(), -1);
        QVERIFY(status(emulator).contains("|T:-1,0.000,-1,0|"));
        out = command(emulator, "M6 T-5");
        QCOMPARE(out.front(), QByteArray("ERROR: Invalid tool: T-5"));
        QCOMPARE(emulator.haltReason(), 6);
    }

    // A manual change waits for the operator in state Tool (here for the change time, standing in for the
    // operator's button).
    void aManualChangeWaitsInStateTool()
    {
        CarveraEmulator emulator;
        emulator.setTiming({ 0, 0, 300 });
        QSignalSpy sent(&emulator, &CarveraEmulator::lineSent);
        emulator.receiveLine("M6 T8");
        QTRY_VERIFY(status(emulator).startsWith("<Tool|"));
        QTRY_VERIFY_WITH_TIMEOUT(!emulator.isBusy(), 3000);
        QCOMPARE(emulator.tool(), 8);
        QVERIFY(status(emulator).startsWith("<Idle|"));
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
    }

    // A move beyond the C1's travel halts at its soft endstop before it starts, in the firmware's words (its
    // answer on the peer: the error, the halt line, "ok"; then Alarm with H:10 where it stood), on every axis
    // and both ways; one towards the inside of the travel is taken, even from beyond it.
    void aMoveBeyondTheTravelHaltsAtTheSoftEndstop()
    {
        CarveraEmulator emulator;
        const QList<QByteArray> said = command(emulator, "G91 G0 Z99999999");
        QCOMPARE(
            said.first(), QByteArray("ERROR: Soft Endstop Z was exceeded - reset or $X or M999 required"));
        QVERIFY(said.at(1).startsWith("Halt Happened at Line"));
        QCOMPARE(said.last(), QByteArray("ok"));
        auto report = parseStatusReport(status(emulator));
        QVERIFY(report && report->isAlarm());
        QCOMPARE(report->haltReason, 10);
        QCOMPARE(report->mpos[2], -2.0); // where it stood
        QCOMPARE(command(emulator, "$X").last(), QByteArray("ok"));
        QCOMPARE(command(emulator, "G90 G53 G0 X-365").first(),
            QByteArray("ERROR: Soft Endstop X was exceeded - reset or $X or M999 required"));
        QCOMPARE(command(emulator, "$X").last(), QByteArray("ok"));
        QCOMPARE(command(emulator, "G53 G0 Y-250.5").first(),
            QByteArray("ERROR: Soft Endstop Y was exceeded - reset or $X or M999 required"));
        QCOMPARE(command(emulator, "$X").last(), QByteArray("ok"));
        // Within the travel, to its very edges, and back in from beyond an edge: taken.
        for (const QByteArray line : { "G53 G0 X-364 Y-250 Z-135", "G53 G0 X-1 Y-1 Z-1" })
            QCOMPARE(command(emulator, line), QList<QByteArray> { "ok" });
        report = parseStatusReport(status(emulator));
        QVERIFY(report && !report->isAlarm());
        QCOMPARE(report->mpos[0], -1.0);
        QCOMPARE(report->mpos[2], -1.0);
    }

    // What the firmware does with what it does not know: an M- or G-code it takes without a word, upper-case
    // text it takes and then halts on, a lower-case word it refuses (its shell).
    void answersUnknownCommandsAsTheFirmwareDoes()
    {
        CarveraEmulator emulator;
        QCOMPARE(command(emulator, "M12345"), QList<QByteArray> { "ok" });
        QCOMPARE(command(emulator, "foo"), QList<QByteArray> { "error:Unsupported command - foo" });
        QVERIFY(!emulator.isHalted());
        const QList<QByteArray> out = command(emulator, "FOO");
        QCOMPARE(out.front(), QByteArray("ok"));
        QVERIFY(emulator.isHalted());
        QCOMPARE(command(emulator, "G20").front(), QByteArray("error:Alarm lock"));
        command(emulator, "$X");
        QCOMPARE(command(emulator, "G20").front(), QByteArray("ERROR: Imperial Units are unsupported"));
    }

    void abortsWithCtrlXEvenWhenIdle()
    {
        CarveraEmulator emulator;
        emulator.setTiming({ 5000, 0 });
        QSignalSpy lines(&emulator, &CarveraEmulator::lineSent);
        emulator.receiveLine("M491");
        QVERIFY(status(emulator).startsWith("<Run|"));
        emulator.receiveRealtime(0x18);
        QVERIFY(lines.contains(QVariantList { QByteArray("ERROR: Abort during cycle") }));
        QVERIFY(emulator.isHalted());
        command(emulator, "$X");
        QVERIFY(!emulator.isHalted());
        emulator.receiveRealtime(0x18); // idle: the firmware halts all the same
        QVERIFY(emulator.isHalted());
        QCOMPARE(emulator.haltReason(), 1);
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
        // Dropped at a script, it is the script's end that never comes.
        emulator.injectFault(CarveraEmulator::Fault::DropOk, "M491");
        out = command(emulator, "M491", 300);
        QCOMPARE(out.last(), QByteArray("TEST: no terminator"));
        emulator.injectFault(CarveraEmulator::Fault::FailProbe);
        out = command(emulator, "M491");
        QVERIFY(out.contains("ERROR: Calibrate fail!"));
        // Aimed at the break test, the fault leaves a plain probe alone (it once hit the first probe).
        QVERIFY(command(emulator, "$X").contains("[Caution: Unlocked]"));
        emulator.injectFault(CarveraEmulator::Fault::FailProbe, "M491.1");
        out = command(emulator, "M491");
        QVERIFY(!out.join('\n').contains("Calibrate fail"));
        QCOMPARE(out.last(), QByteArray("Done ATC"));
        out = command(emulator, "M491.1 H0.1");
        QVERIFY(out.contains("ERROR: Calibrate fail!"));
        QVERIFY(command(emulator, "$X").contains("[Caution: Unlocked]"));
        QSignalSpy closed(&emulator, &CarveraEmulator::linkClosed);
        emulator.injectFault(CarveraEmulator::Fault::CloseLink);
        emulator.receiveLine("$X");
        QCOMPARE(closed.size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestCarveraEmulator)
#include "tst_carveraemulator.moc"
