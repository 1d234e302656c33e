// SPDX-License-Identifier: GPL-3.0-or-later
// linuxcncrsh's answers read by pure functions (docs/LINUXCNC.md), the lines as LinuxCNC 2.9 wrote them on
// the peer: set replies ending "\n\r", a GET NAK, a (DEBUG,…) line of Toffee's among others, an INI's tool
// table.
#include <QTest>

#include "serial/linuxcnc/linuxcncreplies.h"

using namespace Toffee;
using namespace Toffee::LinuxCnc;
using namespace Qt::StringLiterals;

class TestLinuxCncReplies : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void linesAreClassified()
    {
        QCOMPARE(classify("SET MDI ACK\n\r"), ReplyKind::Ok);
        QCOMPARE(classify("HELLO ACK EMCNETSVR 1.1"), ReplyKind::Ok);
        QCOMPARE(classify("SET MDI NAK"), ReplyKind::Error);
        QCOMPARE(classify("GET VERSION NAK"), ReplyKind::Error);
        QCOMPARE(classify("SET NAK"), ReplyKind::Error);
        QCOMPARE(classify("HELLO NAK"), ReplyKind::Error);
        // A get's answer, and an echo of a line sent, are neither.
        QCOMPARE(classify("TOOL 2"), ReplyKind::Other);
        QCOMPARE(classify("set mdi G0 X1 (ACK"), ReplyKind::Other);
        QCOMPARE(classify("OPERATOR_DISPLAY TOFFEE-PRB-3 ACK"), ReplyKind::Other);
        QVERIFY(isHelloAck("HELLO ACK MILL 1.1\r"));
        QVERIFY(!isHelloAck("HELLO NAK"));
    }

    void aGetsValueFollowsItsKeyword()
    {
        QCOMPARE(valueOf("TOOL 2\r", "TOOL"), QByteArray("2"));
        QCOMPARE(valueOf("TOOL_OFFSET 5", "TOOL"), std::nullopt);
        QCOMPARE(valueOf("ESTOP OFF", "ESTOP"), QByteArray("OFF"));
        QCOMPARE(homedJoints("YES YES YES NO NO NO"), 3);
        QCOMPARE(homedJoints("YES NO YES NO NO NO"), 2);
        const auto xyz = position("10.000000 -5.500000 -75.000000 0.000000 0.000000 0.000000");
        QVERIFY(xyz);
        QCOMPARE((*xyz)[2], -75.0);
        QVERIFY(!position("10 nan"));
        QVERIFY(inInches("G80 G17 G40 G20 G90 G94 G54 G49"));
        QVERIFY(!inInches("G80 G17 G40 G21 G90 G94 G54 G49 G99 G64 G97 G91.1 G8 G92.2 F0 S0"));
    }

    void toffeesDebugLineIsItsOwn()
    {
        const auto f = displayFields(
            "TOFFEE-PRB-7 p=-75.000000 a=-75.000000 z=-42.000000 ok=1.000000", "TOFFEE-PRB-7");
        QVERIFY(f);
        QCOMPARE(f->at("p"), -75.0);
        QCOMPARE(f->at("z"), -42.0);
        // Another question's, another program's, and a parameter LinuxCNC does not know.
        QVERIFY(!displayFields("TOFFEE-PRB-6 p=-75.000000", "TOFFEE-PRB-7"));
        QVERIFY(!displayFields("Probe tripped", "TOFFEE-PRB-7"));
        QVERIFY(!displayFields("TOFFEE-PRB-7 p=######", "TOFFEE-PRB-7"));
        QVERIFY(!displayFields("TOFFEE-PRB-7 p", "TOFFEE-PRB-7"));
    }

    void theIniNamesTheToolTable()
    {
        const QByteArray ini = "[EMC]\nMACHINE = mill\n# TOOL_TABLE = wrong.tbl\n[EMCIO]\n"
                               "# a comment\nTOOL_TABLE = tool.tbl\n[TRAJ]\nTOOL_TABLE = not-this\n";
        QCOMPARE(
            toolTableOfIni(ini, u"/home/cnc/configs/mill/mill.ini"_s), u"/home/cnc/configs/mill/tool.tbl"_s);
        QCOMPARE(toolTableOfIni("[EMCIO]\nTOOL_TABLE=/var/lib/t.tbl\n", u"/x/y.ini"_s), u"/var/lib/t.tbl"_s);
        QCOMPARE(toolTableOfIni("[EMCIO]\nRANDOM_TOOLCHANGER = 0\n", u"/x/y.ini"_s), QString());
        QCOMPARE(toolTableOfIni("[TRAJ]\nTOOL_TABLE = t.tbl\n", u"/x/y.ini"_s), QString());
    }
};

QTEST_GUILESS_MAIN(TestLinuxCncReplies)
#include "tst_linuxcncreplies.moc"
