// SPDX-License-Identifier: GPL-3.0-or-later
// The two firmwares, the rack and the tool change, as the emulator plays them (docs/CARVERA.md § 7, § 8).
#include <QSignalSpy>
#include <QTest>

#include "serial/carvera/carverareplies.h"
#include "serial/emulator/carveraemulator.h"
#include "tests/support/emulatorlines.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;
using Firmware = CarveraEmulator::Firmware;
using Lines = QList<QByteArray>;

namespace {

bool near(double a, double b)
{
    return std::fabs(a - b) < 1e-9;
}

const QByteArray kProbeAlarm = "ERROR: Calibrate fail!"; // the setter never touched

} // namespace

class TestCarveraRack : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // `version` is the firmware's shell: one line, no "ok", and it runs while halted too.
    void answersVersionInBothFirmwares()
    {
        CarveraEmulator emulator;
        QCOMPARE(emulator.firmware(), Firmware::Community);
        QCOMPARE(command(emulator, "version"), Lines { "version = 2.1.0c-emulator" });
        emulator.setFirmware(Firmware::Stock);
        emulator.halt(3);
        QCOMPARE(command(emulator, "version"), Lines { "version = 1.0.1" });
        QVERIFY(parseVersion("version = 1.0.1")->kind == FirmwareInfo::Kind::Stock);
        QVERIFY(emulator.isHalted());
        QCOMPARE(command(emulator, "M491"), Lines { "error:Alarm lock" });
    }

    // M493.3 and M493.4 answer only "ok"; M491.1 is a plain M491: no comparison, no halt, no tolerance check.
    void stockIgnoresWhatItDoesNotHave()
    {
        CarveraEmulator emulator;
        emulator.setFirmware(Firmware::Stock);
        command(emulator, "M491"); // T1 at -72.300: TLO 43.040
        QCOMPARE(command(emulator, "M493.3 Z-5"), Lines { "ok" });
        QCOMPARE(command(emulator, "M493.4"), Lines { "ok" });
        QCOMPARE(emulator.currentMz(), -72.3);
        emulator.breakTool(1, 0.5);
        Lines out = command(emulator, "M491.1 H0.05");
        QVERIFY(out.contains("M493.1 R1"));
        QVERIFY(!out.join('\n').contains("Old:"));
        QCOMPARE(out.last(), QByteArray("Done ATC"));
        QVERIFY(near(emulator.tlo(), 42.54)); // the broken tool's TLO, adopted silently
        QVERIFY(command(emulator, "M491.1 H0.001").contains("Done ATC"));
        QVERIFY(!emulator.isHalted());
    }

    void reportsTheToolFieldPerFirmware_data()
    {
        QTest::addColumn<Firmware>("firmware");
        QTest::addColumn<QByteArray>("change");
        QTest::addColumn<QByteArray>("field");
        QTest::newRow("community") << Firmware::Community << QByteArray() << QByteArray("|T:1,0.000,-1,0|");
        QTest::newRow("community, empty")
            << Firmware::Community << QByteArray("M6 T-1") << QByteArray("|T:-1,0.000,-1,0|");
        QTest::newRow("stock") << Firmware::Stock << QByteArray() << QByteArray("|T:1,0.000|");
        QTest::newRow("stock, empty") << Firmware::Stock << QByteArray("M6 T-1") << QByteArray();
    }

    void reportsTheToolFieldPerFirmware()
    {
        QFETCH(Firmware, firmware);
        QFETCH(QByteArray, change);
        QFETCH(QByteArray, field);
        CarveraEmulator emulator;
        emulator.setFirmware(firmware); // T1 in the spindle, TLO 0
        if (!change.isEmpty())
            QCOMPARE(command(emulator, change).last(), QByteArray("Done ATC"));
        const QByteArray report = status(emulator);
        QVERIFY2(field.isEmpty() ? !report.contains("|T:") : report.contains(field), report.constData());
    }

    void haltsOnInches()
    {
        for (const Firmware firmware : { Firmware::Community, Firmware::Stock }) {
            CarveraEmulator emulator;
            emulator.setFirmware(firmware);
            const Lines halt { "ERROR: Imperial Units are unsupported", CarveraEmulator::kHaltLine, "ok" };
            QCOMPARE(command(emulator, "G0 G20 X1"), halt);
            QCOMPARE(emulator.haltReason(), 1);
            QVERIFY(status(emulator).contains("|MPos:-2.0000,-2.0000,")); // it did not move
        }
    }

    // As the community firmware runs M491 R<n> (ATCHandler.cpp, seen on it): a pass per measurement, 25 mm up
    // between them, then M493.1 R<n>'s summary; the "Using" line is the highest contact's (the longest edge),
    // but the TLO kept is the lowest's (the shortest edge).
    void repeatsAMeasurement()
    {
        CarveraEmulator emulator;
        command(emulator, "M493.2 T2");
        emulator.setRepeatability(0.01);
        const Lines out = command(emulator, "M491 R3");
        QCOMPARE(out.count("G91 G0 Z25.000"), 2);
        QVERIFY(out.contains("[PRB:-4.965,-54.480,-105.678:1]"));
        const qsizetype first = out.indexOf("M493.1 R3");
        QVERIFY2(first > 0, out.join('\n').constData());
        const Lines tail { "M493.1 R3", "------------------ Measurements--------------------",
            "TLO value from measurement 1: 9.652", "TLO value from measurement 2: 9.662",
            "TLO value from measurement 3: 9.642", "------------------ Results------------------------------",
            "Using TLO value from measurement 2: 9.662", "Max delta: 0.020",
            "Lowest cutting edge: 2, Highest cutting edge: 3",
            "-----------------------------------------------------------", "ok", "G53 G0 Z-3.000", "ok",
            "Return to XY position: X-2.000 Y-2.000", "Done ATC" };
        QCOMPARE(out.mid(first), tail);
        QVERIFY(near(emulator.tlo(), 9.642));
        QVERIFY(!out.contains("M493.1 R1"));
        // Equal passes: the firmware's edge numbers come out "1, n".
        emulator.setRepeatability(0.0);
        QVERIFY(command(emulator, "M491 R2").contains("Lowest cutting edge: 1, Highest cutting edge: 2"));
    }

    // M491 X<dx> Y<dy>: the touch-off point moves from the setter's, for that M491 only.
    void touchesOffCentre()
    {
        CarveraEmulator emulator;
        command(emulator, "M493.2 T2");
        Lines out = command(emulator, "M491 X-5 Y-3");
        QVERIFY2(out.contains("G53 G0 X-9.965 Y-57.480"), out.join('\n').constData());
        QVERIFY(out.contains("[PRB:-9.965,-57.480,-105.688:1]"));
        out = command(emulator, "M491");
        QVERIFY(out.contains("G53 G0 X-4.965 Y-54.480"));
    }

    void refusesRepeatsOutOfRange()
    {
        CarveraEmulator emulator;
        for (const QByteArray line : { "M491 R256", "M491 R2.5", "M491 R" })
            QCOMPARE(command(emulator, line), Lines { "error:Unsupported command - " + line });
        QVERIFY(!emulator.isHalted());
        QVERIFY(command(emulator, "M491 R0").contains("M493.1 R1")); // the firmware takes R0 as one
        emulator.setFirmware(Firmware::Stock); // R ignored: one plain measurement
        const Lines out = command(emulator, "M491 R11");
        QVERIFY(out.contains("M493.1 R1"));
        QVERIFY(!out.join('\n').contains("TLO value from measurement"));
    }

    void changesARackToolAndAlwaysMeasuresIt()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        const Lines out = command(emulator, "M6 T2");
        QCOMPARE(out.mid(0, 4),
            (Lines { "Saved XY position: X-2.000 Y-2.000", "Start dropping current tool: T1",
                "Start picking new tool: T2", "ok" }));
        // T1 back in its slot, T2 out of its own, then measured, then back where it was.
        QVERIFY(out.contains("G53 G0 X-4.960 Y-84.480")); // T1's slot, as on the firmware
        QVERIFY(out.contains("M493.2 T-1"));
        QVERIFY(out.contains("G53 G0 X-4.960 Y-114.480")); // T2's
        QVERIFY(out.contains("M493.2 T2"));
        QVERIFY(out.contains("[PRB:-4.965,-54.480,-105.688:1]"));
        QCOMPARE(out.mid(out.size() - 2), (Lines { "Return to XY position: X-2.000 Y-2.000", "Done ATC" }));
        QCOMPARE(emulator.tool(), 2);
        QVERIFY(near(emulator.tlo(), 9.652));
        const Lines again = command(emulator, "M6 T3 H-1"); // H is for manual changes only
        QVERIFY(again.contains("[PRB:-4.965,-54.480,-102.500:1]")); // T3: 47.5 mm
        QVERIFY(near(emulator.tlo(), 12.84));
    }

    void stockSaysOneLineForAChange()
    {
        CarveraEmulator emulator;
        emulator.setFirmware(Firmware::Stock);
        Lines out = command(emulator, "M6 T2");
        QCOMPARE(out.at(1), QByteArray("Start atc, old tool: T1, new tool: T2"));
        QCOMPARE(out.last(), QByteArray("Done ATC"));
        out = command(emulator, "M6 T-1");
        QCOMPARE(out.at(1), QByteArray("Start dropping current tool: T2"));
        QCOMPARE(emulator.tool(), -1);
        out = command(emulator, "M6 T3");
        QCOMPARE(out.at(1), QByteArray("Start picking new tool: T3"));
        QVERIFY(out.contains("Done ATC"));
    }

    void picksIntoAnEmptySpindle()
    {
        CarveraEmulator emulator;
        Lines out = command(emulator, "M6 T-1");
        QCOMPARE(out.mid(0, 3),
            (Lines { "Saved XY position: X-2.000 Y-2.000", "Start dropping current tool: T1", "ok" }));
        QCOMPARE(out.last(), QByteArray("Done ATC"));
        QCOMPARE(emulator.tool(), -1);
        out = command(emulator, "M6 T2");
        QCOMPARE(out.at(1), QByteArray("Start picking new tool: T2"));
        QVERIFY(!out.contains("M497.1")); // nothing to drop
        QVERIFY(out.contains("M497.3"));
    }

    void changesByHandOutsideTheRack()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        Lines out = command(emulator, "M6 T0"); // the wireless probe has no slot
        QCOMPARE(out.mid(1, 2),
            (Lines { "Start dropping current tool: T1", "Start manually picking new tool: T0" }));
        QVERIFY(out.contains("M497.3"));
        QVERIFY(out.contains("Done ATC"));
        out = command(emulator, "M6 T999990 H2.5");
        QCOMPARE(out.mid(1, 2),
            (Lines {
                "Start manually dropping current tool: T0", "Start manually picking new tool: T999990" }));
        QVERIFY(out.contains("Tool is now installed and TLO set as 2.500."));
        QVERIFY(!out.contains("M497.3"));
        QCOMPARE(emulator.tlo(), 2.5);
    }

    void theSameToolIsNoChange()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        QCOMPARE(command(emulator, "M6 T1"), Lines { "ok" });
        QCOMPARE(command(emulator, "M6 T1 H5"), Lines { "ok" });
        QCOMPARE(emulator.tlo(), 43.04);
    }

    void alarmsOnAnInvalidTool()
    {
        // The firmware halts above T1000000; it would take T-2 for a manual tool and T2.5 for T2, where the
        // emulator halts too (docs/CARVERA.md § 9; Toffee sends neither).
        for (const QByteArray t : { "1000001", "-2", "2.5" }) {
            CarveraEmulator emulator;
            QCOMPARE(command(emulator, "M6 T" + t),
                (Lines { "ERROR: Invalid tool: T" + t, CarveraEmulator::kHaltLine, "ok" }));
            QCOMPARE(emulator.haltReason(), 6);
            QCOMPARE(emulator.tool(), 1);
        }
    }

    void readsToolSlots()
    {
        const auto rack = CarveraEmulator::parseToolSlots(
            "# my rack\n1 -10 -20 -100\n\n  2\t-40.5 -20   # z as above\n7 -70 -20 -90.25 #\n");
        QVERIFY2(rack, qPrintable(rack.error().text()));
        QCOMPARE(rack.value().size(), 3);
        QCOMPARE(rack.value().at(1).tool, 2);
        QCOMPARE(rack.value().at(1).x, -40.5);
        QCOMPARE(rack.value().at(1).z, -100.0);
        QCOMPARE(rack.value().at(2).z, -90.25);
    }

    void refusesBadToolSlots_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("error");
        QTest::newRow("word") << QByteArray("1 0 0 -100\n2 0 0\n7 abc 5\n")
                              << uR"(line 3: "7 abc 5" is not "number x y [z]")"_s;
        QTest::newRow("too few") << QByteArray("1 0") << uR"(line 1: "1 0" is not "number x y [z]")"_s;
        QTest::newRow("too many") << QByteArray("1 0 0 0 0")
                                  << uR"(line 1: "1 0 0 0 0" is not "number x y [z]")"_s;
        QTest::newRow("fraction") << QByteArray("1.5 0 0 0")
                                  << uR"(line 1: "1.5 0 0 0" is not "number x y [z]")"_s;
        QTest::newRow("zero") << QByteArray("0 0 0 0") << u"line 1: tool 0 is not 1-999989"_s;
        QTest::newRow("probe") << QByteArray("999990 0 0 0") << u"line 1: tool 999990 is not 1-999989"_s;
        QTest::newRow("twice") << QByteArray("3 0 0 0\n3 1 1") << u"line 2: tool 3 has a slot already"_s;
        QTest::newRow("first z") << QByteArray("# z?\n3 0 0") << u"line 2: the first slot needs a z"_s;
        QTest::newRow("empty") << QByteArray() << u"no tool slots"_s;
        QTest::newRow("comments") << QByteArray("# nothing\n\n") << u"no tool slots"_s;
    }

    void refusesBadToolSlots()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, error);
        const auto rack = CarveraEmulator::parseToolSlots(text);
        QVERIFY(!rack);
        QCOMPARE(rack.error().text(), error);
    }

    // The test peer's rack senses no tools: the firmware puts the spindle's back, finds no tool in the slot
    // it just filled, and halts with the spindle empty (seen on it); a pick into an empty spindle halts the
    // same.
    void anEmptyRackHaltsAsTheFirmwareDoes()
    {
        CarveraEmulator emulator;
        emulator.setRackEmpty(true);
        Lines out = command(emulator, "M6 T2");
        QVERIFY(out.contains("ATC loosed!"));
        QVERIFY(out.contains("M493.2 T-1"));
        QVERIFY(!out.contains("Start picking new tool: T2") || !out.contains("ATC clamped!"));
        QCOMPARE(out.mid(out.size() - 3),
            (Lines { "ERROR: Unexpected tool absence detected, please check tool rack!",
                CarveraEmulator::kHaltLine, "ok" }));
        QCOMPARE(emulator.haltReason(), 7);
        command(emulator, "$X");
        out = command(emulator, "M6 T2");
        QVERIFY(out.contains("M492.1"));
        QCOMPARE(out.mid(out.size() - 3),
            (Lines { "ERROR: Unexpected tool absence detected, please check tool rack!",
                CarveraEmulator::kHaltLine, "ok" }));
        QCOMPARE(emulator.haltReason(), 7);
        QVERIFY(status(emulator).contains("|T:-1,0.000,-1,0|"));
    }

    void aCustomRackDecidesWhatIsManual()
    {
        CarveraEmulator emulator;
        QVERIFY(emulator.inRack(6) && !emulator.inRack(7));
        emulator.setRack(CarveraEmulator::parseToolSlots("7 -10 -20 -100").value());
        QVERIFY(emulator.inRack(7) && !emulator.inRack(2));
        QCOMPARE(command(emulator, "M6 T7").at(2), QByteArray("Start picking new tool: T7"));
        QCOMPARE(command(emulator, "M6 T2 H1").at(2), QByteArray("Start manually picking new tool: T2"));
        QCOMPARE(emulator.tlo(), 1.0);
    }

    void aRackChangeTakesTimeAndCanBeAborted()
    {
        CarveraEmulator emulator;
        emulator.setTiming({ 0, 0, 60000 });
        QSignalSpy lines(&emulator, &CarveraEmulator::lineSent);
        emulator.receiveLine("M6 T2");
        QTest::qWait(100);
        QVERIFY(lines.contains(QVariantList { QByteArray("Start picking new tool: T2") }));
        QVERIFY(!lines.contains(QVariantList { QByteArray("M497.3") })); // the probe has not started
        QVERIFY(status(emulator).startsWith("<Run|"));
        emulator.receiveRealtime(0x18);
        QVERIFY(lines.contains(QVariantList { QByteArray("ERROR: Abort during cycle") }));
        QCOMPARE(emulator.haltReason(), 1);
        QTest::qWait(50);
        QVERIFY(!lines.contains(QVariantList { QByteArray("Done ATC") }));
    }

    void faultsHitAToolChange()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        emulator.injectFault(CarveraEmulator::Fault::FailProbe, "M6");
        Lines out = command(emulator, "M6 T2");
        QVERIFY(out.contains(kProbeAlarm));
        QCOMPARE(emulator.haltReason(), 4);
        command(emulator, "$X");
        emulator.injectFault(CarveraEmulator::Fault::DropOk, "M6");
        out = command(emulator, "M6 T3", 200);
        QCOMPARE(out.mid(out.size() - 2),
            (Lines { "Return to XY position: X-4.965 Y-54.480", "TEST: no terminator" }));
        emulator.injectFault(CarveraEmulator::Fault::BreakTool, "M491.1", 0.5);
        out = command(emulator, "M491.1 H0.1");
        QVERIFY(out.contains("Old: 12.840 , new: 12.340"));
        QVERIFY(out.contains("ERROR: Tool Break Check - check tool for breakage"));
        QCOMPARE(emulator.haltReason(), 4);
        QCOMPARE(emulator.toolLength(3), 47.0); // the picked tool broke, not the one put back
        QCOMPARE(emulator.toolLength(1), 77.7);
    }
};

QTEST_GUILESS_MAIN(TestCarveraRack)
#include "tst_carverarack.moc"
