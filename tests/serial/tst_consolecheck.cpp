// SPDX-License-Identifier: GPL-3.0-or-later
// The console's checks: what the panels refuse, it refuses; what moves the machine, it asks about first. The
// Carvera's own rules (CarveraConsole, what MachineSession gives) before every controller's; a controller
// with no rules of its own (grblHAL) gets only those, in words true of it.
#include <QTest>

#include "serial/carvera/carveraconsole.h"
#include "serial/machine/consolecheck.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Verdict = ConsoleCheck::Verdict;

Q_DECLARE_METATYPE(Toffee::ConsoleCheck::Verdict)

class TestConsoleCheck : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void judgesEachLine_data()
    {
        QTest::addColumn<QString>("line");
        QTest::addColumn<bool>("halted");
        QTest::addColumn<Verdict>("verdict");
        QTest::addColumn<QString>("reason");
        // Refused, as the panels refuse them (each once reached the machine and halted it).
        QTest::newRow("tolerance too small") << u"M491.1 H0.01"_s << false << Verdict::Refuse << u"0.02"_s;
        QTest::newRow("offset too large") << u"M493.3 Z1000"_s << false << Verdict::Refuse << u"999.999"_s;
        QTest::newRow("M493.3 alone") << u"m493.3"_s << false << Verdict::Refuse << u"needs Z"_s;
        QTest::newRow("M493.2 with no tool") << u"M493.2"_s << false << Verdict::Refuse << u"halts"_s;
        QTest::newRow("M6 with no tool") << u"M6"_s << false << Verdict::Refuse << u"M6 T2"_s;
        // Refused as it is read: no controller takes a word with more than eight digits before the point.
        QTest::newRow("a huge tool") << u"M6 T99999999999999"_s << false << Verdict::Refuse
                                     << u"T99999999999999 is too large"_s;
        QTest::newRow("a tool beyond the table")
            << u"M6 T1000000"_s << false << Verdict::Refuse << u"not a tool number"_s;
        QTest::newRow("a fractional tool")
            << u"M6 T2.5"_s << false << Verdict::Refuse << u"not a tool number"_s;
        QTest::newRow("a tool that is none")
            << u"M6 T1000000"_s << false << Verdict::Refuse << u"not a tool number"_s;
        QTest::newRow("inches") << u"G20"_s << false << Verdict::Refuse << u"millimetres only"_s;
        QTest::newRow("garbage") << u"M49#"_s << false << Verdict::Refuse << u"not a G-code line"_s;
        // Halted: only Unlock, and the few M codes the firmware still takes.
        QTest::newRow("probe while halted") << u"M491"_s << true << Verdict::Refuse << u"Unlock"_s;
        QTest::newRow("home while halted") << u"$H"_s << true << Verdict::Refuse << u"Unlock"_s;
        QTest::newRow("unlock while halted") << u"$X"_s << true << Verdict::Send << QString();
        QTest::newRow("report while halted") << u"M493.4"_s << true << Verdict::Refuse << u"Unlock"_s;
        QTest::newRow("reset while halted") << u"M999"_s << true << Verdict::Send << QString();
        QTest::newRow("spindle off while halted") << u"M5"_s << true << Verdict::Send << QString();
        QTest::newRow("status while halted") << u"?"_s << true << Verdict::Refuse << u"strip"_s;
        // Asked first: everything that moves the machine or changes the offset it cuts with.
        QTest::newRow("tool change") << u"M6 T2"_s << false << Verdict::Confirm << u"the machine moves"_s;
        QTest::newRow("probe") << u"M491"_s << false << Verdict::Confirm << u"tool setter"_s;
        QTest::newRow("break test") << u"M491.1 H0.05"_s << false << Verdict::Confirm << u"break test"_s;
        QTest::newRow("rapid") << u"G0 Z10"_s << false << Verdict::Confirm << u"moves the machine"_s;
        QTest::newRow("modal move") << u"X5 Y5"_s << false << Verdict::Confirm << u"moves the machine"_s;
        // Offsets written, nothing moved: asked about, in true words (G10 was said to move the machine).
        QTest::newRow("tool table entry")
            << u"G10 L1 P2 Z10"_s << false << Verdict::Confirm << u"writes an offset into the controller"_s;
        QTest::newRow("work offset") << u"G10 L2 P1 Z-5"_s << false << Verdict::Confirm << u"nothing moves"_s;
        QTest::newRow("G92") << u"G92 Z0"_s << false << Verdict::Confirm << u"shifts the work coordinates"_s;
        QTest::newRow("dynamic TLO") << u"G43.1 Z12.5"_s << false << Verdict::Confirm
                                     << u"sets the tool length offset in force"_s;
        QTest::newRow("comment then move")
            << u"(safe) G53 G0 Z-1"_s << false << Verdict::Confirm << u"moves the machine"_s;
        QTest::newRow("spindle on") << u"M3 S10000"_s << false << Verdict::Confirm << u"spindle"_s;
        QTest::newRow("home") << u"$H"_s << false << Verdict::Confirm << u"homes"_s;
        QTest::newRow("jog") << u"$J=G91 X1 F100"_s << false << Verdict::Confirm << u"jogs"_s;
        QTest::newRow("M493.3 H: 115 mm off after a Z")
            << u"M493.3 H12.5"_s << false << Verdict::Refuse << u"Gauge height above Z0"_s;
        QTest::newRow("set TLO") << u"M493.3 Z-30.488"_s << false << Verdict::Confirm << u"set by hand"_s;
        QTest::newRow("select tool") << u"M493.2 T3"_s << false << Verdict::Confirm
                                     << u"keeps the TLO in force now (another tool's, or none)"_s;
        // Sent as typed: what only reads or changes nothing that cuts.
        QTest::newRow("report") << u"M493.4"_s << false << Verdict::Send << QString();
        QTest::newRow("absolute") << u"G90"_s << false << Verdict::Send << QString();
        QTest::newRow("settings") << u"$$"_s << false << Verdict::Send << QString();
        QTest::newRow("comment only") << u"; nothing"_s << false << Verdict::Send << QString();
    }

    void judgesEachLine()
    {
        QFETCH(QString, line);
        QFETCH(bool, halted);
        QFETCH(Verdict, verdict);
        QFETCH(QString, reason);
        const ConsoleCheck check = ConsoleCheck::check(line, halted, &CarveraConsole::rules);
        QCOMPARE(check.verdict, verdict);
        QVERIFY2(check.reason.contains(reason), qPrintable(check.reason));
    }

    void onlyM4933IsRecordedAsAnOffset()
    {
        const ConsoleRules carvera = &CarveraConsole::rules;
        QVERIFY(ConsoleCheck::check(u"M493.3 Z12.5"_s, false, carvera).setsTlo);
        QVERIFY(!ConsoleCheck::check(u"M493.4"_s, false, carvera).setsTlo);
        QVERIFY(!ConsoleCheck::check(u"M6 T2"_s, false, carvera).setsTlo);
        // Nor on a controller whose M493.3 is no command at all: nothing is recorded as its offset.
        QVERIFY(!ConsoleCheck::check(u"M493.3 Z12.5"_s, false, nullptr).setsTlo);
    }

    // A controller with no rules of its own: none of the Carvera's words, its inches or its halted M-codes.
    void judgesEachLineWithoutTheCarverasRules_data()
    {
        QTest::addColumn<QString>("line");
        QTest::addColumn<bool>("halted");
        QTest::addColumn<Verdict>("verdict");
        QTest::addColumn<QString>("reason");
        QTest::newRow("inches, in words not the Carvera's")
            << u"G20"_s << false << Verdict::Refuse << u"Toffee works in millimetres"_s;
        QTest::newRow("M6 asked about, not said to probe")
            << u"M6 T2"_s << false << Verdict::Confirm << u"M6 T2 changes the tool."_s;
        QTest::newRow("M6 with no tool") << u"M6"_s << false << Verdict::Refuse << u"M6 T2"_s;
        QTest::newRow("a tool beyond the table")
            << u"M6 T1000000"_s << false << Verdict::Refuse << u"not a tool number"_s;
        QTest::newRow("tool table entry")
            << u"G10 L1 P2 Z10"_s << false << Verdict::Confirm << u"writes an offset into the controller"_s;
        QTest::newRow("rapid") << u"G0 Z10"_s << false << Verdict::Confirm << u"moves the machine"_s;
        // Halted: no G-code or M-code at all (grblHAL's alarm locks them out), only Unlock.
        QTest::newRow("spindle off while halted") << u"M5"_s << true << Verdict::Refuse << u"Unlock ($X)"_s;
        QTest::newRow("unlock while halted") << u"$X"_s << true << Verdict::Send << QString();
        // The Carvera's M-codes are not this controller's: sent for it to answer, asked about first when an
        // axis word rides along (as any line with one is), never recorded as an offset.
        QTest::newRow("the Carvera's M493.3")
            << u"M493.3 Z-30.488"_s << false << Verdict::Confirm << u"moves the machine"_s;
        QTest::newRow("the Carvera's M491.1") << u"M491.1 H0.01"_s << false << Verdict::Send << QString();
    }

    void judgesEachLineWithoutTheCarverasRules()
    {
        QFETCH(QString, line);
        QFETCH(bool, halted);
        QFETCH(Verdict, verdict);
        QFETCH(QString, reason);
        const ConsoleCheck check = ConsoleCheck::check(line, halted, nullptr);
        QCOMPARE(check.verdict, verdict);
        QVERIFY2(check.reason.contains(reason), qPrintable(check.reason));
        QVERIFY(!check.measures);
    }
};

QTEST_GUILESS_MAIN(TestConsoleCheck)
#include "tst_consolecheck.moc"
