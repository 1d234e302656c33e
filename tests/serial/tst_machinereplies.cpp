// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "serial/machinereplies.h"

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
        QCOMPARE(report->tlo(), -33.388); // not -33.388000000000005
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
        QTest::newRow("garbled T") << QByteArray("<Idle|MPos:1,2,3|T:x,1>") << false << QString() << 0.0
                                   << 0.0 << -1 << 0.0 << 0;
        QTest::newRow("T999999, the last probe number")
            << QByteArray("<Idle|MPos:1,2,3|T:999999,0.5>") << true << u"Idle"_s << 3.0 << 0.0 << 999999
            << 0.5 << 0;
        QTest::newRow("T-1, the empty spindle")
            << QByteArray("<Idle|MPos:1,2,3|T:-1,0>") << true << u"Idle"_s << 3.0 << 0.0 << -1 << 0.0 << 0;
        QTest::newRow("T beyond any tool") << QByteArray("<Idle|MPos:1,2,3|T:1000000,0>") << false
                                           << QString() << 0.0 << 0.0 << -1 << 0.0 << 0;
        // Found by fuzz-replies: taken as an int, 19999999999 wrapped round to another tool's number.
        QTest::newRow("T wrapping an int") << QByteArray("<Idle|MPos:1,2,3|T:19999999999,0>") << false
                                           << QString() << 0.0 << 0.0 << -1 << 0.0 << 0;
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
            QVERIFY(qFuzzyCompare(1.0 + r->tlo(), 1.0 + tlo));
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
};

QTEST_GUILESS_MAIN(TestMachineReplies)
#include "tst_machinereplies.moc"
