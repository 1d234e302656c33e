// SPDX-License-Identifier: GPL-3.0-or-later
// grblHAL's status reports, its replies classified, its messages, and its alarms and errors in words, read by
// pure functions (serial/grblhal/grblhalreplies.h), each with what it must refuse.
#include <QTest>

#include "tests/serial/grblhallines.h"

using namespace Toffee;
using namespace Toffee::GrblHal;
using namespace Qt::StringLiterals;
using namespace Toffee::Test;

class TestGrblHalStatus : public QObject
{
    Q_OBJECT

private Q_SLOTS:
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

QTEST_GUILESS_MAIN(TestGrblHalStatus)
#include "tst_grblhalstatus.moc"
