// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "serial/carvera/carverareplies.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestMachineReplies : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void aTloIsAtTheMachinesResolution()
    {
        const auto report
            = parseTloReport("current tool offset [-105.688] , reference tool offset [-72.300]");
        QVERIFY(report);
        const TloReading reading = TloReading::from(report->currentMz - report->referenceMz, report);
        QCOMPARE(reading.tlo(), -33.388); // not -33.388000000000005
        QCOMPARE(reading.currentMz, -105.688);
    }

    // After a probe, M493.4's current - reference is the TLO in force: the current MCS Z is known. After
    // M493.3 Z-10.5 the firmware prints -10.5 as "current" and the status report's TLO is -10.5: there is no
    // MCS Z of the tool then, and none is made up (seen on the firmware).
    void theCurrentMcsZIsKeptOnlyWhenItAddsUpToTheTloInForce_data()
    {
        QTest::addColumn<QByteArray>("report");
        QTest::addColumn<double>("tloInForce");
        QTest::addColumn<bool>("currentKnown");
        QTest::newRow("after a probe")
            << QByteArray("current tool offset [-108.425] , reference tool offset [-115.340]") << 6.915
            << true;
        QTest::newRow("after M493.3 Z-10.5")
            << QByteArray("current tool offset [-10.500] , reference tool offset [-115.340]") << -10.5
            << false;
        QTest::newRow("a fresh machine")
            << QByteArray("current tool offset [0.000] , reference tool offset [-115.340]") << 0.0 << false;
    }
    void theCurrentMcsZIsKeptOnlyWhenItAddsUpToTheTloInForce()
    {
        QFETCH(QByteArray, report);
        QFETCH(double, tloInForce);
        QFETCH(bool, currentKnown);
        const auto parsed = parseTloReport(report);
        QVERIFY(parsed);
        const TloReading reading = TloReading::from(tloInForce, parsed);
        QCOMPARE(reading.tlo(), tloInForce); // the TLO is the one in force, never current - reference
        QCOMPARE(reading.referenceMz, -115.34);
        QCOMPARE(reading.currentMz.has_value(), currentKnown);
    }

    // The firmware's `version` says what its build was named: only a plain release number is Makera's.
    void tellsTheFirmwareFromItsVersion_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<int>("kind");
        const int community = int(FirmwareInfo::Kind::Community);
        const int stock = int(FirmwareInfo::Kind::Stock);
        QTest::newRow("the peer") << QByteArray("version = 2.1.0c-simulator") << community;
        QTest::newRow("a tag") << QByteArray("version = 2.1.0c") << community;
        QTest::newRow("a branch") << QByteArray("version = Dev-78afb9f") << community;
        QTest::newRow("a pull request") << QByteArray("version = pr-355-78afb9f") << community;
        QTest::newRow("an alpha") << QByteArray("version = vcommunity_1.0.5alpha6") << community;
        QTest::newRow("an older tag") << QByteArray("version = v1.0.3c1.0.6") << community;
        QTest::newRow("git describe") << QByteArray("version = v2.1.0c-3-gabc1234") << community;
        QTest::newRow("Makera 1.0.5") << QByteArray("version = 1.0.5") << stock;
        QTest::newRow("Makera 0.9.13") << QByteArray("version = 0.9.13") << stock;
        QTest::newRow("Makera 1.0") << QByteArray("version = 1.0") << stock;
    }
    void tellsTheFirmwareFromItsVersion()
    {
        QFETCH(QByteArray, line);
        QFETCH(int, kind);
        const auto info = parseVersion(line);
        QVERIFY(info);
        QCOMPARE(int(info->kind), kind);
        QCOMPARE(info->version, QString::fromLatin1(line.mid(10)));
    }

    // How each kind of command's reply ends on the firmware: a script to "Done ATC", `version` with its one
    // line, $X and lower-case shell words perhaps with nothing.
    void knowsHowEachRepliesEnd_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<int>("end");
        QTest::newRow("M491") << QByteArray("M491") << int(ReplyEnd::Script);
        QTest::newRow("M491.1 H0.05") << QByteArray("M491.1 H0.05") << int(ReplyEnd::Script);
        QTest::newRow("M6 T2") << QByteArray("M6 T2") << int(ReplyEnd::Script);
        QTest::newRow("m6t2, lower case") << QByteArray("m6t2") << int(ReplyEnd::Quiet);
        QTest::newRow("M493.4") << QByteArray("M493.4") << int(ReplyEnd::Ok);
        QTest::newRow("M493.2 T1") << QByteArray("M493.2 T1") << int(ReplyEnd::Ok);
        QTest::newRow("G0 X1") << QByteArray("G0 X1") << int(ReplyEnd::Ok);
        QTest::newRow("version") << QByteArray("version") << int(ReplyEnd::Line);
        QTest::newRow("$X") << QByteArray("$X") << int(ReplyEnd::Quiet);
        QTest::newRow("$I: the state, no ok") << QByteArray("$I") << int(ReplyEnd::Quiet);
        QTest::newRow("$J X1: no ok") << QByteArray("$J X1") << int(ReplyEnd::Quiet);
        QTest::newRow("$G") << QByteArray("$G") << int(ReplyEnd::Ok);
        QTest::newRow("$#") << QByteArray("$#") << int(ReplyEnd::Ok);
        QTest::newRow("$H") << QByteArray("$H") << int(ReplyEnd::Ok);
        QTest::newRow("$Q: error:Invalid statement") << QByteArray("$Q") << int(ReplyEnd::Quiet);
        QTest::newRow("echo echo") << QByteArray("echo echo") << int(ReplyEnd::Quiet);
        QTest::newRow("empty") << QByteArray("") << int(ReplyEnd::Ok);
    }
    void knowsHowEachRepliesEnd()
    {
        QFETCH(QByteArray, line);
        QFETCH(int, end);
        QCOMPARE(int(replyEndFor(line)), end);
        QVERIFY(isScriptDone("Done ATC\r"));
        QVERIFY(!isScriptDone("Done ATC soon"));
    }

    void classifiesByExactToken_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<int>("kind");
        QTest::newRow("ok") << QByteArray("ok") << int(ReplyKind::Ok);
        QTest::newRow("ok with CR") << QByteArray("ok\r") << int(ReplyKind::Ok);
        QTest::newRow("okay is not ok") << QByteArray("okay") << int(ReplyKind::Other);
        QTest::newRow("ok inside a line") << QByteArray("Probe ok") << int(ReplyKind::Other);
        QTest::newRow("ok then text") << QByteArray("ok T1") << int(ReplyKind::Other);
        QTest::newRow("error") << QByteArray("error:Alarm lock") << int(ReplyKind::Error);
        QTest::newRow("error inside a line") << QByteArray("no error:here") << int(ReplyKind::Other);
        QTest::newRow("unsupported") << QByteArray("error:Unsupported command - M999.9")
                                     << int(ReplyKind::Error);
        QTest::newRow("alarm") << QByteArray("ALARM: Probe failed to trigger within safety margin (135.00mm)")
                               << int(ReplyKind::Alarm);
        QTest::newRow("abort") << QByteArray("ALARM: Abort during cycle") << int(ReplyKind::Alarm);
        QTest::newRow("halting error")
            << QByteArray("ERROR: Tool Break Check - check tool for breakage") << int(ReplyKind::HaltError);
        QTest::newRow("status") << QByteArray("<Idle|MPos:0,0,0,0,0>") << int(ReplyKind::Status);
        QTest::newRow("echo") << QByteArray("G38.6 Z-145.000 F500") << int(ReplyKind::Other);
        QTest::newRow("garbage") << QByteArray("\xbf\xbf\x01") << int(ReplyKind::Other);
        QTest::newRow("empty") << QByteArray() << int(ReplyKind::Other);
    }
    void classifiesByExactToken()
    {
        QFETCH(QByteArray, line);
        QFETCH(int, kind);
        QCOMPARE(int(classifyReply(line)), kind);
    }

    void readsMessages()
    {
        QCOMPARE(replyMessage("error:Alarm lock"), u"Alarm lock"_s);
        QCOMPARE(replyMessage("ALARM: Abort during cycle"), u"Abort during cycle"_s);
    }

    void parsesStatusReports_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<QString>("state");
        QTest::addColumn<double>("mz");
        QTest::addColumn<double>("wz");
        QTest::addColumn<int>("tool");
        QTest::addColumn<double>("tlo");
        QTest::addColumn<int>("halt");
        QTest::newRow("firmware example") << QByteArray(
            "<Idle|MPos:0.0000,0.0000,-2.0000,0.0000,0.0000|WPos:0.0000,0.0000,57.0000,0.0000,0.0000|"
            "R:0.0000|G:0|F:0.0,3000.0,100.0|S:0.0,0.0,100.0,0,23.5,24.1|T:2,-33.388,-1,0|W:0.00|"
            "C:1,0,0,1>") << true << u"Idle"_s
                                          << -2.0 << 57.0 << 2 << -33.388 << 0;
        QTest::newRow("halted") << QByteArray("<Alarm|MPos:0,0,-145,0,0|WPos:0,0,0,0,0|T:1,0.000,-1,0|H:3>")
                                << true << u"Alarm"_s << -145.0 << 0.0 << 1 << 0.0 << 3;
        QTest::newRow("unknown fields skipped")
            << QByteArray("<Run|Q:what|MPos:1,2,3,4,5|Z|NEW:1,2|WPos:1,2,3,4,5>") << true << u"Run"_s << 3.0
            << 3.0 << -1 << 0.0 << 0;
        QTest::newRow("three axes") << QByteArray("<Idle|MPos:1,2,3>") << true << u"Idle"_s << 3.0 << 0.0
                                    << -1 << 0.0 << 0;
        QTest::newRow("no MPos") << QByteArray("<Idle|WPos:1,2,3>") << false << QString() << 0.0 << 0.0 << -1
                                 << 0.0 << 0;
        QTest::newRow("garbled number")
            << QByteArray("<Idle|MPos:1,\xbf,3>") << false << QString() << 0.0 << 0.0 << -1 << 0.0 << 0;
        // No machine is at 1e308 mm: a status that says so is garbage (it once printed 309 digits).
        QTest::newRow("position beyond any machine") << QByteArray("<Idle|MPos:0,0,1e308,0,0|WPos:0,0,0,0,0>")
                                                     << false << QString() << 0.0 << 0.0 << -1 << 0.0 << 0;
        QTest::newRow("garbled T") << QByteArray("<Idle|MPos:1,2,3|T:x,1>") << false << QString() << 0.0
                                   << 0.0 << -1 << 0.0 << 0;
        QTest::newRow("T999999, the last probe number")
            << QByteArray("<Idle|MPos:1,2,3|T:999999,0.5>") << true << u"Idle"_s << 3.0 << 0.0 << 999999
            << 0.5 << 0;
        QTest::newRow("T-1, the empty spindle")
            << QByteArray("<Idle|MPos:1,2,3|T:-1,0>") << true << u"Idle"_s << 3.0 << 0.0 << -1 << 0.0 << 0;
        // The firmware takes M493.2 T1000000 (or T-2) and reports it: the report holds no tool then, but its
        // state and position still count (every report refused would look like a dead link).
        QTest::newRow("T beyond any tool") << QByteArray("<Idle|MPos:1,2,3|T:1000000,6.915>") << true
                                           << u"Idle"_s << 3.0 << 0.0 << -1 << 6.915 << 0;
        QTest::newRow("T-2") << QByteArray("<Idle|MPos:1,2,3|T:-2,0.000,-1,0>") << true << u"Idle"_s << 3.0
                             << 0.0 << -1 << 0.0 << 0;
        // Found by fuzz-replies: taken as an int, 19999999999 wrapped round to another tool's number.
        QTest::newRow("T wrapping an int") << QByteArray("<Idle|MPos:1,2,3|T:19999999999,0>") << true
                                           << u"Idle"_s << 3.0 << 0.0 << -1 << 0.0 << 0;
        QTest::newRow("the real firmware, halted") << QByteArray(
            "<Alarm|MPos:-4.9650,-54.4800,-20.0000,0.4875,0.0000|WPos:-4.9650,-54.4800,-26.9150,0.4875,0."
            "0000|"
            "R:0.0000|G:0|F:0.0,5000.0,100.0|S:0.0,10000.0,100.0,0,25.0,0.0,0,0,0|T:1,6.915,-1,0|W:0.00|"
            "L:0, 0, 0, 0.0,100.0|P:93980767033532,0,0,0,93980767033532|H:4|C:1,6,0,0|PWM:0.000>")
                                                   << true << u"Alarm"_s << -20.0 << -26.915 << 1 << 6.915
                                                   << 4;
        QTest::newRow("H wrapping an int") << QByteArray("<Alarm|MPos:1,2,3|H:4294967299>") << false
                                           << QString() << 0.0 << 0.0 << -1 << 0.0 << 0;
        QTest::newRow("H negative") << QByteArray("<Alarm|MPos:1,2,3|H:-3>") << false << QString() << 0.0
                                    << 0.0 << -1 << 0.0 << 0;
        QTest::newRow("no closing bracket")
            << QByteArray("<Idle|MPos:1,2,3") << false << QString() << 0.0 << 0.0 << -1 << 0.0 << 0;
        QTest::newRow("empty state") << QByteArray("<|MPos:1,2,3>") << false << QString() << 0.0 << 0.0 << -1
                                     << 0.0 << 0;
        QTest::newRow("too few axes")
            << QByteArray("<Idle|MPos:1,2>") << false << QString() << 0.0 << 0.0 << -1 << 0.0 << 0;
    }
    void parsesStatusReports()
    {
        QFETCH(QByteArray, line);
        QFETCH(bool, valid);
        const auto status = parseStatusReport(line);
        QCOMPARE(status.has_value(), valid);
        if (!valid)
            return;
        QFETCH(QString, state);
        QFETCH(double, mz);
        QFETCH(double, wz);
        QFETCH(int, tool);
        QFETCH(double, tlo);
        QFETCH(int, halt);
        QCOMPARE(status->state, state);
        QCOMPARE(status->mpos[2], mz);
        QCOMPARE(status->wpos[2], wz);
        QCOMPARE(status->tool.value_or(-1), tool);
        QCOMPARE(status->tlo.value_or(0.0), tlo);
        QCOMPARE(status->haltReason.value_or(0), halt);
        QCOMPARE(status->isAlarm(), halt != 0);
    }

    void parsesTheTloReport_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<double>("tlo");
        QTest::newRow("seed") << QByteArray(
            "current tool offset [-105.688] , reference tool offset [-72.300]")
                              << true << -33.388;
        QTest::newRow("zero") << QByteArray("current tool offset [0.000] , reference tool offset [0.000]")
                              << true << 0.0;
        QTest::newRow("CR") << QByteArray("current tool offset [1.5] , reference tool offset [0.5]\r") << true
                            << 1.0;
        QTest::newRow("second report line")
            << QByteArray("no one-off tool setter position offsets configured") << false << 0.0;
        QTest::newRow("garbled") << QByteArray(
            "current tool offset [-\xbf\xbf.688] , reference tool offset [-72.300]")
                                 << false << 0.0;
        QTest::newRow("trailing text")
            << QByteArray("current tool offset [1] , reference tool offset [2] extra") << false << 0.0;
        QTest::newRow("missing bracket")
            << QByteArray("current tool offset [1 , reference tool offset [2]") << false << 0.0;
        // Values no machine can have: a difference of infinity would print as "TLO inf mm".
        QTest::newRow("1e308 apart") << QByteArray(
            "current tool offset [1e308] , reference tool offset [-1e308]")
                                     << false << 0.0;
        QTest::newRow("beyond 100 m")
            << QByteArray("current tool offset [100000.001] , reference tool offset [0]") << false << 0.0;
        QTest::newRow("at 100 m") << QByteArray(
            "current tool offset [100000] , reference tool offset [-100000]")
                                  << true << 200000.0;
    }
    void parsesTheTloReport()
    {
        QFETCH(QByteArray, line);
        QFETCH(bool, valid);
        QFETCH(double, tlo);
        const auto r = parseTloReport(line);
        QCOMPARE(r.has_value(), valid);
        if (valid)
            QVERIFY(qFuzzyCompare(1.0 + (r->currentMz - r->referenceMz), 1.0 + tlo));
    }

    void parsesProbeResults_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<bool>("triggered");
        QTest::addColumn<double>("z");
        QTest::newRow("ok") << QByteArray("[PRB:-88.000,-9.000,-72.300:ok]") << true << true << -72.3;
        QTest::newRow("grbl 1") << QByteArray("[PRB:-88.000,-9.000,-105.688:1]") << true << true << -105.688;
        QTest::newRow("grbl 0") << QByteArray("[PRB:0,0,0:0]") << true << false << 0.0;
        QTest::newRow("garbled") << QByteArray("[PRB:-\xbf\xbf.000,-9.000,-72.300:1]") << false << false
                                 << 0.0;
        QTest::newRow("two axes") << QByteArray("[PRB:1,2:1]") << false << false << 0.0;
        QTest::newRow("no flag") << QByteArray("[PRB:1,2,3]") << false << false << 0.0;
        QTest::newRow("odd flag") << QByteArray("[PRB:1,2,3:maybe]") << false << false << 0.0;
    }
    void parsesProbeResults()
    {
        QFETCH(QByteArray, line);
        QFETCH(bool, valid);
        QFETCH(bool, triggered);
        QFETCH(double, z);
        const auto p = parseProbeResult(line);
        QCOMPARE(p.has_value(), valid);
        if (!valid)
            return;
        QCOMPARE(p->triggered, triggered);
        QCOMPARE(p->z, z);
    }

    void parsesTheBreakTest_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<double>("oldTlo");
        QTest::addColumn<double>("newTlo");
        QTest::newRow("firmware") << QByteArray("Old: -33.388 , new: -33.390") << true << -33.388 << -33.39;
        QTest::newRow("broken") << QByteArray("Old: -33.388 , new: -34.388") << true << -33.388 << -34.388;
        QTest::newRow("no new") << QByteArray("Old: -33.388") << false << 0.0 << 0.0;
        QTest::newRow("garbled") << QByteArray("Old: -\xbf.388 , new: -33.390") << false << 0.0 << 0.0;
        QTest::newRow("other line") << QByteArray("No previous TLO included, aborting") << false << 0.0
                                    << 0.0;
        QTest::newRow("1e308") << QByteArray("Old: 1e308 , new: -1e308") << false << 0.0 << 0.0;
    }
    void parsesTheBreakTest()
    {
        QFETCH(QByteArray, line);
        QFETCH(bool, valid);
        QFETCH(double, oldTlo);
        QFETCH(double, newTlo);
        const auto b = parseBreakTest(line);
        QCOMPARE(b.has_value(), valid);
        if (!valid)
            return;
        QCOMPARE(b->oldTlo, oldTlo);
        QCOMPARE(b->newTlo, newTlo);
    }

    void namesHaltReasons()
    {
        QCOMPARE(haltReasonName(3), u"PROBE_FAIL (3)"_s);
        QCOMPARE(haltReasonName(16), u"CRASH_DETECTED (16)"_s);
        QVERIFY(haltReasonName(22).contains(u"22"_s));
        QVERIFY(haltRecovery(4).contains(u"Unlock"_s));
        QVERIFY(haltRecovery(23).contains(u"reset"_s));
        QVERIFY(haltRecovery(41).contains(u"off and on"_s));
    }

    // The halting lines the firmwares print, explained; others are left to the status report's reason.
    void explainsTheHaltingLinesItKnows_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<QString>("said");
        QTest::newRow("setter never touched") << QByteArray("ERROR: Calibrate fail!") << u"never touched"_s;
        QTest::newRow("stock: safety margin")
            << QByteArray("ALARM: Probe failed to trigger within safety margin (151.40mm)")
            << u"safety margin"_s;
        QTest::newRow("community: not homed")
            << QByteArray("ERROR: Machine has not been homed. Use M888 to disable homed check") << u"home"_s;
        QTest::newRow("stock: not homed") << QByteArray("Machine has not been homed") << u"home"_s;
        QTest::newRow("invalid tool") << QByteArray("ERROR: Invalid tool: T1000001") << u"not a valid tool"_s;
        QTest::newRow("no slot") << QByteArray("ERROR: Tool T9 not defined in tool slots")
                                 << u"not a valid tool"_s;
        QTest::newRow("unknown") << QByteArray("ERROR: Can not do ATC in laser mode!") << QString();
    }
    void explainsTheHaltingLinesItKnows()
    {
        QFETCH(QByteArray, line);
        QFETCH(QString, said);
        const QString meaning = haltLineMeaning(replyMessage(line));
        if (said.isEmpty())
            QVERIFY(meaning.isEmpty());
        else
            QVERIFY2(meaning.contains(said), qPrintable(meaning));
    }
};

QTEST_GUILESS_MAIN(TestMachineReplies)
#include "tst_machinereplies.moc"
