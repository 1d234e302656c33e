// SPDX-License-Identifier: GPL-3.0-or-later
// grblHAL's build info, its tool table and parameter report, read by pure functions
// (serial/grblhal/grblhalreplies.h), each with what it must refuse. Its status reports, messages, alarms and
// errors: tst_grblhalstatus.
#include <QTest>

#include "tests/serial/grblhallines.h"

using namespace Toffee;
using namespace Toffee::GrblHal;
using namespace Qt::StringLiterals;
using namespace Toffee::Test;

class TestGrblHalReplies : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void readsTheBuildInfoOfThePeer()
    {
        BuildInfoBuilder builder;
        int taken = 0;
        for (const QByteArray &line : kPeerBuildInfo)
            taken += builder.addLine(line) ? 1 : 0;
        QCOMPARE(taken, 5); // VER OPT AXS NEWOPT FIRMWARE; the others are skipped, not refused
        QCOMPARE(builder.refusedLines(), 0);
        QVERIFY(builder.hasVersionAndOptions());
        const BuildInfo &info = builder.info();
        QVERIFY(info.isGrblHal());
        QCOMPARE(info.version, u"1.1f.20260817"_s);
        QCOMPARE(info.buildName, QString());
        QCOMPARE(info.toolTableSize, 16);
        QVERIFY(info.hasToolTable());
        QVERIFY(info.toolChange);
        QVERIFY(!info.automaticToolChanger);
        QCOMPARE(info.axes, u"XYZ"_s);
    }

    void readsEachBuildInfoLine_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<bool>("taken");
        QTest::addColumn<QString>("version");
        QTest::addColumn<QString>("buildName");
        QTest::addColumn<int>("tools");
        QTest::addColumn<bool>("toolChange");
        QTest::addColumn<bool>("atc");
        const QString none;
        QTest::newRow("a named build") << QByteArray("[VER:1.1f.20250101:My mill]") << true
                                       << u"1.1f.20250101"_s << u"My mill"_s << 0 << false << false;
        QTest::newRow("a name with colons") << QByteArray("[VER:1.1f.20250101:a:b]") << true
                                            << u"1.1f.20250101"_s << u"a:b"_s << 0 << false << false;
        QTest::newRow("no table") << QByteArray("[OPT:VNML+,100,1024,3,0]") << true << none << none << 0
                                  << false << false;
        QTest::newRow("32 tools") << QByteArray("[OPT:VNMZHL,35,1024,4,32]") << true << none << none << 32
                                  << false << false;
        QTest::newRow("classic Grbl's three fields")
            << QByteArray("[OPT:V,15,128]") << true << none << none << 0 << false << false;
        QTest::newRow("an ATC") << QByteArray("[NEWOPT:ENUMS,RT+,HOME,ATC=1,SED]") << true << none << none
                                << 0 << true << true;
        QTest::newRow("no tool change")
            << QByteArray("[NEWOPT:ENUMS,RT-,SED]") << true << none << none << 0 << false << false;
        QTest::newRow("TC inside another word")
            << QByteArray("[NEWOPT:ENUMS,ETC,TCX]") << true << none << none << 0 << false << false;
        QTest::newRow("a tool count not a number")
            << QByteArray("[OPT:VNML+,100,1024,3,x]") << false << none << none << 0 << false << false;
        QTest::newRow("a huge tool count") << QByteArray("[OPT:VNML+,100,1024,3,99999999999999999999]")
                                           << false << none << none << 0 << false << false;
        QTest::newRow("a negative tool count")
            << QByteArray("[OPT:VNML+,100,1024,3,-16]") << false << none << none << 0 << false << false;
        QTest::newRow("OPT truncated")
            << QByteArray("[OPT:VNML+,100") << false << none << none << 0 << false << false;
        QTest::newRow("VER without version")
            << QByteArray("[VER::name]") << false << none << none << 0 << false << false;
        QTest::newRow("a million-character name")
            << huge("[VER:1.1f.1:", "]") << false << none << none << 0 << false << false;
        QTest::newRow("a control character in the name")
            << QByteArray("[VER:1.1f.1:a\x01z]") << false << none << none << 0 << false << false;
    }
    void readsEachBuildInfoLine()
    {
        QFETCH(QByteArray, line);
        QFETCH(bool, taken);
        BuildInfoBuilder builder;
        QCOMPARE(builder.addLine(line), taken);
        QCOMPARE(builder.refusedLines(), taken ? 0 : 1);
        QTEST(builder.info().version, "version");
        QTEST(builder.info().buildName, "buildName");
        QTEST(builder.info().toolTableSize, "tools");
        QTEST(builder.info().toolChange, "toolChange");
        QTEST(builder.info().automaticToolChanger, "atc");
    }

    void aRepeatedBuildLineIsRefusedAndTheFirstStands()
    {
        BuildInfoBuilder builder;
        QVERIFY(builder.addLine("[FIRMWARE:grblHAL]"));
        QVERIFY(!builder.addLine("[FIRMWARE:Other]"));
        QVERIFY(builder.addLine("[OPT:VNML+,100,1024,3,16]"));
        QVERIFY(!builder.addLine("[OPT:VNML+,100,1024,3,999]"));
        QCOMPARE(builder.refusedLines(), 2);
        QVERIFY(builder.info().isGrblHal());
        QCOMPARE(builder.info().toolTableSize, 16);
        QVERIFY(!builder.hasVersionAndOptions()); // no [VER:…] yet
    }

    void classicGrblIsNotGrblHal()
    {
        BuildInfoBuilder builder;
        QVERIFY(builder.addLine("[VER:1.1h.20190825:]"));
        QVERIFY(builder.addLine("[OPT:V,15,128]"));
        QVERIFY(!builder.info().isGrblHal());
        QVERIFY(!builder.info().hasToolTable());
    }

    void readsToolEntries_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<int>("number");
        QTest::addColumn<double>("z");
        QTest::addColumn<double>("radius");
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("pocket"); // -1: none
        QTest::newRow("the peer's T3") << QByteArray("[T:3|0.000,0.000,-12.345|1.500|6,0,0||3]\r\n") << true
                                       << 3 << -12.345 << 1.5 << QString() << 3;
        QTest::newRow("no pocket") << QByteArray("[T:7|0.000,0.000,4.000|0.000|6,0,0|]") << true << 7 << 4.0
                                   << 0.0 << QString() << -1;
        QTest::newRow("a name") << QByteArray("[T:12|0.000,0.000,-30.100|3.175|6,0,0|1/8 flat end|4]") << true
                                << 12 << -30.1 << 3.175 << u"1/8 flat end"_s << 4;
        QTest::newRow("a UTF-8 name") << QByteArray("[T:2|0,0,-1|0|6,0,0|Fräser Ø6|2]") << true << 2 << -1.0
                                      << 0.0 << u"Fräser Ø6"_s << 2;
        QTest::newRow("five axes") << QByteArray("[T:4|0.000,0.000,-8.000,0.000,0.000|0.000|6,0,0||4]")
                                   << true << 4 << -8.0 << 0.0 << QString() << 4;
        QTest::newRow("tool 0 of a random changer") << QByteArray("[T:0|0.000,0.000,0.000|0.000|6,0,0||0]")
                                                    << true << 0 << 0.0 << 0.0 << QString() << 0;
        const QString none;
        QTest::newRow("a name with a bar")
            << QByteArray("[T:5|0,0,-1|0|6,0,0|a|b|5]") << false << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("a name with a bar, no pocket")
            << QByteArray("[T:5|0,0,-1|0|6,0,0|a|b]") << false << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("truncated") << QByteArray("[T:3|0.000,0.000,-12.345|1.5") << false << 0 << 0.0 << 0.0
                                   << none << -1;
        QTest::newRow("no closing bracket") << QByteArray("[T:3|0.000,0.000,-12.345|1.500|6,0,0||3") << false
                                            << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("two axes") << QByteArray("[T:3|0.000,-12.345|1.500|6,0,0||3]") << false << 0 << 0.0
                                  << 0.0 << none << -1;
        QTest::newRow("ten axes") << QByteArray("[T:3|0,0,0,0,0,0,0,0,0,0|1.500|6,0,0||3]") << false << 0
                                  << 0.0 << 0.0 << none << -1;
        QTest::newRow("NaN") << QByteArray("[T:3|0.000,0.000,nan|1.500|6,0,0||3]") << false << 0 << 0.0 << 0.0
                             << none << -1;
        QTest::newRow("inf") << QByteArray("[T:3|0.000,0.000,-inf|1.500|6,0,0||3]") << false << 0 << 0.0
                             << 0.0 << none << -1;
        QTest::newRow("1e308") << QByteArray("[T:3|0.000,0.000,1e308|1.500|6,0,0||3]") << false << 0 << 0.0
                               << 0.0 << none << -1;
        QTest::newRow("beyond any machine") << QByteArray("[T:3|0.000,0.000,-100000.001|1.500|6,0,0||3]")
                                            << false << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("a radius of NaN")
            << QByteArray("[T:3|0,0,0|nan|6,0,0||3]") << false << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("a negative tool")
            << QByteArray("[T:-1|0,0,0|0|6,0,0||1]") << false << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("a tool beyond any number")
            << QByteArray("[T:1000000|0,0,0|0|6,0,0||1]") << false << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("a tool number that overflows")
            << QByteArray("[T:99999999999999999999999|0,0,0|0|6,0,0||1]") << false << 0 << 0.0 << 0.0 << none
            << -1;
        QTest::newRow("a pocket not a number")
            << QByteArray("[T:3|0,0,0|0|6,0,0||x]") << false << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("a pocket too large")
            << QByteArray("[T:3|0,0,0|0|6,0,0||100000]") << false << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("a hex number")
            << QByteArray("[T:3|0,0,0x10|0|6,0,0||3]") << false << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("a name too long") << ("[T:3|0,0,0|0|6,0,0|" + QByteArray(256, 'n') + "|3]") << false
                                         << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("a name not UTF-8")
            << QByteArray("[T:3|0,0,0|0|6,0,0|\xff\xfe|3]") << false << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("a million characters")
            << huge("[T:3|0,0,", "|0|6,0,0||3]") << false << 0 << 0.0 << 0.0 << none << -1;
        QTest::newRow("TLO is not a tool")
            << QByteArray("[TLO:0.000,0.000,-12.345]") << false << 0 << 0.0 << 0.0 << none << -1;
    }
    void readsToolEntries()
    {
        QFETCH(QByteArray, line);
        QFETCH(bool, valid);
        const auto tool = parseToolEntry(line);
        QCOMPARE(tool.has_value(), valid);
        if (!valid)
            return;
        QTEST(tool->number, "number");
        QTEST(tool->offset.z(), "z");
        QTEST(tool->radius, "radius");
        QTEST(tool->name, "name");
        QTEST(tool->pocket.value_or(-1), "pocket");
    }

    void readsTheOtherParameterLines()
    {
        const auto g54 = parseWorkOffset("[G54:1.000,-2.500,3.000]\r\n");
        QVERIFY(g54);
        QCOMPARE(g54->name, u"G54"_s);
        QCOMPARE(g54->values.y(), -2.5);
        const auto rotated = parseWorkOffset("[G59.1:1.000,2.000,3.000:45.00]");
        QVERIFY(rotated);
        QCOMPARE(rotated->name, u"G59.1"_s);
        QCOMPARE(rotated->values.z(), 3.0);
        QVERIFY(!parseWorkOffset("[G51:1.000,1.000,1.000]")); // scaling, not an offset
        QVERIFY(!parseWorkOffset("[G54:1.000,nan,3.000]"));
        QVERIFY(!parseWorkOffset("[G54:1.000,2.000,3.000:x]"));
        QVERIFY(!parseWorkOffset("[G54:]"));
        QVERIFY(!parseWorkOffset("[G54"));

        const auto tlo = parseToolLengthOffset("[TLO:0.000,0.000,-12.345]");
        QVERIFY(tlo);
        QCOMPARE(tlo->z(), -12.345);
        const auto oneAxis = parseToolLengthOffset("[TLO:-7.500]"); // a build with one tool length axis
        QVERIFY(oneAxis);
        QCOMPARE(oneAxis->z(), -7.5);
        QCOMPARE(oneAxis->x(), 0.0);
        QVERIFY(!parseToolLengthOffset("[TLO:inf]"));
        QVERIFY(!parseToolLengthOffset("[TLO:]"));

        const auto touched = parseProbeReport("[PRB:0.000,0.000,-70.000:1]\r\n");
        QVERIFY(touched);
        QVERIFY(touched->touched);
        QCOMPARE(touched->position.z(), -70.0);
        const auto missed = parseProbeReport("[PRB:0.000,0.000,-62.344:0]");
        QVERIFY(missed);
        QVERIFY(!missed->touched);
        QVERIFY(!parseProbeReport("[PRB:0.000,0.000,-70.000:ok]")); // grblHAL writes 1 or 0 (report.c)
        QVERIFY(!parseProbeReport("[PRB:0.000,0.000,-70.000:2]"));
        QVERIFY(!parseProbeReport("[PRB:0.000,0.000,-70.000]"));
        QVERIFY(!parseProbeReport("[PRB:0.000,0.000,1e999:1]"));
    }

    // $# as the peer printed it after G10 L1 P3 Z-12.345 R1.5, M61 Q1, a probe and G43 H3.
    void gathersTheParameterReport()
    {
        QByteArrayList lines;
        for (const char *name :
            { "G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3", "G28", "G30", "G92" })
            lines << "[" + QByteArray(name) + ":0.000,0.000,0.000]\r\n";
        for (int n = 1; n <= 16; ++n) {
            const QByteArray z = n == 3 ? "-12.345" : "0.000";
            const QByteArray radius = n == 3 ? "1.500" : "0.000";
            lines << "[T:" + QByteArray::number(n) + "|0.000,0.000," + z + "|" + radius + "|6,0,0||"
                    + QByteArray::number(n) + "]\r\n";
        }
        lines << "[TLO:0.000,0.000,-12.345]\r\n"
              << "[PRB:0.000,0.000,-70.000:1]\r\n"
              << "ok\r\n";
        ParameterReport report;
        int taken = 0;
        for (const QByteArray &line : std::as_const(lines))
            taken += report.addLine(line) ? 1 : 0;
        QCOMPARE(taken, 12 + 16 + 2);
        QCOMPARE(report.refusedLines, 0);
        QCOMPARE(report.workOffsets.size(), 12);
        QCOMPARE(report.tools.size(), size_t(16));
        QCOMPARE(report.tools.at(3).offset.z(), -12.345);
        QCOMPARE(report.tools.at(3).radius, 1.5);
        QCOMPARE(report.tools.at(3).pocket, std::optional<int>(3));
        QCOMPARE(report.toolLengthOffset->z(), -12.345);
        QVERIFY(report.probe->touched);
        QCOMPARE(report.probe->position.z(), -70.0);
        QVERIFY(!report.toolLengthReference);
        QVERIFY(report.addLine("[TLR:-95.000]"));
        QCOMPARE(report.toolLengthReference, std::optional<double>(-95.0));
    }

    void aParameterReportRefusesWhatItCannotTrust()
    {
        ParameterReport report;
        QVERIFY(report.addLine("[T:3|0,0,-1|0|6,0,0||3]"));
        QVERIFY(!report.addLine("[T:3|0,0,-2|0|6,0,0||3]")); // a tool twice: the first stands, counted
        QCOMPARE(report.tools.at(3).offset.z(), -1.0);
        QVERIFY(report.addLine("[G54:0,0,0]"));
        QVERIFY(!report.addLine("[G54:1,1,1]"));
        QVERIFY(report.addLine("[TLO:0,0,-1]"));
        QVERIFY(!report.addLine("[TLO:0,0,-2]"));
        QVERIFY(report.addLine("[PRB:0,0,-1:1]"));
        QVERIFY(!report.addLine("[PRB:0,0,-2:1]"));
        QVERIFY(!report.addLine("[T:4|0,0,nan|0|6,0,0||4]"));
        QVERIFY(!report.addLine("[G54:0,0"));
        QVERIFY(!report.addLine(huge("[T:5|0,0,", "|0|6,0,0||5]")));
        QCOMPARE(report.refusedLines, 7);
        // Lines of $# that are not read, and lines of other replies, are skipped, not refused.
        QVERIFY(!report.addLine("[HOME:0.000,0.000,0.000:7]"));
        QVERIFY(!report.addLine("[G51:1.000,1.000,1.000]"));
        QVERIFY(!report.addLine("ok"));
        QVERIFY(!report.addLine(""));
        QCOMPARE(report.refusedLines, 7);
    }

    void keepsAtMostTheToolsItBounds()
    {
        ParameterReport report;
        for (int n = 1; n <= kMaxTools + 50; ++n)
            report.addLine(QByteArray("[T:" + QByteArray::number(n) + "|0,0,-1|0|6,0,0|]"));
        QCOMPARE(report.tools.size(), size_t(kMaxTools));
        QCOMPARE(report.refusedLines, 50);
    }
};

QTEST_GUILESS_MAIN(TestGrblHalReplies)
#include "tst_grblhalreplies.moc"
