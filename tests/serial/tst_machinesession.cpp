// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <limits>

#include <QElapsedTimer>
#include <QTest>

#include "model/limits.h"
#include "tests/support/sessionharness.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Test::SessionHarness;
using Outcome = SessionResult::Outcome;

class TestMachineSession : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void connectsFlushesAndReadsTheOffsets()
    {
        SessionHarness h;
        const SessionResult r = h.connect();
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(h.sent.mid(0, 4), (QList<QByteArray> { "", ";", "version", "M493.4" }));
        QCOMPARE(h.session.firmware().kind, FirmwareInfo::Kind::Community);
        QCOMPARE(h.session.firmware().version, u"2.1.0c-emulator"_s);
        QVERIFY(r.status.has_value());
        QCOMPARE(r.tool.value_or(-2), 1);
        QVERIFY(r.tlo.has_value());
    }

    // The TLO in force is the machine's own (its status report), against the reference it is calibrated
    // with (-115.340 on a C1): probing never makes a tool the reference.
    void measuresAndSetsAgainstTheMachinesReference()
    {
        SessionHarness h;
        QVERIFY(h.connect().ok());
        SessionResult r = h.run([&](auto done) { h.session.probe(done); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(*r.tlo->referenceMz, -115.34);
        QCOMPARE(r.tlo->tlo(), 43.04);
        QVERIFY(h.run([&](auto done) { h.session.selectTool(2, done); }).ok());
        r = h.run([&](auto done) { h.session.probe(done); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(r.tool.value_or(-1), 2);
        QCOMPARE(*r.tlo->currentMz, -105.688);
        QCOMPARE(QString::number(r.tlo->tlo(), 'f', 3), u"9.652"_s);
        // The result carries what to record: T2's TLO, probed, against the reference at -115.340.
        QVERIFY(r.recording);
        QCOMPARE(r.recording->tool, 2);
        QCOMPARE(*r.recording->tlo, 9.652);
        QCOMPARE(r.recording->source, TloSource::Probe);
        QCOMPARE(*r.recording->referenceMz, -115.34);
        QCOMPARE(*r.recording->currentMz, -105.688);
        r = h.run([&](auto done) { h.session.setTlo(r.tlo->tlo() + 2.9, done); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(QString::number(r.tlo->tlo(), 'f', 3), u"12.552"_s);
        QCOMPARE(h.sent.last(), QByteArray("M493.4"));
        QVERIFY(h.sent.contains("M493.3 Z12.552"));
        QVERIFY(r.recording);
        QCOMPARE(r.recording->source, TloSource::Manual); // set by hand
        QCOMPARE(*r.recording->tlo, 12.552);
        // M493.4 prints the TLO as the "current tool offset" now: no MCS Z of the tool is made up from it.
        QVERIFY(!r.recording->currentMz);
        // Recorded the same way the window and the CLI record it.
        ToolTable table;
        QVERIFY(table.record(*r.recording).ok());
        QCOMPARE(table.find(2)->tloSource, TloSource::Manual);
        QCOMPARE(*table.find(2)->referenceMz, -115.34);
    }

    // Set from a gauge: Toffee works the TLO out from the status report and sends M493.3 Z (the firmware's
    // M493.3 H is 115 mm off after an M493.3 Z).
    void setsTheTloFromAGaugeWithoutTheFirmwaresH()
    {
        SessionHarness h;
        QVERIFY(h.connect().ok());
        QVERIFY(h.run([&](auto done) { h.session.setTlo(20.0, done); }).ok());
        const SessionResult r = h.run([&](auto done) { h.session.setTloAboveZ0(3.0, done); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        // Work Z is MPos Z (-2) less the work offset (0) less the TLO (20): -22. The tip at 3 mm: TLO -5.
        QCOMPARE(r.tlo->tlo(), -5.0);
        QVERIFY(h.sent.contains("M493.3 Z-5"));
        QVERIFY(!h.sent.contains("M493.3 H3"));
        QCOMPARE(h.emulator.tlo(), -5.0);
    }

    // An empty spindle (T-1): the firmware would keep the TLO for the next tool selected. Refused, nothing
    // sent; the emulator's TLO in force stays.
    void anEmptySpindleTakesNoTlo()
    {
        SessionHarness h;
        h.emulator.setToolInSpindle(Limits::kEmptySpindle);
        QVERIFY(h.connect().ok());
        const double before = h.emulator.tlo();
        const qsizetype sent = h.sent.size();
        for (const bool aboveZ0 : { false, true }) {
            const SessionResult r = h.run([&](MachineSession::Done done) {
                return aboveZ0 ? h.session.setTloAboveZ0(3.0, done) : h.session.setTlo(12.0, done);
            });
            QCOMPARE(r.outcome, Outcome::Refused);
            QVERIFY2(r.message.contains(u"spindle is empty (T-1)"_s), qPrintable(r.message));
            QVERIFY(!r.recording);
        }
        QCOMPARE(h.sent.size(), sent);
        QCOMPARE(h.emulator.tlo(), before);
    }

    void refusesBadInputWithoutSendingIt_data()
    {
        QTest::addColumn<int>("operation");
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("message");
        const double nan = std::numeric_limits<double>::quiet_NaN();
        QTest::newRow("tolerance below 0.02") << 0 << 0.01 << u"too small"_s;
        QTest::newRow("tolerance 0.0199") << 0 << 0.0199 << u"too small"_s;
        QTest::newRow("tolerance negative") << 0 << -0.1 << u"too small"_s;
        QTest::newRow("tolerance NaN") << 0 << nan << u"not a number"_s;
        QTest::newRow("TLO NaN") << 1 << nan << u"from -999.999 to 999.999"_s;
        QTest::newRow("TLO too large") << 1 << 5000.0 << u"from -999.999 to 999.999"_s;
        QTest::newRow("height infinite")
            << 2 << std::numeric_limits<double>::infinity() << u"height above Z0"_s;
        QTest::newRow("tool -2") << 3 << -2.0 << u"not a tool number"_s;
        QTest::newRow("tool too large") << 4 << 1e7 << u"not a tool number"_s;
        QTest::newRow("restore with NaN") << 5 << nan << u"tool length offset"_s;
    }
    void refusesBadInputWithoutSendingIt()
    {
        QFETCH(int, operation);
        QFETCH(double, value);
        QFETCH(QString, message);
        SessionHarness h;
        QVERIFY(h.connect().ok());
        const qsizetype before = h.sent.size();
        const SessionResult r = h.run([&](MachineSession::Done done) {
            switch (operation) {
            case 0:
                return h.session.breakTest(value, done);
            case 1:
                return h.session.setTlo(value, done);
            case 2:
                return h.session.setTloAboveZ0(value, done);
            case 3:
                return h.session.selectTool(int(value), done);
            case 4:
                return h.session.changeTool(int(value), done);
            default:
                return h.session.restoreTlo(2, value, done);
            }
        });
        QCOMPARE(r.outcome, Outcome::Refused);
        QVERIFY2(r.message.contains(message), qPrintable(r.message));
        QCOMPARE(h.sent.size(), before); // nothing left the computer
    }

    void theMinimumToleranceIsSent()
    {
        SessionHarness h;
        QVERIFY(h.connect().ok());
        QVERIFY(h.run([&](auto done) { h.session.probe(done); }).ok());
        const SessionResult r = h.run([&](auto done) { h.session.breakTest(0.02, done); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(h.sent.last(), QByteArray("M491.1 H0.02"));
        QCOMPARE(r.breakTest->newTlo, r.breakTest->oldTlo);
    }

    void findsABrokenTool()
    {
        SessionHarness h;
        QVERIFY(h.connect().ok());
        QVERIFY(h.run([&](auto done) { h.session.probe(done); }).ok());
        h.emulator.breakTool(1, 0.3);
        const SessionResult r = h.run([&](auto done) { h.session.breakTest(0.1, done); });
        QCOMPARE(r.outcome, Outcome::ToolBroken);
        QVERIFY(r.breakTest.has_value());
        QCOMPARE(QString::number(r.breakTest->newTlo - r.breakTest->oldTlo, 'f', 3), u"-0.300"_s);
        QVERIFY(r.recording && r.recording->breakTestFailed == true && !r.recording->tlo);
        QCOMPARE(r.recording->tool, 1);
        QVERIFY2(
            r.message.contains(u"may be broken"_s) && r.message.contains(u"Unlock"_s), qPrintable(r.message));
        QVERIFY(h.emulator.isHalted());
    }

    // The firmware compares with the TLO in force and takes 0.000 for none (it would measure without
    // comparing): a TLO of 0.000, the reference tool's, goes in as 0.001 and is compared by the firmware,
    // which halts a broken tool as it does every other. It was once refused, and Check Rack passed it
    // untested.
    void aBreakTestAgainstATloOfZeroIsComparedAsOneMicrometre()
    {
        SessionHarness h;
        QVERIFY(h.connect().ok());
        // The reference tool itself (its TLO 0.000 in force): within the tolerance, it passes.
        h.emulator.setToolLength(1, h.emulator.toolLength(1) - 43.04);
        const SessionResult intact = h.run([&](auto done) { h.session.breakTest(0.1, done, 0.0); });
        QVERIFY2(intact.ok(), qPrintable(intact.message));
        QCOMPARE(intact.breakTest->oldTlo, 0.0);
        QCOMPARE(intact.breakTest->newTlo, 0.0);
        QVERIFY(intact.recording && intact.recording->breakTestFailed == false);
        QVERIFY(h.sent.contains("M493.3 Z0.001"));
        QVERIFY(h.sent.contains("M491.1 H0.1"));
        // 0.5 mm shorter: broken, the firmware halts, and Unlock sets the stored 0.000 back.
        h.emulator.breakTool(1, 0.5);
        const SessionResult broken = h.run([&](auto done) { h.session.breakTest(0.1, done, 0.0); });
        QCOMPARE(broken.outcome, Outcome::ToolBroken);
        QCOMPARE(broken.breakTest->oldTlo, 0.0);
        QCOMPARE(broken.breakTest->newTlo, -0.5);
        QVERIFY2(broken.message.contains(u"against 0.000 mm before"_s), qPrintable(broken.message));
        QVERIFY(broken.recording && broken.recording->breakTestFailed == true);
        QVERIFY(h.emulator.isHalted());
        QCOMPARE(h.session.tloToRestore(), std::optional(0.0));
    }

    // After M493.2 the firmware still has the previous tool's TLO in force, and M491.1 would compare with
    // it: with the table's TLO the session sets that first.
    void aBreakTestComparesWithTheStoredTloNotThePreviousTools()
    {
        SessionHarness h;
        QVERIFY(h.connect().ok());
        QVERIFY(h.run([&](auto done) { h.session.probe(done); }).ok()); // T1: 43.040
        QVERIFY(h.run([&](auto done) { h.session.selectTool(2, done); }).ok());
        const SessionResult r = h.run([&](auto done) { h.session.breakTest(0.1, done, 9.652); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QVERIFY(h.sent.contains("M493.3 Z9.652"));
        QCOMPARE(r.breakTest->oldTlo, 9.652);
        QCOMPARE(r.breakTest->newTlo, 9.652);
    }

    // The firmware takes T0 and T9 on for its wireless probe in M491.1, and halts after measuring.
    void aBreakTestOfToolNineOrAboveIsNotSent()
    {
        SessionHarness h;
        QVERIFY(h.connect().ok());
        QVERIFY(h.run([&](auto done) { h.session.selectTool(9, done); }).ok());
        const qsizetype before = h.sent.size();
        const SessionResult r = h.run([&](auto done) { h.session.breakTest(0.1, done, 12.5); });
        QCOMPARE(r.outcome, Outcome::Refused);
        QVERIFY2(r.message.contains(u"wireless probe"_s), qPrintable(r.message));
        QCOMPARE(h.sent.size(), before);
    }

    // A failed break test halts with the new, broken length in force; Unlock sets the stored TLO back first.
    void unlockingAfterABrokenToolPutsTheStoredTloBack()
    {
        SessionHarness h;
        QVERIFY(h.connect().ok());
        QVERIFY(h.run([&](auto done) { h.session.probe(done); }).ok());
        h.emulator.breakTool(1, 0.3);
        SessionResult r = h.run([&](auto done) { h.session.breakTest(0.1, done); });
        QCOMPARE(r.outcome, Outcome::ToolBroken);
        QCOMPARE(h.emulator.tlo(), 42.74); // the broken length, in force
        QCOMPARE(h.session.tloToRestore(), 43.04);
        QVERIFY2(r.message.contains(u"42.740 mm, in force"_s), qPrintable(r.message));
        r = h.run([&](auto done) { h.session.unlock(done); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(h.emulator.tlo(), 43.04);
        QCOMPARE(h.sent.mid(h.sent.size() - 3), (QList<QByteArray> { "$X", "M493.3 Z43.04", "M493.4" }));
        QVERIFY2(r.message.contains(u"stored TLO, 43.040 mm, is in force again"_s), qPrintable(r.message));
        QVERIFY(!h.session.tloToRestore());
    }

    // $X on a machine that is not halted gets no answer at all from the firmware: it is not sent.
    void unlockingAMachineThatIsNotHaltedSendsNothing()
    {
        SessionHarness h;
        QVERIFY(h.connect().ok());
        const qsizetype before = h.sent.size();
        const SessionResult r = h.run([&](auto done) { h.session.unlock(done); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(h.sent.size(), before);
        QVERIFY(h.link.isOpen());
    }

    void reachesAHaltedMachineToUnlockIt()
    {
        SessionHarness h;
        h.emulator.halt(3);
        SessionResult r = h.connect();
        QVERIFY2(r.ok(), qPrintable(r.message));
        QVERIFY(r.status->isAlarm());
        QCOMPARE(r.status->haltReason.value_or(0), 3);
        QVERIFY(!h.sent.contains("M493.4")); // it would only get "Alarm lock"
        r = h.run([&](auto done) { h.session.probe(done); });
        QCOMPARE(r.outcome, Outcome::MachineError);
        QVERIFY(r.message.contains(u"Alarm lock"_s));
        r = h.run([&](auto done) { h.session.unlock(done); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QVERIFY(!r.status->isAlarm());
    }

    void anUnhomedMachineSaysSoInsteadOfAnUnreadableProbe()
    {
        // "Machine has not been homed" has no ALARM:/ERROR: prefix but halts the machine (reason 2).
        SessionHarness h;
        QVERIFY(h.connect().ok());
        h.emulator.setHomed(false);
        const SessionResult r = h.run([&](auto done) { h.session.probe(done); });
        QCOMPARE(r.outcome, Outcome::MachineError);
        QVERIFY2(r.message.contains(u"not been homed"_s), qPrintable(r.message));
        QVERIFY(!r.recording);
        QVERIFY(h.emulator.isHalted());
    }

    void restoresAKnownTloWithoutProbing()
    {
        SessionHarness h;
        QVERIFY(h.connect().ok());
        QVERIFY(h.run([&](auto done) { h.session.probe(done); }).ok());
        const SessionResult r = h.run([&](auto done) { h.session.restoreTlo(5, -12.25, done); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(r.tool.value_or(-1), 5);
        QCOMPARE(r.tlo->tlo(), -12.25);
        // The table's own value: the history gets a restore, the table nothing new.
        QVERIFY(r.recording);
        QCOMPARE(r.recording->kind, RecordingKind::Restore);
        QCOMPARE(r.recording->tlo, -12.25);
        ToolTable table
            = ToolTable::fromTools({ Tool { 5, 5, {}, 40, 0, 3, 0, -12.25, {}, {}, {} } }, Units::Millimetre)
                  .takeValue();
        const ToolTable before = table;
        QVERIFY(table.record(*r.recording));
        QCOMPARE(table, before);
        QVERIFY(!h.sent.contains("M491") || h.sent.count("M491") == 1);
        QCOMPARE(h.emulator.tool(), 5);
    }

    void changesToolsAndMeasuresThem()
    {
        SessionHarness h;
        QVERIFY(h.connect().ok());
        QVERIFY(h.run([&](auto done) { h.session.probe(done); }).ok());
        const SessionResult r = h.run([&](auto done) { h.session.changeTool(2, done); });
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(r.tool.value_or(-1), 2);
        QCOMPARE(QString::number(r.tlo->tlo(), 'f', 3), u"9.652"_s);
    }

    void abortStopsAProbe()
    {
        SessionHarness h;
        h.emulator.setTiming({ 3000, 0 });
        QVERIFY(h.connect().ok());
        std::optional<SessionResult> result;
        h.session.probe([&](const SessionResult &r) { result = r; });
        QTest::qWait(50);
        h.session.abort();
        QTRY_VERIFY_WITH_TIMEOUT(result.has_value(), 3000);
        QCOMPARE(result->outcome, Outcome::MachineError);
        QVERIFY2(result->message.contains(u"Abort during cycle"_s), qPrintable(result->message));
        QVERIFY(h.emulator.isHalted());
    }

    // With a time limit (toffee-cli --timeout), connecting to a machine that stays busy ends at the limit,
    // not after the 130 s a probe may take.
    void connectingToABusyMachineObeysTheTimeLimit()
    {
        SessionHarness h;
        h.emulator.setTiming({ 0, 600000 });
        h.emulator.receiveLine("G0 X1"); // running for ten minutes
        h.link.setTimeoutOverride(500);
        QElapsedTimer clock;
        clock.start();
        const SessionResult r = h.connect();
        QCOMPARE(r.outcome, Outcome::LinkFailure);
        QVERIFY2(r.message.contains(u"stayed busy (Run) for the 0.5 s allowed"_s), qPrintable(r.message));
        QVERIFY2(
            clock.elapsed() >= 500 && clock.elapsed() < 3000, qPrintable(QString::number(clock.elapsed())));
    }

    void connectingToASilentMachineObeysTheTimeLimit()
    {
        SessionHarness h;
        h.emulator.injectFault(CarveraEmulator::Fault::NoAnswer);
        h.link.setTimeoutOverride(400);
        QElapsedTimer clock;
        clock.start();
        const SessionResult r = h.connect();
        QCOMPARE(r.outcome, Outcome::LinkFailure);
        QVERIFY2(r.message.contains(u"within the 0.4 s allowed"_s), qPrintable(r.message));
        QVERIFY2(
            clock.elapsed() >= 400 && clock.elapsed() < 3000, qPrintable(QString::number(clock.elapsed())));
        QVERIFY(!h.link.isOpen()); // a late answer can no longer be taken for another command's
    }
};

QTEST_GUILESS_MAIN(TestMachineSession)
#include "tst_machinesession.moc"
