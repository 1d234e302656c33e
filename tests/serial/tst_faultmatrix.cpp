// SPDX-License-Identifier: GPL-3.0-or-later
// Every machine-session operation under every injected fault: a clear error, no change to the tool table, and
// a link that works again after an unlock or a reconnect. In process, and over a real TCP socket in Makera's
// frames (the Wi-Fi link), where the machine may also reset the connection.
#include <array>

#include <QTest>

#include "model/tooltable.h"
#include "tests/support/sessionharness.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Test::SessionHarness;
using Fault = CarveraEmulator::Fault;
using Outcome = SessionResult::Outcome;

namespace {

enum Operation {
    Report,
    Probe,
    BreakTest,
    SetTlo,
    SetAboveZ0,
    SelectTool,
    ChangeTool,
    ChangeToStoredTlo,
    Unlock,
    RestoreTlo,
    OperationCount
};
enum Injected {
    DropOk,
    NoAnswer,
    Garble,
    CloseLink,
    Alarm,
    LateAnswer,
    ToolBroken,
    LinkReset,
    InjectedCount
};

// Sized by the enums, with a check that every entry is filled: a name left out fails to compile.
constexpr std::array<const char *, OperationCount> kOperationNames
    = { "report", "probe", "break-test", "set-tlo", "set-above-z0", "select-tool", "change-tool",
          "change-to-stored-tlo", "unlock", "restore-tlo" };
constexpr std::array<const char *, InjectedCount> kFaultNames = { "dropped ok", "no answer", "garbled reply",
    "link closed", "alarm", "late answer", "tool broken", "link reset" };
// The first command each operation sends, which the fault is aimed at.
constexpr std::array<const char *, OperationCount> kFirstCommand
    = { "M493.4", "M491", "M491.1", "M493.3", "M493.3", "M493.2", "M6", "M6", "$X", "M493.2" };
static_assert(kOperationNames.back() && kFaultNames.back() && kFirstCommand.back(), "every entry named");

void start(MachineSession &session, int operation, MachineSession::Done done)
{
    switch (operation) {
    case Report:
        return session.report(done);
    case Probe:
        return session.probe(done);
    case BreakTest:
        return session.breakTest(0.1, done);
    case SetTlo:
        return session.setTlo(-30.488, done);
    case SetAboveZ0:
        return session.setTloAboveZ0(3.0, done);
    case SelectTool:
        return session.selectTool(2, done);
    case ChangeTool:
        return session.changeTool(2, done);
    case ChangeToStoredTlo: // a manual tool, with the TLO the table holds: no probe
        return session.changeTool(8, done, -12.3);
    case Unlock:
        return session.unlock(done);
    default:
        return session.restoreTlo(2, -20.0, done);
    }
}

bool probes(int operation)
{
    return operation == Probe || operation == BreakTest || operation == ChangeTool;
}

// The fault of a row, aimed at the operation's first command.
void injectFault(CarveraEmulator &emulator, int operation, int fault)
{
    const QByteArray target = kFirstCommand[size_t(operation)];
    switch (fault) {
    case DropOk:
        emulator.injectFault(Fault::DropOk, target);
        break;
    case NoAnswer:
        emulator.injectFault(Fault::NoAnswer, target);
        break;
    case Garble:
        emulator.injectFault(Fault::Garble, target);
        break;
    case CloseLink:
    case LinkReset: // the harness's server resets instead of closing
        emulator.injectFault(Fault::CloseLink, target);
        break;
    case Alarm:
        if (probes(operation))
            emulator.injectFault(Fault::FailProbe); // the alarm comes in the middle of the cycle
        else
            emulator.halt(3); // already halted: every command gets "Alarm lock"
        break;
    case LateAnswer:
        // Beyond any limit the test set: 600 ms for a probe, 3 s for a tool change (a manual one waits for
        // the operator).
        emulator.injectFault(Fault::Delay, target, target == QByteArray("M6") ? 3500 : 800);
        break;
    case ToolBroken:
        emulator.injectFault(Fault::BreakTool, target, 0.5); // the tool in the spindle loses 0.5 mm
        break;
    }
}

} // namespace

class TestFaultMatrix : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void everyOperationUnderEveryFault_data()
    {
        QTest::addColumn<int>("operation");
        QTest::addColumn<int>("fault");
        QTest::addColumn<int>("wire");
        for (const auto wire : { SessionHarness::Wire::InProcess, SessionHarness::Wire::TcpFramed }) {
            const bool tcp = wire != SessionHarness::Wire::InProcess;
            for (int o = 0; o < OperationCount; ++o) {
                for (int f = 0; f < InjectedCount; ++f) {
                    if (f == LinkReset && !tcp)
                        continue; // a connection to reset is TCP's
                    QTest::addRow("%s%s, %s", tcp ? "TCP framed: " : "", kOperationNames[size_t(o)],
                        kFaultNames[size_t(f)])
                        << o << f << int(wire);
                }
            }
        }
    }
    void everyOperationUnderEveryFault()
    {
        QFETCH(int, operation);
        QFETCH(int, fault);
        QFETCH(int, wire);
        SessionHarness h { SessionHarness::Wire(wire) };
        if (h.server)
            h.server->setDropByReset(fault == LinkReset);
        // Connecting and the first probe at the real limits: under a sanitizer on a busy machine a 25 ms
        // limit is not always enough for a command that has no fault at all.
        QVERIFY(h.connect().ok());
        QVERIFY(h.run([&](auto done) { h.session.probe(done); }).ok()); // so the break test has a TLO

        ToolTable table = ToolTable::fromTools({ Tool { 1, 1, u"end mill"_s, 40, 0, 3, 0, -1.5, {}, {}, {} },
                                                   Tool { 2, 2, u"drill"_s, 50, 0, 2, 0, {}, {}, {}, {} } },
            Units::Millimetre)
                              .takeValue();
        const ToolTable before = table;

        // $X on a machine that is not halted is never sent (the firmware would say nothing): unlock is tried
        // on a halted one.
        if (operation == Unlock)
            h.emulator.halt(1);
        injectFault(h.emulator, operation, fault);
        h.link.setTimeoutScale(
            0.005); // for the operation under the fault: 5 s -> 25 ms, a probe's 120 s -> 600 ms

        const SessionResult r = h.run([&](auto done) { start(h.session, operation, done); });
        // What the window and the CLI do: record only a whole success.
        if (r.ok() && r.tlo && r.tool)
            QVERIFY(table.recordMeasurement(*r.tool, r.tlo->tlo(), QDateTime::currentDateTimeUtc()).ok());

        if (operation == Unlock && fault == Alarm) {
            QVERIFY2(r.ok(), qPrintable(r.message)); // unlocking a halted machine is what unlock is for
        } else if (fault == Garble && (operation == ChangeToStoredTlo || operation == SetTlo)) {
            // Only the command's own lines were garbled: the TLO in force is read from the status report
            // after it, and it is the one asked for, which is what counts.
            QVERIFY2(r.ok(), qPrintable(r.message));
            QCOMPARE(
                QString::number(r.tlo->tlo(), 'f', 3), operation == SetTlo ? u"-30.488"_s : u"-12.300"_s);
        } else if (fault == Garble && operation == SetAboveZ0) {
            // As above: Toffee works the TLO out itself, and the status report shows it in force.
            QVERIFY2(r.ok(), qPrintable(r.message));
            QCOMPARE(r.tlo->tlo(), h.emulator.tlo());
        } else if (fault == ToolBroken) {
            // Only the break test can tell a broken tool: it must say so and write nothing. A probe measures
            // the tool as it now is (T1, the reference, 0.5 mm short); the other operations do not look at
            // the tool.
            if (operation == BreakTest) {
                QCOMPARE(r.outcome, Outcome::ToolBroken);
                QVERIFY2(r.message.contains(u"may be broken"_s), qPrintable(r.message));
                QCOMPARE(table, before);
            } else {
                QVERIFY2(r.ok(), qPrintable(r.message));
                if (operation == Probe) // T1: 43.040 whole, 0.5 mm short now
                    QCOMPARE(QString::number(r.tlo->tlo(), 'f', 3), u"42.540"_s);
            }
        } else {
            QVERIFY2(!r.ok(), "the fault went unnoticed");
            QVERIFY(r.outcome == Outcome::MachineError || r.outcome == Outcome::LinkFailure);
            QVERIFY2(r.message.size() > 20, qPrintable(r.message));
            QVERIFY2(!r.message.startsWith(u"TEST:"_s), "the operation hung");
            QCOMPARE(table, before);
        }

        // Recovery, at the real limits again: reconnect when the link dropped, unlock when the machine
        // halted; then it answers again.
        h.link.setTimeoutScale(1.0);
        if (!h.link.isOpen()) {
            const SessionResult again = h.connect();
            QVERIFY2(again.ok(), qPrintable(again.message));
        }
        if (h.emulator.isHalted())
            QVERIFY(h.run([&](auto done) { h.session.unlock(done); }).ok());
        const SessionResult report = h.run([&](auto done) { h.session.report(done); });
        QVERIFY2(report.ok(), qPrintable(report.message));
    }
};

QTEST_GUILESS_MAIN(TestFaultMatrix)
#include "tst_faultmatrix.moc"
