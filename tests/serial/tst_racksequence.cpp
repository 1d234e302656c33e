// SPDX-License-Identifier: GPL-3.0-or-later
// Measure Rack and Check Rack on the emulator: every tool in turn, a fault injected at every step of it, and
// what is recorded afterwards is only what was measured. The stock firmware's limits, and a change that
// takes a stored TLO.
#include <QSignalSpy>
#include <QTest>

#include "model/numberformat.h"
#include "model/tooltable.h"
#include "serial/carvera/rack/racksequence.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/machine/machinelink.h"
#include "serial/machineconnection.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Fault = CarveraEmulator::Fault;
using Outcome = SessionResult::Outcome;
using State = RackStep::State;
using Mode = RackSequence::Mode;

namespace {

const QList<int> kRack { 1, 2, 3, 4, 5, 6 };

// A connection to a built-in emulator, every line it sends, and what a sequence recorded, applied to a
// table as the window and the CLI apply it.
struct Station
{
    MachineConnection connection;
    QList<QByteArray> sent;
    QList<Recording> recordings;
    ToolTable table;

    explicit Station(bool stock = false)
    {
        ConnectionTarget target;
        target.emulatorStock = stock;
        QObject::connect(&connection, &MachineConnection::consoleLine, &connection,
            [this](const QByteArray &line, bool outgoing) {
                if (outgoing)
                    sent.append(line);
            });
        connection.connectTo(target);
        (void)QTest::qWaitFor(
            [this] { return connection.state() != MachineConnection::State::Connecting; }, 10000);
    }
    CarveraEmulator &machine() { return *connection.emulator(); }

    // Runs a sequence to its end; false when it hung.
    bool run(RackSequence &sequence)
    {
        QObject::connect(&sequence, &RackSequence::recorded, &sequence, [this](const SessionResult &r) {
            recordings.append(*r.recording);
            QVERIFY(table.record(*r.recording).ok());
        });
        QSignalSpy finished(&sequence, &RackSequence::finished);
        if (!sequence.start())
            return true;
        return finished.wait(20000) || finished.size() == 1;
    }

    // Measures the whole rack (first setup), for a check to compare with.
    void measureAll()
    {
        RackSequence measure(&connection, RackSequence::plan(Mode::Measure, kRack, table, 0.1));
        QVERIFY(run(measure));
        QVERIFY2(measure.outcome().ok(), qPrintable(measure.outcome().message));
    }

    [[nodiscard]] QList<State> states(const RackSequence &sequence) const
    {
        QList<State> out;
        for (const RackStep &step : sequence.steps())
            out.append(step.state);
        return out;
    }
};

// The rack as a station measured it yesterday, on a machine switched off since.
ToolTable measuredYesterday()
{
    Station yesterday;
    yesterday.measureAll();
    return yesterday.table;
}

} // namespace

class TestRackSequence : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void measuresEveryRackToolOnce()
    {
        Station s;
        QVERIFY(s.connection.state() == MachineConnection::State::Connected);
        QCOMPARE(s.connection.firmware().kind, FirmwareInfo::Kind::Community);
        s.machine().setToolLength(4, 61.25);
        RackSequence measure(&s.connection, RackSequence::plan(Mode::Measure, kRack, s.table, 0.1));
        QVERIFY(s.run(measure));
        QVERIFY2(measure.outcome().ok(), qPrintable(measure.outcome().message));
        QCOMPARE(s.states(measure), QList<State>(6, State::Measured));
        // T1 is already in the spindle: measured where it is; the others are changed to, and measured.
        QVERIFY(s.sent.contains("M491"));
        for (int t = 2; t <= 6; ++t)
            QVERIFY2(s.sent.contains("M6 T" + QByteArray::number(t)), qPrintable(QString::number(t)));
        QCOMPARE(s.recordings.size(), 6);
        for (const Recording &r : std::as_const(s.recordings))
            QCOMPARE(r.kind, RecordingKind::Probe);
        // Against the machine's reference (-115.340): T1 77.7 mm long, T4 61.25.
        QCOMPARE(*s.table.find(1)->measuredTlo, 43.04);
        QCOMPARE(QString::number(*s.table.find(4)->measuredTlo, 'f', 3), u"26.590"_s);
        QCOMPARE(*s.table.find(4)->referenceMz, -115.34);
        QCOMPARE(s.machine().tool(), 6);
        QVERIFY(!s.connection.isBusy());
    }

    void checksEveryToolAndPutsTheLastBack()
    {
        Station s;
        s.measureAll();
        s.recordings.clear();
        const ToolTable measured = s.table;
        s.sent.clear();
        RackSequence check(&s.connection, RackSequence::plan(Mode::Check, kRack, s.table, 0.05));
        QVERIFY(s.run(check));
        QVERIFY2(check.outcome().ok(), qPrintable(check.outcome().message));
        QCOMPARE(s.states(check), QList<State>(6, State::Passed));
        // Each tool gets its stored TLO, then the firmware compares: M6 T (and its offsets read), M493.3 Z,
        // M491.1 H.
        const qsizetype change = s.sent.indexOf("M6 T3");
        QVERIFY(change >= 0);
        QCOMPARE(s.sent.at(change + 1), QByteArray("M493.4"));
        QCOMPARE(s.sent.at(change + 2),
            "M493.3 Z" + numberBytes(*measured.find(3)->measuredTlo, NumberFormat::command()));
        QCOMPARE(s.sent.at(change + 3), QByteArray("M491.1 H0.05"));
        QCOMPARE(s.sent.last(), QByteArray("M6 T-1"));
        QCOMPARE(s.machine().tool(), -1);
        // Six verdicts, no measurement: the TLOs stay as measured.
        QCOMPARE(s.recordings.size(), 6);
        for (const Recording &r : std::as_const(s.recordings)) {
            QCOMPARE(r.kind, RecordingKind::BreakTest);
            QCOMPARE(r.breakTestFailed, std::optional<bool>(false));
        }
        for (int t : kRack)
            QCOMPARE(s.table.find(t)->measuredTlo, measured.find(t)->measuredTlo);
    }

    // The reference tool (a stored TLO of 0.000) cannot be break-tested: the firmware's M491.1 takes 0 for
    // "No previous TLO" and measures without comparing. The check skips it, as Prepare does, says why, and
    // goes on with the others.
    // The reference tool's stored TLO is 0.000, which the firmware's break test takes for none: the check
    // tests it all the same (measured and compared by Toffee), and finds it broken when it is. It was once
    // skipped, and the check passed with that tool 0.5 mm short.
    void theReferenceToolIsTestedToo()
    {
        Station s;
        s.machine().setToolLength(2, s.machine().toolLength(2) - 9.652); // T2 is the reference: TLO 0
        s.measureAll();
        QCOMPARE(*s.table.find(2)->measuredTlo, 0.0);
        s.recordings.clear();
        s.sent.clear();
        RackSequence check(&s.connection, RackSequence::plan(Mode::Check, kRack, s.table, 0.05));
        QVERIFY(s.run(check));
        QVERIFY2(check.outcome().ok(), qPrintable(check.outcome().message));
        QCOMPARE(s.states(check),
            (QList<State> {
                State::Passed, State::Passed, State::Passed, State::Passed, State::Passed, State::Passed }));
        QVERIFY(s.sent.contains("M6 T2"));
        QCOMPARE(s.recordings.size(), 6);

        s.machine().breakTool(2, 0.5);
        s.recordings.clear();
        RackSequence again(&s.connection, RackSequence::plan(Mode::Check, kRack, s.table, 0.05));
        QVERIFY(s.run(again));
        QCOMPARE(again.outcome().outcome, SessionResult::Outcome::ToolBroken);
        QCOMPARE(again.steps().at(1).state, State::Broken);
        QVERIFY2(again.outcome().message.contains(u"-0.500 mm against 0.000 mm before"_s),
            qPrintable(again.outcome().message));
        QVERIFY(s.sent.contains("M493.3 Z0.001")); // 0.000 compared as 0.001: the firmware takes 0 for none
    }

    void aBrokenToolStopsTheCheck()
    {
        Station s;
        s.measureAll();
        s.recordings.clear();
        const ToolTable measured = s.table;
        s.machine().breakTool(3, 0.5);
        s.sent.clear();
        RackSequence check(&s.connection, RackSequence::plan(Mode::Check, kRack, s.table, 0.1));
        QVERIFY(s.run(check));
        QCOMPARE(check.outcome().outcome, Outcome::ToolBroken);
        QVERIFY2(check.outcome().message.contains(u"T3"_s), qPrintable(check.outcome().message));
        QCOMPARE(s.states(check),
            (QList<State> {
                State::Passed, State::Passed, State::Broken, State::NotRun, State::NotRun, State::NotRun }));
        QVERIFY(s.machine().isHalted()); // the firmware halts, as it does
        QCOMPARE(s.machine().haltReason(), 4);
        QVERIFY(!s.sent.contains("M6 T4"));
        QVERIFY(!s.sent.contains("M6 T-1"));
        QCOMPARE(s.recordings.size(), 3);
        QCOMPARE(s.recordings.last().breakTestFailed, std::optional<bool>(true));
        QVERIFY(s.table.find(3)->breakTestFailed);
        QCOMPARE(s.table.find(3)->measuredTlo, measured.find(3)->measuredTlo); // not the broken length
        QVERIFY(!s.connection.isBusy());
    }

    void aFaultAtEveryStepStopsTheSequence_data()
    {
        QTest::addColumn<int>("mode");
        QTest::addColumn<QByteArray>("command");
        QTest::addColumn<int>("fault");
        const std::pair<const char *, Fault> faults[] = { { "dropped ok", Fault::DropOk },
            { "no answer", Fault::NoAnswer }, { "garbled", Fault::Garble },
            { "link closed", Fault::CloseLink }, { "alarm mid-change", Fault::FailProbe } };
        const std::pair<int, QByteArray> steps[] = { { int(Mode::Measure), "M6 T3" },
            { int(Mode::Measure), "M491" }, { int(Mode::Check), "M6 T3" }, { int(Mode::Check), "M493.3" },
            { int(Mode::Check), "M491.1" }, { int(Mode::Check), "M6 T-1" } };
        for (const auto &[mode, command] : steps) {
            for (const auto &[name, fault] : faults) {
                QTest::addRow(
                    "%s, %s, %s", mode == int(Mode::Measure) ? "measure" : "check", command.constData(), name)
                    << mode << command << int(fault);
            }
        }
    }
    void aFaultAtEveryStepStopsTheSequence()
    {
        QFETCH(int, mode);
        QFETCH(QByteArray, command);
        QFETCH(int, fault);
        Station s;
        if (mode == int(Mode::Check)) {
            s.measureAll();
            s.recordings.clear();
        }
        const ToolTable before = s.table;
        // An alarm needs a probe to fail: it is aimed at the next probing cycle the command runs.
        if (Fault(fault) == Fault::FailProbe && command.startsWith("M493.3"))
            return; // M493.3 does not probe; its alarm is the M491.1 row's
        if (Fault(fault) == Fault::FailProbe && command == "M6 T-1")
            return; // emptying the spindle probes nothing
        s.machine().injectFault(Fault(fault), Fault(fault) == Fault::FailProbe ? QByteArray() : command);
        s.connection.link()->setTimeoutScale(0.005); // 5 s -> 25 ms, a change's 120 s -> 600 ms
        RackSequence sequence(&s.connection, RackSequence::plan(Mode(mode), kRack, s.table, 0.1));
        QVERIFY2(s.run(sequence), "the sequence hung");
        if (Fault(fault) == Fault::Garble && command.startsWith("M493.3")) {
            // Its report was garbled, but the firmware set the stored TLO: the break test's own line says it
            // compared with it (Old: …), which Toffee checks.
            QVERIFY2(sequence.outcome().ok(), qPrintable(sequence.outcome().message));
            return;
        }
        if (Fault(fault) == Fault::Garble && command == "M6 T-1") {
            // Its line was garbled, but the status confirms the spindle is empty: the put-back happened.
            QVERIFY2(sequence.outcome().ok(), qPrintable(sequence.outcome().message));
            QCOMPARE(s.machine().tool(), -1);
            return;
        }
        QVERIFY2(!sequence.outcome().ok(), "the fault went unnoticed");
        QVERIFY(sequence.outcome().outcome == Outcome::MachineError
            || sequence.outcome().outcome == Outcome::LinkFailure);
        QVERIFY2(sequence.outcome().message.size() > 20, qPrintable(sequence.outcome().message));
        QVERIFY(!s.connection.isBusy() || s.connection.state() == MachineConnection::State::Disconnected);
        // The failed tool and every one after it recorded nothing; the ones before, all they measured.
        const QList<State> states = s.states(sequence);
        const qsizetype failed = states.indexOf(State::Failed);
        if (command != "M6 T-1") {
            QVERIFY2(failed >= 0, "no tool failed");
            for (qsizetype i = failed + 1; i < states.size(); ++i)
                QCOMPARE(states.at(i), State::NotRun);
            QCOMPARE(s.recordings.size(), failed);
        } else {
            QCOMPARE(states, QList<State>(6, State::Passed)); // the put-back failed, after every verdict
            QCOMPARE(s.recordings.size(), 6);
        }
        for (const Recording &r : std::as_const(s.recordings))
            QVERIFY2(!r.tlo || mode == int(Mode::Measure), "a check stored a TLO");
        for (int t = failed < 0 ? 7 : kRack.at(failed); t <= 6; ++t)
            QCOMPARE(s.table.find(t) ? s.table.find(t)->measuredTlo : std::nullopt,
                before.find(t) ? before.find(t)->measuredTlo : std::nullopt);
    }

    void aReferenceAFewMicronsOffStillChecks()
    {
        const ToolTable measured = measuredYesterday();
        // Switched off and on: T1, the reference, measures 2 um shorter (the setter's scatter).
        Station today;
        today.machine().setToolLength(1, 77.698);
        today.table = measured;
        RackSequence check(&today.connection, RackSequence::plan(Mode::Check, kRack, today.table, 0.1));
        QVERIFY(today.run(check));
        QVERIFY2(check.outcome().ok(), qPrintable(check.outcome().message));
        QCOMPARE(today.states(check), QList<State>(6, State::Passed));
    }

    void aMovedReferenceStopsTheCheck()
    {
        const ToolTable measured = measuredYesterday();
        // Overnight the machine was calibrated again, 0.5 mm away: every stored TLO is off by that much now.
        Station today;
        today.machine().setReference(CarveraEmulator::kFactoryReferenceMz - 0.5);
        bool reported = false;
        QVERIFY(today.connection.report([&reported](const SessionResult &) { reported = true; }));
        QTRY_VERIFY(reported);
        today.table = measured;
        RackSequence check(&today.connection, RackSequence::plan(Mode::Check, kRack, today.table, 0.1));
        QVERIFY(today.run(check));
        QVERIFY2(check.outcome().outcome == Outcome::MachineError, qPrintable(check.outcome().message));
        QVERIFY2(check.outcome().message.contains(u"Check the machine's calibration"_s),
            qPrintable(check.outcome().message));
        QVERIFY(check.outcome().message.contains(u"0.500 mm away"_s));
        QCOMPARE(today.states(check).first(), State::Failed);
        QVERIFY(today.recordings.isEmpty());
        QVERIFY(!today.sent.contains("M491.1 H0.1")); // nothing compared against the wrong reference
    }

    void cancelFinishesTheCurrentToolAndStops()
    {
        Station s;
        s.machine().setTiming({ 150, 0, 150 });
        RackSequence measure(&s.connection, RackSequence::plan(Mode::Measure, kRack, s.table, 0.1));
        QObject::connect(&measure, &RackSequence::stepChanged, &measure, [&measure](int index) {
            if (index == 1 && measure.steps().at(1).state == State::Running)
                measure.cancel();
        });
        QVERIFY(s.run(measure));
        QVERIFY(measure.isCancelled());
        QVERIFY2(measure.outcome().ok(), qPrintable(measure.outcome().message));
        QVERIFY(measure.outcome().message.contains(u"T2"_s));
        QCOMPARE(s.states(measure),
            (QList<State> { State::Measured, State::Measured, State::NotRun, State::NotRun, State::NotRun,
                State::NotRun }));
        QCOMPARE(s.recordings.size(), 2);
        QVERIFY(!s.sent.contains("M6 T3"));
        QVERIFY(!s.machine().isHalted()); // finished, not stopped
    }

    void cancelOnTheLastToolLeavesItInTheSpindle()
    {
        Station s;
        s.measureAll();
        s.sent.clear();
        RackSequence check(&s.connection, RackSequence::plan(Mode::Check, kRack, s.table, 0.1));
        QObject::connect(&check, &RackSequence::stepChanged, &check, [&check](int index) {
            if (index == 5 && check.steps().at(5).state == State::Running)
                check.cancel();
        });
        QVERIFY(s.run(check));
        QVERIFY2(check.outcome().ok(), qPrintable(check.outcome().message));
        QCOMPARE(s.states(check), QList<State>(6, State::Passed));
        QVERIFY2(
            check.outcome().message.contains(u"every tool was done"_s), qPrintable(check.outcome().message));
        QVERIFY(!s.sent.contains("M6 T-1")); // cancelled: nothing more moves
        QCOMPARE(s.machine().tool(), 6);
    }

    void refusesWhatCannotRunBeforeAnythingMoves()
    {
        Station s;
        s.sent.clear();
        // Nothing measured yet: nothing to compare with.
        RackSequence unmeasured(&s.connection, RackSequence::plan(Mode::Check, kRack, s.table, 0.1));
        QVERIFY(!unmeasured.start());
        QCOMPARE(unmeasured.outcome().outcome, Outcome::Refused);
        QVERIFY2(unmeasured.outcome().message.contains(u"T1, T2, T3, T4, T5, T6"_s),
            qPrintable(unmeasured.outcome().message));
        RackSequence empty(&s.connection, RackSequence::plan(Mode::Measure, {}, s.table, 0.1));
        QVERIFY(!empty.start());
        s.measureAll();
        s.sent.clear();
        RackSequence tooTight(&s.connection, RackSequence::plan(Mode::Check, kRack, s.table, 0.01));
        QVERIFY(!tooTight.start());
        QVERIFY(tooTight.outcome().message.contains(u"0.02"_s));
        QVERIFY(s.sent.isEmpty());
    }

    void theStockFirmwareHasNoBreakTest()
    {
        Station s(true);
        QCOMPARE(s.connection.firmware().kind, FirmwareInfo::Kind::Stock);
        QCOMPARE(s.connection.firmware().version, u"1.0.1"_s);
        // Its TLO comes from the status report: no MCS Z is claimed.
        s.measureAll();
        QCOMPARE(s.recordings.size(), 6);
        QVERIFY(!s.table.find(2)->referenceMz);
        QCOMPARE(QString::number(*s.table.find(2)->measuredTlo, 'f', 3), u"9.652"_s);
        s.sent.clear();
        RackSequence check(&s.connection, RackSequence::plan(Mode::Check, kRack, s.table, 0.1));
        QVERIFY(!check.start());
        QVERIFY2(
            check.outcome().message.contains(u"stock firmware 1.0.1"_s), qPrintable(check.outcome().message));
        QVERIFY(s.sent.isEmpty());
        std::optional<SessionResult> refused;
        QVERIFY(s.connection.breakTest(0.1, [&refused](const SessionResult &r) { refused = r; }));
        QVERIFY(QTest::qWaitFor([&refused] { return refused.has_value(); }, 5000));
        QCOMPARE(refused->outcome, Outcome::Refused);
        QVERIFY(!s.sent.contains("M491.1 H0.1"));
    }

    void aManualChangeTakesTheStoredTlo()
    {
        Station s;
        s.measureAll(); // a reference
        std::optional<SessionResult> changed;
        QVERIFY(s.connection.changeTool(
            8, [&changed](const SessionResult &r) { changed = r; }, -12.3));
        QVERIFY(QTest::qWaitFor([&changed] { return changed.has_value(); }, 5000));
        QVERIFY2(changed->ok(), qPrintable(changed->message));
        QCOMPARE(s.sent.last(), QByteArray("M493.4"));
        QVERIFY(s.sent.contains("M6 T8 H-12.3"));
        QCOMPARE(QString::number(s.machine().tlo(), 'f', 3), u"-12.300"_s);
        QVERIFY(changed->recording);
        QCOMPARE(changed->recording->kind, RecordingKind::Restore);
        QCOMPARE(*changed->recording->tlo, -12.3);
    }
};

QTEST_GUILESS_MAIN(TestRackSequence)
#include "tst_racksequence.moc"
