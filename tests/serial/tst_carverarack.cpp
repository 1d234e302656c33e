// SPDX-License-Identifier: GPL-3.0-or-later
// The two firmwares, the rack and the tool change, as the emulator plays them (docs/CARVERA.md § 7, § 8).
#include <QSignalSpy>
#include <QTest>

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

const QByteArray kProbeAlarm = "ALARM: Probe failed to trigger within safety margin (135.00mm)";

} // namespace

class TestCarveraRack : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void answersVersionInBothFirmwares()
    {
        CarveraEmulator emulator;
        QCOMPARE(emulator.firmware(), Firmware::Community);
        const Lines community { "version = 2.1.0c", "ok" };
        QCOMPARE(command(emulator, "version  "), community);
        QCOMPARE(QByteArray(CarveraEmulator::kCommunityVersion), QByteArray("2.1.0c"));
        emulator.setFirmware(Firmware::Stock);
        emulator.halt(3);
        const Lines stock { "version = 1.0.1", "ok" };
        QCOMPARE(command(emulator, "version"), stock); // a shell command: it runs while halted
        QVERIFY(emulator.isHalted());
        QCOMPARE(command(emulator, "M491"), Lines { "error:Alarm lock" });
    }

    // M493.3 and M493.4 answer only "ok"; M491.1 is a plain M491: no comparison, no halt, no tolerance check.
    void stockIgnoresWhatItDoesNotHave()
    {
        CarveraEmulator emulator;
        emulator.setFirmware(Firmware::Stock);
        command(emulator, "M491"); // the reference: T1's -72.300
        QCOMPARE(command(emulator, "M493.3 Z-5"), Lines { "ok" });
        QCOMPARE(command(emulator, "M493.4"), Lines { "ok" });
        QCOMPARE(emulator.currentMz(), -72.3);
        emulator.breakTool(1, 0.5);
        Lines out = command(emulator, "M491.1 H0.05");
        QVERIFY(out.contains("M493.1"));
        QVERIFY(!out.join('\n').contains("Old:"));
        QCOMPARE(out.last(), QByteArray("ok"));
        QVERIFY(near(emulator.tlo(), -0.5)); // the broken tool's TLO, adopted silently
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
            QCOMPARE(command(emulator, change).last(), QByteArray("ok"));
        const QByteArray report = status(emulator);
        QVERIFY2(field.isEmpty() ? !report.contains("|T:") : report.contains(field), report.constData());
    }

    void alarmsOnInches()
    {
        for (const Firmware firmware : { Firmware::Community, Firmware::Stock }) {
            CarveraEmulator emulator;
            emulator.setFirmware(firmware);
            const Lines alarm { "ALARM: Imperial Units are unsupported", "ok" };
            QCOMPARE(command(emulator, "G0 G20 X1"), alarm);
            QCOMPARE(emulator.haltReason(), 1);
            QVERIFY(status(emulator).contains("|MPos:0.0000,0.0000,")); // it did not move
        }
    }

    void repeatsAMeasurement()
    {
        CarveraEmulator emulator;
        command(emulator, "M491"); // T1: the reference, -72.300
        command(emulator, "M493.2 T2");
        emulator.setRepeatability(0.01);
        const Lines out = command(emulator, "M491 R3");
        const qsizetype first = out.indexOf("TLO measurement 1 of 3: -33.388");
        QVERIFY2(first > 0, out.join('\n').constData());
        QCOMPARE(out.at(first - 1), QByteArray("[PRB:-88.000,-9.000,-105.688:1]"));
        const Lines tail { "TLO measurement 1 of 3: -33.388", "[PRB:-88.000,-9.000,-105.678:1]",
            "TLO measurement 2 of 3: -33.378", "[PRB:-88.000,-9.000,-105.698:1]",
            "TLO measurement 3 of 3: -33.398", "Max delta: 0.020", "Using TLO: -33.388",
            "Return to XY position: X0.000 Y0.000", "Done ATC", "ok" };
        QCOMPARE(out.mid(first), tail);
        QVERIFY(near(emulator.tlo(), -33.388));
        QVERIFY(!out.contains("M493.1"));
    }

    void refusesRepeatsOutOfRange()
    {
        CarveraEmulator emulator;
        for (const QByteArray line : { "M491 R0", "M491 R11", "M491 R2.5", "M491 R" })
            QCOMPARE(command(emulator, line), Lines { "error:Unsupported command - " + line });
        QVERIFY(!emulator.isHalted());
        emulator.setFirmware(Firmware::Stock); // R ignored: one plain measurement
        const Lines out = command(emulator, "M491 R11");
        QVERIFY(out.contains("M493.1"));
        QVERIFY(!out.join('\n').contains("TLO measurement"));
    }

    void changesARackToolAndAlwaysMeasuresIt()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        const Lines change { "Start dropping current tool: T1", "Start picking new tool: T2", "M497.3",
            "G53 G0 Z-10.000", "G53 G0 X-88.000 Y-9.000", "G38.6 Z-145.000 F500",
            "[PRB:-88.000,-9.000,-105.688:1]", "M493.1", "Return to XY position: X0.000 Y0.000", "Done ATC",
            "ok" };
        QCOMPARE(command(emulator, "M6 T2"), change);
        QCOMPARE(emulator.tool(), 2);
        QVERIFY(near(emulator.tlo(), -33.388));
        const Lines out = command(emulator, "M6 T3 H-1"); // H is for manual changes only
        QVERIFY(out.contains("[PRB:-88.000,-9.000,-102.500:1]")); // T3: 47.5 mm
        QVERIFY(near(emulator.tlo(), -30.2));
    }

    void stockSaysOneLineForAChange()
    {
        CarveraEmulator emulator;
        emulator.setFirmware(Firmware::Stock);
        Lines out = command(emulator, "M6 T2");
        QCOMPARE(out.front(), QByteArray("Start atc, old tool: T1, new tool: T2"));
        QCOMPARE(out.at(1), QByteArray("M497.3"));
        QCOMPARE(command(emulator, "M6 T-1"), (Lines { "Start dropping current tool: T2", "ok" }));
        QCOMPARE(emulator.tool(), -1);
        out = command(emulator, "M6 T3");
        QCOMPARE(out.front(), QByteArray("Start picking new tool: T3"));
        QVERIFY(out.contains("Done ATC"));
    }

    void picksIntoAnEmptySpindle()
    {
        CarveraEmulator emulator;
        QCOMPARE(command(emulator, "M6 T-1"), (Lines { "Start dropping current tool: T1", "ok" }));
        QCOMPARE(emulator.tool(), -1);
        const Lines out = command(emulator, "M6 T2");
        QCOMPARE(out.front(), QByteArray("Start picking new tool: T2"));
        QCOMPARE(out.at(1), QByteArray("M497.3"));
    }

    void changesByHandOutsideTheRack()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        Lines out = command(emulator, "M6 T0"); // the wireless probe has no slot
        QCOMPARE(out.mid(0, 3),
            (Lines { "Start dropping current tool: T1", "Start manually picking new tool: T0", "M497.3" }));
        QVERIFY(out.contains("Done ATC"));
        out = command(emulator, "M6 T999990 H2.5");
        QCOMPARE(out,
            (Lines { "Start dropping current tool: T0", "Start manually picking new tool: T999990", "ok" }));
        QCOMPARE(emulator.tlo(), 2.5);
    }

    void theSameToolIsNoChange()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        QCOMPARE(command(emulator, "M6 T1"), Lines { "ok" });
        QCOMPARE(command(emulator, "M6 T1 H5"), Lines { "ok" });
        QCOMPARE(emulator.tlo(), 0.0);
    }

    void alarmsOnAnInvalidTool()
    {
        for (const QByteArray t : { "1000000", "-2", "2.5" }) {
            CarveraEmulator emulator;
            QCOMPARE(command(emulator, "M6 T" + t), (Lines { "ALARM: Invalid tool: T" + t, "ok" }));
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

    void aCustomRackDecidesWhatIsManual()
    {
        CarveraEmulator emulator;
        QVERIFY(emulator.inRack(6) && !emulator.inRack(7));
        emulator.setRack(CarveraEmulator::parseToolSlots("7 -10 -20 -100").value());
        QVERIFY(emulator.inRack(7) && !emulator.inRack(2));
        QCOMPARE(command(emulator, "M6 T7").at(1), QByteArray("Start picking new tool: T7"));
        QCOMPARE(command(emulator, "M6 T2 H1").at(1), QByteArray("Start manually picking new tool: T2"));
        QCOMPARE(emulator.tlo(), 1.0);
    }

    void aRackChangeTakesTimeAndCanBeAborted()
    {
        CarveraEmulator emulator;
        emulator.setTiming({ 0, 0, 60000 });
        QCOMPARE(command(emulator, "M6 T7 H1").last(), QByteArray("ok")); // by hand: no wait
        QSignalSpy lines(&emulator, &CarveraEmulator::lineSent);
        emulator.receiveLine("M6 T2");
        QTest::qWait(100);
        QCOMPARE(lines.size(), 2); // the drop and pick lines; the probe has not started
        QCOMPARE(lines.at(1).front().toByteArray(), QByteArray("Start picking new tool: T2"));
        QVERIFY(status(emulator).startsWith("<Run|"));
        emulator.receiveRealtime(0x18);
        QCOMPARE(lines.last().front().toByteArray(), QByteArray("ALARM: Abort during cycle"));
        QCOMPARE(emulator.haltReason(), 1);
        QTest::qWait(50);
        QVERIFY(!lines.contains(QVariantList { QByteArray("ok") }));
    }

    void faultsHitAToolChange()
    {
        CarveraEmulator emulator;
        command(emulator, "M491");
        emulator.injectFault(CarveraEmulator::Fault::FailProbe, "M6");
        Lines out = command(emulator, "M6 T2");
        QVERIFY(out.contains(kProbeAlarm));
        QCOMPARE(emulator.haltReason(), 3);
        command(emulator, "$X");
        emulator.injectFault(CarveraEmulator::Fault::DropOk, "M6");
        out = command(emulator, "M6 T3", 200);
        QCOMPARE(out.mid(out.size() - 2), (Lines { "Done ATC", "TEST: no terminator" }));
        emulator.injectFault(CarveraEmulator::Fault::BreakTool, "M491.1", 0.5);
        out = command(emulator, "M491.1 H0.1");
        QVERIFY(out.contains("Old: -30.200 , new: -30.700"));
        QVERIFY(out.contains("ERROR: Tool Break Check - check tool for breakage"));
        QCOMPARE(emulator.haltReason(), 4);
        QCOMPARE(emulator.toolLength(3), 47.0); // the picked tool broke, not the one put back
        QCOMPARE(emulator.toolLength(1), 77.7);
    }
};

QTEST_GUILESS_MAIN(TestCarveraRack)
#include "tst_carverarack.moc"
