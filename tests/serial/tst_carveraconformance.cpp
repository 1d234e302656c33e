// SPDX-License-Identifier: GPL-3.0-or-later
// Conformance: every operation Toffee uses, run against the Carvera's real firmware (the community firmware
// in its simulator, ../shared/peers/carvera, found through TOFFEE_CARVERA_PEER) and against Toffee's emulator
// set up as the same machine, each over a pseudo-terminal through the same MachineConnection. What Toffee
// concludes at each step — the outcome, the tool, the TLO in force, the reference, the tool's MCS Z, the
// state and halt, the break test's verdict, what it records, and the table at the end — must be the same for
// both: a difference fails, naming the step. Without the peer the test skips and says so.
#include <algorithm>

#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include "model/tooltable.h"
#include "serial/machineconnection.h"
#include "serial/transport/tcptransport.h"
#include "tests/support/carverapeer.h"
#include "tests/support/processes.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;
using Outcome = SessionResult::Outcome;

namespace {

// Every tool of the simulator measures the same: it triggers the setter at MCS Z -108.425.
const QStringList kLikeThePeer { u"--reference"_s, u"-115.34"_s, u"--spindle"_s, u"-1"_s, u"--empty-rack"_s,
    u"--probe-ms"_s, u"0"_s, u"--change-ms"_s, u"0"_s, u"--tool"_s, u"1=41.575"_s, u"--tool"_s, u"2=41.575"_s,
    u"--tool"_s, u"10=41.575"_s };

QString mm(std::optional<double> v)
{
    return v ? QString::number(*v, 'f', 3) : u"none"_s;
}

// What Toffee concluded from one step, as text: two runs agree when their lines are equal.
QString conclusion(const QString &step, bool started, const SessionResult &r)
{
    if (!started)
        return step + u": not started (refused while the machine cannot take it)"_s;
    const char *outcomes[] = { "success", "refused", "tool broken", "machine error", "link failure" };
    QStringList parts { step + u": "_s + QString::fromLatin1(outcomes[int(r.outcome)]) };
    if (r.tool)
        parts << u"T%1"_s.arg(*r.tool);
    if (r.tlo)
        parts << u"TLO %1, reference %2, MCS Z %3"_s.arg(
            mm(r.tlo->tlo()), mm(r.tlo->referenceMz), mm(r.tlo->currentMz));
    if (r.status) {
        parts << r.status->state;
        if (r.status->haltReason)
            parts << u"H:%1"_s.arg(*r.status->haltReason);
        if (r.status->tlo)
            parts << u"T: %1"_s.arg(mm(*r.status->tlo));
    }
    if (r.breakTest)
        parts << u"old %1, new %2"_s.arg(mm(r.breakTest->oldTlo), mm(r.breakTest->newTlo));
    if (r.recording) {
        const Recording &rec = *r.recording;
        parts << u"records T%1 kind %2 TLO %3 source %4 reference %5 broken %6"_s.arg(rec.tool)
                     .arg(int(rec.kind))
                     .arg(mm(rec.tlo))
                     .arg(int(rec.source))
                     .arg(mm(rec.referenceMz))
                     .arg(rec.breakTestFailed ? (*rec.breakTestFailed ? u"yes"_s : u"no"_s) : u"-"_s);
    }
    return parts.join(u" | "_s);
}

// A machine on a pseudo-terminal, driven through the window's connection, one step at a time.
class Machine
{
public:
    // `where`: a pseudo-terminal's path, or "tcp:HOST:PORT"; the protocol is found on connecting.
    explicit Machine(const QString &where)
    {
        ConnectionTarget target;
        target.emulator = false;
        if (where.startsWith(u"tcp:"_s)) {
            const auto address = TcpTransport::parseAddress(where.mid(4));
            target.host = address.value().host;
            target.tcpPort = address.value().port;
        } else {
            target.port = where;
        }
        m_connection.connectTo(target);
        (void)QTest::qWaitFor(
            [this] { return m_connection.state() != MachineConnection::State::Connecting; }, 20000);
        m_log << conclusion(u"connect"_s, m_connection.state() == MachineConnection::State::Connected,
            m_connection.connectResult())
              << u"firmware: %1"_s.arg(int(m_connection.firmware().kind))
              << u"framed: %1"_s.arg(m_connection.description().endsWith(u"(framed)"_s));
    }
    MachineConnection &connection() { return m_connection; }
    const QStringList &log() const { return m_log; }
    ToolTable &table() { return m_table; }

    // Runs an operation of the connection and notes what Toffee concluded; the result, for the next step.
    SessionResult step(const QString &name, const std::function<bool(MachineConnection::Done)> &operation)
    {
        std::optional<SessionResult> result;
        const bool started = operation([&result](const SessionResult &r) { result = r; });
        if (started && !QTest::qWaitFor([&result] { return result.has_value(); }, 60000)) {
            result = SessionResult {};
            result->outcome = Outcome::LinkFailure;
        }
        const SessionResult r = result.value_or(SessionResult {});
        m_log << conclusion(name, started, r);
        // What the window and the CLI record, recorded here too: the tables must agree at the end.
        if (r.recording)
            (void)m_table.record(*r.recording);
        QTest::qWait(200); // the status reports settle between steps
        return r;
    }

private:
    MachineConnection m_connection;
    QStringList m_log;
    ToolTable m_table;
};

// The script, the same for both: each operation Toffee uses, and the firmware's states between them.
void script(Machine &run)
{
    MachineConnection &c = run.connection();
    using Done = MachineConnection::Done;
    run.step(u"select T1"_s, [&c](Done d) { return c.selectTool(1, d); });
    run.step(u"report, nothing measured"_s, [&c](Done d) { return c.report(d); });
    run.step(u"probe T1"_s, [&c](Done d) { return c.probe(d); });
    run.step(u"report after the probe"_s, [&c](Done d) { return c.report(d); });
    run.step(u"set TLO -10.5"_s, [&c](Done d) { return c.setTlo(-10.5, d); });
    run.step(u"status"_s, [&c](Done d) { return c.status(d); });
    run.step(u"set TLO 3 mm above Z0"_s, [&c](Done d) { return c.setTloAboveZ0(3.0, d); });
    run.step(u"break test against -6, failing"_s, [&c](Done d) { return c.breakTest(0.05, d); });
    run.step(u"status, halted"_s, [&c](Done d) { return c.status(d); });
    run.step(u"probe while halted"_s, [&c](Done d) { return c.probe(d); });
    run.step(u"typed M493.4 while halted"_s, [&c](Done d) {
        return c.sendLine("M493.4", [d](const CommandReply &reply, const SessionResult &r) {
            SessionResult said = r;
            said.outcome = reply.ok() ? Outcome::Success : Outcome::MachineError;
            d(said);
        });
    });
    run.step(u"unlock, the stored TLO set back"_s, [&c](Done d) { return c.unlock(d); });
    run.step(u"status, unlocked"_s, [&c](Done d) { return c.status(d); });
    run.step(u"break test against the stored 6.915, passing"_s,
        [&c](Done d) { return c.breakTest(0.05, d, 6.915); });
    run.step(u"break test at 0.01"_s, [&c](Done d) { return c.breakTest(0.01, d); });
    run.step(u"select T10"_s, [&c](Done d) { return c.selectTool(10, d); });
    run.step(u"break test of T10"_s, [&c](Done d) { return c.breakTest(0.1, d, 6.915); });
    run.step(u"select T1 again"_s, [&c](Done d) { return c.selectTool(1, d); });
    run.step(u"change to T2 (the rack is empty)"_s, [&c](Done d) { return c.changeTool(2, d); });
    run.step(u"status after the change"_s, [&c](Done d) { return c.status(d); });
    run.step(u"unlock after the change"_s, [&c](Done d) { return c.unlock(d); });
    run.step(u"empty the spindle, already empty"_s, [&c](Done d) { return c.changeTool(-1, d); });
    run.step(u"unlock, not halted"_s, [&c](Done d) { return c.unlock(d); });
    run.step(u"typed $X, not halted"_s, [&c](Done d) {
        return c.sendLine("$X", [d](const CommandReply &reply, const SessionResult &r) {
            SessionResult said = r;
            said.outcome = reply.ok() && reply.lines.isEmpty() ? Outcome::Success : Outcome::MachineError;
            d(said);
        });
    });
    run.step(u"typed M493.1"_s, [&c](Done d) {
        return c.sendLine("M493.1", [d](const CommandReply &reply, const SessionResult &r) {
            SessionResult said = r;
            said.outcome = reply.ok() && reply.lines.isEmpty() ? Outcome::Success : Outcome::MachineError;
            d(said);
        });
    });
    // The shell's grbl commands: $I prints the modal state and no "ok", $G the same with one; neither may
    // leave the link waiting, nor an "ok" for the next command to take.
    for (const char *typed : { "$I", "$G", "$Q" }) {
        run.step(u"typed %1"_s.arg(QString::fromLatin1(typed)), [&c, typed](Done d) {
            return c.sendLine(typed, [d](const CommandReply &reply, const SessionResult &r) {
                SessionResult said = r;
                const bool state = reply.lines.size() == 1 && reply.lines.front().startsWith("[G0 G54");
                said.outcome = reply.ok() && state                  ? Outcome::Success
                    : reply.status == CommandReply::Status::Refused ? Outcome::Refused
                                                                    : Outcome::MachineError;
                d(said);
            });
        });
        run.step(u"status after %1"_s.arg(QString::fromLatin1(typed)), [&c](Done d) { return c.status(d); });
    }
    // A move beyond the machine's travel: the firmware halts at its soft endstop (reason 10) before it moves,
    // and stays where it was.
    run.step(u"typed G91 G0 Z99999999"_s, [&c](Done d) {
        return c.sendLine("G91 G0 Z99999999", [d](const CommandReply &reply, const SessionResult &r) {
            SessionResult said = r;
            const bool endstop = std::any_of(reply.lines.cbegin(), reply.lines.cend(),
                [](const QByteArray &l) { return l.startsWith("ERROR: Soft Endstop Z was exceeded"); });
            said.outcome = endstop ? Outcome::MachineError : Outcome::Success;
            d(said);
        });
    });
    run.step(u"status at the soft endstop"_s, [&c](Done d) { return c.status(d); });
    run.step(u"where it stands"_s, [&c](Done d) {
        return c.status([d](const SessionResult &r) {
            SessionResult said = r;
            said.outcome = r.status && r.status->mpos[2] < -1.0 ? Outcome::Success : Outcome::MachineError;
            d(said);
        });
    });
    run.step(u"unlock after the soft endstop"_s, [&c](Done d) { return c.unlock(d); });
}

} // namespace

class TestCarveraConformance : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        if (CarveraPeer::script().isEmpty())
            QSKIP(qPrintable(CarveraPeer::skipReason()));
    }

    // The same operations over each wire the firmware serves: its USB serial port and its Wi-Fi TCP port, in
    // plain text (the community firmware) and in frames (--protocol makera, as Makera's current firmware).
    void toffeeConcludesTheSameFromTheFirmwareAndTheEmulator_data()
    {
        QTest::addColumn<bool>("tcp");
        QTest::addColumn<bool>("framed");
        QTest::newRow("serial, plain text") << false << false;
        QTest::newRow("TCP, plain text") << true << false;
        QTest::newRow("TCP, framed") << true << true;
        QTest::newRow("serial, framed") << false << true;
    }
    void toffeeConcludesTheSameFromTheFirmwareAndTheEmulator()
    {
        QFETCH(bool, tcp);
        QFETCH(bool, framed);
        CarveraPeer peer({}, framed ? u"makera"_s : u"smoothie"_s);
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        QTemporaryDir dir;
        QStringList emulatorArguments = kLikeThePeer;
        if (tcp)
            emulatorArguments << u"--listen"_s << u"0"_s;
        if (framed)
            emulatorArguments << u"--framed"_s;
        Emulator emulator(dir.filePath(u"tty"_s), emulatorArguments);
        QVERIFY(emulator.started());

        Machine firmware(tcp ? u"tcp:"_s + peer.wifi() : peer.uart());
        script(firmware);
        Machine emulated(tcp ? u"tcp:"_s + emulator.tcp() : dir.filePath(u"tty"_s));
        script(emulated);

        QStringList differences;
        for (qsizetype i = 0; i < std::max(firmware.log().size(), emulated.log().size()); ++i) {
            const QString f = firmware.log().value(i);
            const QString e = emulated.log().value(i);
            if (f != e)
                differences << u"firmware: %1\n emulator: %2"_s.arg(f, e);
        }
        QVERIFY2(differences.isEmpty(), qPrintable(differences.join(u"\n"_s)));
        for (const QString &line : firmware.log())
            qInfo().noquote() << line; // what both concluded, for the log
        // The conclusions hold what the firmware really does (not only that the two agree).
        const QStringList &log = firmware.log();
        QVERIFY2(
            log.first().contains(u"connect: success | T-1 | TLO 0.000, reference -115.340, MCS Z none"_s),
            qPrintable(log.first()));
        QCOMPARE(log.at(1), u"firmware: %1"_s.arg(int(FirmwareInfo::Kind::Community)));
        QCOMPARE(log.at(2), u"framed: %1"_s.arg(framed));
        const auto find = [&log](const QString &step) {
            for (const QString &l : log) {
                if (l.startsWith(step + u':'))
                    return l;
            }
            return QString();
        };
        QVERIFY2(find(u"probe T1"_s).contains(u"TLO 6.915, reference -115.340, MCS Z -108.425"_s),
            qPrintable(find(u"probe T1"_s)));
        QVERIFY2(find(u"set TLO -10.5"_s).contains(u"TLO -10.500, reference -115.340, MCS Z none"_s),
            qPrintable(find(u"set TLO -10.5"_s)));
        QVERIFY2(find(u"set TLO 3 mm above Z0"_s).contains(u"TLO -6.000"_s),
            qPrintable(find(u"set TLO 3 mm above Z0"_s)));
        QVERIFY2(find(u"break test against -6, failing"_s)
                     .startsWith(u"break test against -6, failing: tool broken"_s)
                && find(u"break test against -6, failing"_s).contains(u"old -6.000, new 6.915"_s),
            qPrintable(find(u"break test against -6, failing"_s)));
        // The firmware keeps the broken length in force while it halts; Unlock sets the stored one back.
        QVERIFY2(find(u"status, halted"_s).contains(u"Alarm | H:4 | T: 6.915"_s),
            qPrintable(find(u"status, halted"_s)));
        QVERIFY2(find(u"status, unlocked"_s).contains(u"Idle | T: -6.000"_s),
            qPrintable(find(u"status, unlocked"_s)));
        QVERIFY(find(u"probe while halted"_s).contains(u"not started"_s));
        QVERIFY(find(u"typed M493.4 while halted"_s).contains(u"machine error"_s)); // error:Alarm lock
        QVERIFY2(find(u"break test against the stored 6.915, passing"_s).contains(u"success"_s)
                && find(u"break test against the stored 6.915, passing"_s)
                       .contains(u"old 6.915, new 6.915"_s),
            qPrintable(find(u"break test against the stored 6.915, passing"_s)));
        QVERIFY(find(u"break test at 0.01"_s).contains(u"refused"_s));
        QVERIFY(find(u"break test of T10"_s).contains(u"refused"_s));
        QVERIFY2(find(u"status after the change"_s).contains(u"Alarm | H:7"_s),
            qPrintable(find(u"status after the change"_s)));
        QVERIFY(find(u"typed $X, not halted"_s).contains(u"success"_s)); // not a word, and no hang
        QVERIFY2(find(u"typed $I"_s).contains(u"success"_s), qPrintable(find(u"typed $I"_s)));
        QVERIFY2(find(u"typed $G"_s).contains(u"success"_s), qPrintable(find(u"typed $G"_s)));
        QVERIFY2(find(u"typed $Q"_s).contains(u"refused"_s), qPrintable(find(u"typed $Q"_s)));
        QVERIFY2(find(u"status after $I"_s).contains(u"success | T-1 | Idle"_s),
            qPrintable(find(u"status after $I"_s)));
        // What both recorded: the probe, the sets, the verdicts, in one table.
        QCOMPARE(firmware.table().tools().size(), emulated.table().tools().size());
        QVERIFY(firmware.table().find(1));
        QCOMPARE(*firmware.table().find(1)->measuredTlo, *emulated.table().find(1)->measuredTlo);
        QCOMPARE(firmware.table().find(1)->breakTestFailed, emulated.table().find(1)->breakTestFailed);
        QCOMPARE(*firmware.table().find(1)->referenceMz, -115.34);
    }
};

QTEST_GUILESS_MAIN(TestCarveraConformance)
#include "tst_carveraconformance.moc"
