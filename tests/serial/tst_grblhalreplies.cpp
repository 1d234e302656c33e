// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTest>

#include "serial/grblhal/grblhalreplies.h"

using namespace Toffee;
using namespace Toffee::GrblHal;
using namespace Qt::StringLiterals;

namespace {

// A million characters: a line no controller sends, which must cost little and conclude nothing.
QByteArray huge(const QByteArray &head, const QByteArray &tail)
{
    return head + QByteArray(1000000, '1') + tail;
}

// What $I printed on the peer (../shared/peers/grblhal), line ends and all.
const QByteArrayList kPeerBuildInfo { "[VER:1.1f.20260817:]\r\n", "[OPT:VNML+,100,1024,3,16]\r\n",
    "[AXS:3:XYZ]\r\n", "[NEWOPT:ENUMS,RT+,TC,SED]\r\n", "[FIRMWARE:grblHAL]\r\n", "[SIGNALS:D]\r\n",
    "[NVS STORAGE:*EEPROM]\r\n", "[DRIVER:Simulator]\r\n", "[DRIVER VERSION:260324]\r\n" };

} // namespace

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

    void readsStatusReports_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<int>("state");
        QTest::addColumn<int>("substate"); // -1: none
        QTest::addColumn<double>("z"); // MPos Z, or WPos Z when there is no MPos
        QTest::addColumn<int>("tool"); // -1: not said
        QTest::addColumn<double>("wcoZ"); // NaN: not said
        QTest::addColumn<int>("tlr"); // -1: not said
        QTest::addColumn<bool>("probe");
        const double unsaid = qQNaN();
        const int idle = int(State::Idle);
        QTest::newRow("the peer at rest")
            << QByteArray("<Idle|MPos:0.000,0.000,0.000|Bf:100,1023|FS:0,0|Ov:100,100,100|A:|TLR:0>\r\n")
            << true << idle << -1 << 0.0 << -1 << unsaid << 0 << false;
        QTest::newRow("after a probe") << QByteArray(
            "<Idle|MPos:0.000,0.000,-72.000|Bf:100,1023|FS:0,0|Pn:P|WCO:0.000,0.000,0.000|A:|T:1>")
                                       << true << idle << -1 << -72.0 << 1 << 0.0 << -1 << true;
        QTest::newRow("after G43 H3")
            << QByteArray("<Idle|MPos:0.000,0.000,-72.000|Bf:100,1023|FS:0,0|WCO:0.000,0.000,-12.345|A:|T:3>")
            << true << idle << -1 << -72.0 << 3 << -12.345 << -1 << false;
        QTest::newRow("in alarm") << QByteArray(
            "<Alarm|MPos:0.000,0.000,-62.344|Bf:100,1023|FS:0,0|A:|H:0|T:2>")
                                  << true << int(State::Alarm) << -1 << -62.344 << 2 << unsaid << -1 << false;
        QTest::newRow("alarm with its number")
            << QByteArray("<Alarm:5|MPos:0,0,-1>") << true << int(State::Alarm) << 5 << -1.0 << -1 << unsaid
            << -1 << false;
        QTest::newRow("hold") << QByteArray("<Hold:0|MPos:1,2,3|FS:0,0>") << true << int(State::Hold) << 0
                              << 3.0 << -1 << unsaid << -1 << false;
        QTest::newRow("door") << QByteArray("<Door:1|MPos:1,2,3>") << true << int(State::Door) << 1 << 3.0
                              << -1 << unsaid << -1 << false;
        QTest::newRow("run probing") << QByteArray("<Run:2|MPos:0,0,-5|FS:3000,0>") << true << int(State::Run)
                                     << 2 << -5.0 << -1 << unsaid << -1 << false;
        QTest::newRow("tool change") << QByteArray("<Tool|MPos:0,0,0|A:T>") << true << int(State::Tool) << -1
                                     << 0.0 << -1 << unsaid << -1 << false;
        QTest::newRow("work position, five axes")
            << QByteArray("<Jog|WPos:0,0,4.5,0,0|TLR:1>") << true << int(State::Jog) << -1 << 4.5 << -1
            << unsaid << 1 << false;
        QTest::newRow("limits and the probe") << QByteArray("<Check|MPos:0,0,0|Pn:XZP>") << true
                                              << int(State::Check) << -1 << 0.0 << -1 << unsaid << -1 << true;
        QTest::newRow("an unknown state is not idle")
            << QByteArray("<Busy|MPos:0,0,0>") << true << int(State::Unknown) << -1 << 0.0 << -1 << unsaid
            << -1 << false;
        QTest::newRow("unknown fields skipped")
            << QByteArray("<Sleep|MPos:0,0,0|Zz:what|Q|SP1:0,,|In:-1>") << true << int(State::Sleep) << -1
            << 0.0 << -1 << unsaid << -1 << false;
        QTest::newRow("no position") << QByteArray("<Idle|FS:0,0>") << false << 0 << 0 << 0.0 << 0 << 0.0 << 0
                                     << false;
        QTest::newRow("truncated") << QByteArray("<Idle|MPos:0.000,0.0") << false << 0 << 0 << 0.0 << 0 << 0.0
                                   << 0 << false;
        QTest::newRow("no closing bracket")
            << QByteArray("<Idle|MPos:0,0,0|T:3") << false << 0 << 0 << 0.0 << 0 << 0.0 << 0 << false;
        QTest::newRow("MPos twice") << QByteArray("<Idle|MPos:0,0,0|MPos:0,0,-5>") << false << 0 << 0 << 0.0
                                    << 0 << 0.0 << 0 << false;
        QTest::newRow("T twice") << QByteArray("<Idle|MPos:0,0,0|T:1|T:2>") << false << 0 << 0 << 0.0 << 0
                                 << 0.0 << 0 << false;
        QTest::newRow("NaN in MPos") << QByteArray("<Idle|MPos:0,0,nan>") << false << 0 << 0 << 0.0 << 0
                                     << 0.0 << 0 << false;
        QTest::newRow("inf in WCO") << QByteArray("<Idle|MPos:0,0,0|WCO:0,0,inf>") << false << 0 << 0 << 0.0
                                    << 0 << 0.0 << 0 << false;
        QTest::newRow("a huge number")
            << QByteArray("<Idle|MPos:0,0,1e300>") << false << 0 << 0 << 0.0 << 0 << 0.0 << 0 << false;
        QTest::newRow("a tool beyond any number") << QByteArray("<Idle|MPos:0,0,0|T:4294967295>") << false
                                                  << 0 << 0 << 0.0 << 0 << 0.0 << 0 << false;
        QTest::newRow("a negative tool")
            << QByteArray("<Idle|MPos:0,0,0|T:-1>") << false << 0 << 0 << 0.0 << 0 << 0.0 << 0 << false;
        QTest::newRow("TLR neither 0 nor 1")
            << QByteArray("<Idle|MPos:0,0,0|TLR:2>") << false << 0 << 0 << 0.0 << 0 << 0.0 << 0 << false;
        QTest::newRow("a substate not a number")
            << QByteArray("<Hold:x|MPos:0,0,0>") << false << 0 << 0 << 0.0 << 0 << 0.0 << 0 << false;
        QTest::newRow("a state that is no word")
            << QByteArray("<Id le|MPos:0,0,0>") << false << 0 << 0 << 0.0 << 0 << 0.0 << 0 << false;
        QTest::newRow("empty") << QByteArray("<>") << false << 0 << 0 << 0.0 << 0 << 0.0 << 0 << false;
        QTest::newRow("a million characters")
            << huge("<Idle|MPos:0,0,", ">") << false << 0 << 0 << 0.0 << 0 << 0.0 << 0 << false;
        QTest::newRow("a million fields") << ("<Idle|MPos:0,0,0" + QByteArray(1000000, '|') + ">") << false
                                          << 0 << 0 << 0.0 << 0 << 0.0 << 0 << false;
    }
    void readsStatusReports()
    {
        QFETCH(QByteArray, line);
        QFETCH(bool, valid);
        const auto status = parseStatusReport(line);
        QCOMPARE(status.has_value(), valid);
        if (!valid)
            return;
        QFETCH(double, wcoZ);
        QTEST(int(status->state), "state");
        QTEST(status->substate.value_or(-1), "substate");
        QTEST((status->machinePosition ? status->machinePosition : status->workPosition)->z(), "z");
        QTEST(status->tool.value_or(-1), "tool");
        QCOMPARE(status->workCoordinateOffset.has_value(), !qIsNaN(wcoZ));
        if (status->workCoordinateOffset)
            QCOMPARE(status->workCoordinateOffset->z(), wcoZ);
        QTEST(status->toolLengthReferenceSet ? int(*status->toolLengthReferenceSet) : -1, "tlr");
        QTEST(status->probeTriggered, "probe");
    }

    void classifiesReplies_data()
    {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<int>("kind");
        QTest::addColumn<int>("code"); // -1: none
        QTest::addColumn<bool>("ends");
        QTest::newRow("ok") << QByteArray("ok\r\n") << int(ReplyKind::Ok) << -1 << true;
        QTest::newRow("error:9") << QByteArray("error:9\r\n") << int(ReplyKind::Error) << 9 << true;
        QTest::newRow("error:38") << QByteArray("error:38") << int(ReplyKind::Error) << 38 << true;
        QTest::newRow("error with words")
            << QByteArray("error:Bad number") << int(ReplyKind::Error) << -1 << true;
        QTest::newRow("error beyond any code")
            << QByteArray("error:99999999999999999999") << int(ReplyKind::Error) << -1 << true;
        QTest::newRow("ALARM:5") << QByteArray("ALARM:5\r\n") << int(ReplyKind::Alarm) << 5 << false;
        QTest::newRow("ALARM:4") << QByteArray("ALARM:4") << int(ReplyKind::Alarm) << 4 << false;
        QTest::newRow("ALARM:-1") << QByteArray("ALARM:-1") << int(ReplyKind::Alarm) << -1 << false;
        QTest::newRow("a message") << QByteArray("[MSG:Caution: Unlocked]\r\n") << int(ReplyKind::Message)
                                   << -1 << false;
        QTest::newRow("a status") << QByteArray("<Idle|MPos:0,0,0>") << int(ReplyKind::Status) << -1 << false;
        QTest::newRow("the greeting") << QByteArray("GrblHAL 1.1f ['$' or '$HELP' for help]\r\n")
                                      << int(ReplyKind::Greeting) << -1 << false;
        QTest::newRow("classic Grbl's greeting")
            << QByteArray("Grbl 1.1h ['$' for help]") << int(ReplyKind::Greeting) << -1 << false;
        QTest::newRow("a $# line") << QByteArray("[T:3|0,0,0|0|6,0,0||3]") << int(ReplyKind::Report) << -1
                                   << false;
        QTest::newRow("$G") << QByteArray("[GC:G0 G54 G17 G21 G90 G94 G40 G43 G98 G50 M5 M9 T3 F0 S0.]")
                            << int(ReplyKind::Report) << -1 << false;
        QTest::newRow("a setting") << QByteArray("$130=299.000") << int(ReplyKind::Other) << -1 << false;
        QTest::newRow("okay is not ok") << QByteArray("okay") << int(ReplyKind::Other) << -1 << false;
        QTest::newRow("empty") << QByteArray("") << int(ReplyKind::Other) << -1 << false;
        QTest::newRow("a million characters after error:")
            << huge("error:", "") << int(ReplyKind::Other) << -1 << false;
    }
    void classifiesReplies()
    {
        QFETCH(QByteArray, line);
        const Reply reply = classifyReply(line);
        QTEST(int(reply.kind), "kind");
        QTEST(reply.code.value_or(-1), "code");
        QTEST(endsCommand(line), "ends");
    }

    void readsMessages()
    {
        QCOMPARE(parseMessage("[MSG:Caution: Unlocked]\r\n"), std::optional<QString>(u"Caution: Unlocked"_s));
        QCOMPARE(parseMessage("[MSG:]"), std::optional<QString>(QString()));
        QVERIFY(!parseMessage("[MSG:Caution"));
        QVERIFY(!parseMessage("[GC:G0]"));
        QVERIFY(!parseMessage(huge("[MSG:", "]")));
    }

    // The alarms and errors a tool manager meets are told in words with what to do; others still say their
    // number.
    void tellsAlarmsAndErrorsInWords_data()
    {
        QTest::addColumn<bool>("alarm");
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("words");
        QTest::newRow("ALARM:4") << true << 4 << u"Probe already touching"_s;
        QTest::newRow("ALARM:5") << true << 5 << u"Probe found nothing"_s;
        QTest::newRow("ALARM:1") << true << 1 << u"limit switch"_s;
        QTest::newRow("ALARM:2") << true << 2 << u"travel"_s;
        QTest::newRow("ALARM:3") << true << 3 << u"reset"_s;
        QTest::newRow("ALARM:9") << true << 9 << u"Homing failed"_s;
        QTest::newRow("ALARM:10") << true << 10 << u"emergency stop"_s;
        QTest::newRow("ALARM:99") << true << 99 << u"ALARM:99"_s;
        QTest::newRow("error:9") << false << 9 << u"G-code locked out during alarm or jog state"_s;
        QTest::newRow("error:20") << false << 20 << u"does not support"_s;
        QTest::newRow("error:38") << false << 38 << u"No such tool"_s;
        QTest::newRow("error:79") << false << 79 << u"critical event"_s;
        QTest::newRow("error:250") << false << 250 << u"error:250"_s;
    }
    void tellsAlarmsAndErrorsInWords()
    {
        QFETCH(bool, alarm);
        QFETCH(int, code);
        QFETCH(QString, words);
        const QString meaning = alarm ? alarmMeaning(code) : errorMeaning(code);
        QVERIFY2(meaning.contains(words), qPrintable(meaning));
        if (alarm && code <= 5)
            QVERIFY2(meaning.contains(u"($X)"_s), qPrintable(meaning)); // what to do
    }
};

QTEST_GUILESS_MAIN(TestGrblHalReplies)
#include "tst_grblhalreplies.moc"
