// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli against grblHAL itself (TOFFEE_GRBLHAL_PEER: the real controller firmware built to run here,
// with a tool setter modelled by a file), as a script runs it, over TCP and over a pseudo-terminal:
// detection, two tools probed into the table and into grblHAL's own table (read back by the test with $#), a
// restart and a restore, a break test that passes and one that finds a tool 0.5 mm shorter with nothing
// overwritten, a probe that touches nothing, a TLO set by hand, push and pull. The table file, the history
// and the controller are checked at each step.
#include <cmath>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include "tests/support/grblhalpeer.h"
#include "tests/support/processes.h"

using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

QJsonObject json(const Run &run)
{
    return QJsonDocument::fromJson(run.out.trimmed().split('\n').last()).object();
}

// The setter at machine Z −100 and the fast feeds the peer's settings allow (a probe takes about 2 s).
const QString kSetter = u"0,0,-120,3000,300"_s;

} // namespace

class TestGrblHalCli : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QStringList m_target;

    QString table() const { return m_dir.filePath(u"tools.json"_s); }
    // The controller is not chosen: every command finds grblHAL by asking, and is given its setter and the
    // reference kept for the machine once it is known.
    Run machine(const QStringList &arguments, const QString &tablePath = {})
    {
        return cli(QStringList { u"--json"_s, u"--library"_s, m_dir.filePath(u"library.sqlite"_s),
                       u"--machine"_s, u"LongMill"_s, u"--setter"_s, kSetter, u"--table"_s,
                       tablePath.isEmpty() ? table() : tablePath }
                + m_target + arguments,
            90000);
    }
    static QJsonObject toolIn(const QString &path, int number)
    {
        for (const QJsonValue &t : QJsonDocument::fromJson(readFile(path)).object()[u"tools"_s].toArray()) {
            if (t[u"number"_s].toInt() == number)
                return t.toObject();
        }
        return {};
    }
    QJsonObject tool(int number) const { return toolIn(table(), number); }
    static bool writeEmptyTable(const QString &path)
    {
        QFile file(path);
        return file.open(QIODevice::WriteOnly)
            && file.write(R"({"format": "toffee-tool-table", "version": 1, "units": "mm", "tools": []})") > 0;
    }
    QList<QJsonObject> historyOf(int number)
    {
        const Run run = cli({ u"--json"_s, u"--library"_s, m_dir.filePath(u"library.sqlite"_s), u"history"_s,
            u"--machine"_s, u"LongMill"_s, u"--tool"_s, QString::number(number) });
        QList<QJsonObject> events;
        for (const QJsonValue &e : QJsonDocument::fromJson(run.out).object()[u"events"_s].toArray())
            events.append(e.toObject());
        return events;
    }

private Q_SLOTS:
    void initTestCase()
    {
        if (GrblHalPeer::script().isEmpty())
            QSKIP(qPrintable(GrblHalPeer::skipReason()));
        qputenv("XDG_DATA_HOME", m_dir.filePath(u"data"_s).toLocal8Bit());
    }

    void aScriptKeepsGrblHalsTableMeasured()
    {
        QTemporaryDir state;
        auto peer = std::make_unique<GrblHalPeer>(state.path());
        QVERIFY2(peer->started(), qPrintable(peer->errors()));
        QVERIFY(peer->writeSetter(-100.0, { { 1, 30.0 }, { 2, 45.3 }, { 3, 0.0 } }));
        m_target = peer->cliTarget();
        QVERIFY(writeEmptyTable(table()));
        // The machine's owner named the controller ($I=, kept in its EEPROM): that is how Toffee knows it
        // again, on whatever port it answers after a restart.
        QVERIFY(peer->ask("$I=LongMill").contains("ok"));

        // Detection: $I says grblHAL, its version, its name and a table of 16 tools.
        Run run = machine({ u"status"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"identity"_s].toString(), u"grblhal:name=LongMill"_s);
        const QJsonObject firmware = json(run)[u"firmware"_s].toObject();
        QCOMPARE(firmware[u"controller"_s].toString(), u"grblhal"_s);
        QCOMPARE(firmware[u"version"_s].toString(), u"1.1f.20260817"_s);
        QCOMPARE(firmware[u"tool_table_size"_s].toInt(), 16);
        QCOMPARE(json(run)[u"state"_s].toString(), u"Idle"_s);

        // The first tool measured is the machine's reference: TLO 0, its contact the reference.
        QCOMPARE(machine({ u"select-tool"_s, u"1"_s }).exitCode, 0);
        run = machine({ u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"tlo"_s].toDouble(), 0.0);
        QCOMPARE(json(run)[u"reference_mz"_s].toDouble(), -70.0);
        QCOMPARE(json(run)[u"history"_s].toString(), u"recorded"_s);
        QCOMPARE(tool(1)[u"measured_tlo"_s].toDouble(), 0.0);
        QCOMPARE(tool(1)[u"reference_mz"_s].toDouble(), -70.0);

        // The second against it: 45.3 − 30 = 15.3 mm longer, in the file and in grblHAL's own table.
        QCOMPARE(machine({ u"select-tool"_s, u"2"_s }).exitCode, 0);
        run = machine({ u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"tlo"_s].toDouble(), 15.3);
        QCOMPARE(json(run)[u"current_mz"_s].toDouble(), -54.7);
        QCOMPARE(tool(2)[u"measured_tlo"_s].toDouble(), 15.3);
        QCOMPARE(peer->tableZ(2), std::optional(15.3));
        QCOMPARE(peer->tableZ(1), std::optional(0.0));
        QCOMPARE(historyOf(2).size(), 1);
        QCOMPARE(historyOf(2).first()[u"kind"_s].toString(), u"probe"_s);
        // The offset is in force: the status report's WCO and $# say 15.3.
        QVERIFY(peer->ask("$#").contains("[TLO:0.000,0.000,15.300]"));

        // Switched off and on, with its EEPROM kept: the offset in force is gone; restore puts T2's stored
        // TLO back without probing, since the reference (from the history) still holds.
        peer.reset();
        peer = std::make_unique<GrblHalPeer>(state.path());
        QVERIFY2(peer->started(), qPrintable(peer->errors()));
        QVERIFY(peer->writeSetter(-100.0, { { 1, 30.0 }, { 2, 45.3 }, { 3, 0.0 } }));
        m_target = peer->cliTarget();
        QVERIFY(peer->ask("$#").contains("[TLO:0.000,0.000,0.000]"));
        QCOMPARE(
            peer->tableZ(2), std::optional(15.3)); // grblHAL kept its table: only the offset in force went
        run = machine({ u"restore"_s, u"2"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"tlo"_s].toDouble(), 15.3);
        QCOMPARE(peer->tableZ(2), std::optional(15.3));
        QVERIFY(peer->ask("$#").contains("[TLO:0.000,0.000,15.300]"));
        QCOMPARE(historyOf(2).last()[u"kind"_s].toString(), u"restore"_s);

        // A break test of the intact tool passes and changes nothing. The setter is the machine's, kept in
        // the library from the last --setter: not given again.
        run = cli(QStringList { u"--json"_s, u"--library"_s, m_dir.filePath(u"library.sqlite"_s),
                      u"--machine"_s, u"LongMill"_s, u"--controller"_s, u"grblhal"_s, u"--table"_s, table() }
                + m_target + QStringList { u"break-test"_s },
            90000);
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"broken"_s].toBool(), false);
        QCOMPARE(json(run)[u"new_tlo"_s].toDouble(), 15.3);

        // 0.5 mm shorter: broken, exit 3; the stored TLO stays in the table and in grblHAL.
        QVERIFY(peer->writeSetter(-100.0, { { 1, 30.0 }, { 2, 44.8 }, { 3, 0.0 } }));
        run = machine({ u"break-test"_s });
        QCOMPARE(run.exitCode, 3);
        QCOMPARE(json(run)[u"broken"_s].toBool(), true);
        QCOMPARE(json(run)[u"old_tlo"_s].toDouble(), 15.3);
        QCOMPARE(json(run)[u"new_tlo"_s].toDouble(), 14.8);
        QVERIFY2(run.err.contains("kept in the table and in grblHAL"), run.err.constData());
        QCOMPARE(tool(2)[u"measured_tlo"_s].toDouble(), 15.3);
        QCOMPARE(tool(2)[u"break_test_failed"_s].toBool(), true);
        QCOMPARE(peer->tableZ(2), std::optional(15.3));
        QVERIFY(peer->ask("$#").contains("[TLO:0.000,0.000,15.300]"));
        // Lifted, spindle stopped.
        const QList<QByteArray> modal = peer->ask("$G");
        QVERIFY(!modal.isEmpty() && modal.first().contains(" M5 "));

        // A probe that touches nothing (the lowest Z above the setter): ALARM:5 in words, nothing recorded.
        QCOMPARE(machine({ u"select-tool"_s, u"3"_s }).exitCode, 0);
        run = cli(QStringList { u"--json"_s, u"--no-history"_s, u"--controller"_s, u"grblhal"_s,
                      u"--setter"_s, u"0,0,-90,3000,300"_s, u"--table"_s, table() }
                + m_target + QStringList { u"probe"_s },
            60000);
        QCOMPARE(run.exitCode, 4);
        QVERIFY2(
            run.err.contains("ALARM:5") && run.err.contains("never touched the setter"), run.err.constData());
        QVERIFY(tool(3).isEmpty());
        QCOMPARE(peer->tableZ(3), std::optional(0.0));
        run = machine({ u"status"_s });
        QCOMPARE(json(run)[u"state"_s].toString(), u"Alarm"_s);
        // Every motion is refused until unlocked, and said so.
        run = machine({ u"set-tlo"_s, u"--z"_s, u"3.25"_s });
        QCOMPARE(run.exitCode, 4);
        QVERIFY2(run.err.contains("halted") || run.err.contains("Unlock"), run.err.constData());
        run = machine({ u"unlock"_s });
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(json(run)[u"state"_s].toString(), u"Idle"_s);
        QCOMPARE(json(machine({ u"status"_s }))[u"state"_s].toString(), u"Idle"_s);

        // A TLO set by hand: in the file as set by hand, and in grblHAL's table.
        run = machine({ u"set-tlo"_s, u"--z"_s, u"3.25"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(tool(3)[u"measured_tlo"_s].toDouble(), 3.25);
        QCOMPARE(tool(3)[u"tlo_source"_s].toString(), u"manual"_s);
        QCOMPARE(peer->tableZ(3), std::optional(3.25));

        // Push: grblHAL's entries emptied by hand are written back from the file and read back.
        QVERIFY(peer->ask("G10 L1 P1 Z7").contains("ok"));
        QVERIFY(peer->ask("G10 L1 P3 Z0").contains("ok"));
        run = machine({ u"push-offsets"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"written"_s].toArray().size(), 3);
        QCOMPARE(peer->tableZ(1), std::optional(0.0));
        QCOMPARE(peer->tableZ(2), std::optional(15.3));
        QCOMPARE(peer->tableZ(3), std::optional(3.25));

        // A tool beyond grblHAL's 16 is refused by name, and nothing is written.
        QVERIFY(peer->ask("G10 L1 P3 Z1.5").contains("ok"));
        QByteArray text = readFile(table());
        text.insert(text.lastIndexOf(']'),
            R"(, {"number": 20, "pocket": 20, "description": "", "length_geometry": 0, "length_wear": 0, )"
            R"("radius_geometry": 0, "radius_wear": 0, "measured_tlo": 4, "measured_at": "2026-11-25T00:00:00Z"})");
        const QString wide = m_dir.filePath(u"wide.json"_s);
        {
            QFile out(wide);
            QVERIFY(out.open(QIODevice::WriteOnly));
            out.write(text);
        }
        run = machine({ u"push-offsets"_s }, wide);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("T20") && run.err.contains("Nothing was written"), run.err.constData());
        QCOMPARE(peer->tableZ(3), std::optional(1.5));

        // Pull: what was set on the controller comes into a file: T3's 1.5 as set there, not measured, with a
        // history event; empty entries are left alone.
        const QString pulled = m_dir.filePath(u"pulled.json"_s);
        QVERIFY(writeEmptyTable(pulled));
        run = machine({ u"pull-offsets"_s }, pulled);
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"changed"_s].toArray().size(), 2); // T2 15.3 and T3 1.5; T1 is 0, an empty entry
        QCOMPARE(toolIn(pulled, 3)[u"measured_tlo"_s].toDouble(), 1.5);
        QCOMPARE(toolIn(pulled, 3)[u"tlo_source"_s].toString(), u"pulled"_s);
        QVERIFY(!toolIn(pulled, 3).contains(u"reference_mz"_s)); // not Toffee's measurement: never restored
        QCOMPARE(toolIn(pulled, 2)[u"measured_tlo"_s].toDouble(), 15.3);
        QVERIFY(toolIn(pulled, 1).isEmpty());
        QCOMPARE(historyOf(3).last()[u"kind"_s].toString(), u"import"_s);
        QCOMPARE(historyOf(3).last()[u"tlo"_s].toDouble(), 1.5);
        // Pulled again: nothing changed.
        run = machine({ u"pull-offsets"_s }, pulled);
        QCOMPARE(json(run)[u"changed"_s].toArray().size(), 0);
        QCOMPARE(json(run)[u"unchanged"_s].toInt(), 2);

        // A manual change: M6 T1 holds grblHAL in state Tool until the operator says the tool is in (Enter
        // here, or the machine's cycle start); then T1 is measured against the reference.
        {
            QProcess change;
            Terminal terminal; // the operator at the machine types the command, and Enter
            terminal.attach(change);
            change.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"),
                QStringList { u"--json"_s, u"--library"_s, m_dir.filePath(u"library.sqlite"_s),
                    u"--machine"_s, u"LongMill"_s, u"--controller"_s, u"grblhal"_s, u"--table"_s, table() }
                    + m_target + QStringList { u"change-tool"_s, u"1"_s });
            QVERIFY(change.waitForStarted());
            QByteArray said;
            QElapsedTimer clock;
            clock.start();
            while (!said.contains("press the machine's cycle start") && clock.elapsed() < 20000) {
                change.waitForReadyRead(100);
                said += change.readAllStandardError();
            }
            QVERIFY2(said.contains("put T1 in the spindle"), said.constData());
            terminal.type("\n");
            QVERIFY(change.waitForFinished(60000));
            const QByteArray out = change.readAllStandardOutput();
            QVERIFY2(change.exitCode() == 0, QByteArray(said + change.readAllStandardError()).constData());
            QCOMPARE(
                QJsonDocument::fromJson(out.trimmed().split('\n').last()).object()[u"tool"_s].toInt(), 1);
            QCOMPARE(
                QJsonDocument::fromJson(out.trimmed().split('\n').last()).object()[u"tlo"_s].toDouble(), 0.0);
            const QList<QByteArray> modal = peer->ask("$G");
            QVERIFY(!modal.isEmpty() && modal.first().contains(" T1 ") && modal.first().contains(" G43 "));
        }

        // The rack is the Carvera's: refused by name.
        run = machine({ u"measure-rack"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("no tool rack"), run.err.constData());
    }

    void overItsSerialPort()
    {
        GrblHalPeer peer({}, GrblHalPeer::Link::Pty);
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        QVERIFY(peer.writeSetter(-100.0, { { 4, 20.0 } }));
        m_target = peer.cliTarget();
        const QString path = m_dir.filePath(u"pty.json"_s);
        QVERIFY(writeEmptyTable(path));
        // No controller chosen: found by asking, on a serial port as on any.
        Run run
            = cli(QStringList { u"--json"_s, u"--no-history"_s } + m_target + QStringList { u"status"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"controller"_s].toString(), u"grblhal"_s);
        QCOMPARE(json(run)[u"firmware"_s][u"controller"_s].toString(), u"grblhal"_s);
        QCOMPARE(machine({ u"select-tool"_s, u"4"_s }, path).exitCode, 0);
        // The name LongMill stands for the machine of the TCP story (the controller named LongMill): this one
        // gives no name of its own and is refused until the operator says it is the same machine; nothing
        // recorded, nothing written.
        run = machine({ u"probe"_s }, path);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(
            run.err.contains("The library's machine \"LongMill\" is grblHAL \xe2\x80\x9cLongMill\xe2\x80\x9d")
                && run.err.contains(QByteArray(QByteArray("this is grblHAL at ") + peer.pty().toUtf8()))
                && run.err.contains("--same-machine"),
            run.err.constData());
        QVERIFY(toolIn(path, 4).isEmpty());
        // Said to be the same machine: the history's reference (−70, from the TCP story) is this machine's
        // too: a tool 20 mm long touches at −80, 10 mm shorter than the reference tool.
        run = machine({ u"--same-machine"_s, u"probe"_s }, path);
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"current_mz"_s].toDouble(), -80.0);
        QCOMPARE(toolIn(path, 4)[u"measured_tlo"_s].toDouble(), json(run)[u"tlo"_s].toDouble());
        run = cli(QStringList { u"--json"_s, u"--no-history"_s } + m_target + QStringList { u"report"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"tlo"_s].toDouble(), toolIn(path, 4)[u"measured_tlo"_s].toDouble());
    }

    void refusalsBeforeAnythingMoves()
    {
        // Without a setter a probe is refused with what to give; a malformed setter never reaches a machine.
        Run run = cli({ u"--no-history"_s, u"--controller"_s, u"grblhal"_s, u"--host"_s, u"127.0.0.1:9"_s,
            u"--setter"_s, u"0,0"_s, u"probe"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("X,Y,ZMIN"), run.err.constData());
        run = cli({ u"--no-history"_s, u"--controller"_s, u"grblhal"_s, u"--host"_s, u"127.0.0.1:9"_s,
            u"--setter"_s, u"0,0,-120,40,500"_s, u"probe"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("latch feed"), run.err.constData());
        run = cli({ u"--no-history"_s, u"--controller"_s, u"fanuc"_s, u"--emulator"_s, u"status"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("auto, carvera, grblhal or linuxcnc"), run.err.constData());
        run = cli({ u"--no-history"_s, u"--controller"_s, u"grblhal"_s, u"--emulator"_s, u"status"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("emulator is a Carvera"), run.err.constData());
    }

    // A pull is all or nothing: an entry beyond any tool (T2 at 5000 mm, set on the controller by someone)
    // keeps T1 and T3 out of the file and the history too, and the refusal names T2. It once wrote T1, failed
    // on T2 and skipped T3.
    void aPullWithOneImpossibleEntryTakesNone()
    {
        QTemporaryDir state;
        GrblHalPeer peer(state.path());
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        m_target = peer.cliTarget();
        const QString path = m_dir.filePath(u"pull.json"_s);
        QVERIFY(writeEmptyTable(path));
        for (const char *line : { "G10 L1 P1 Z10", "G10 L1 P2 Z5000", "G10 L1 P3 Z12" })
            QVERIFY(peer.ask(line).contains("ok"));
        const QByteArray before = readFile(path);
        const qsizetype events = historyOf(1).size() + historyOf(2).size() + historyOf(3).size();
        const Run run = machine({ u"--same-machine"_s, u"pull-offsets"_s }, path);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(json(run)[u"error"_s].toString().contains(u"T2: "_s), run.out.constData());
        QVERIFY2(json(run)[u"error"_s].toString().contains(u"Nothing was recorded"_s), run.out.constData());
        QCOMPARE(readFile(path), before);
        QCOMPARE(historyOf(1).size() + historyOf(2).size() + historyOf(3).size(), events);
    }

    // No controller chosen, on a port that is not grblHAL's 23: `auto` (the default) finds grblHAL by asking,
    // with questions that change nothing (its coolant stays off; the old framed status query toggled it).
    void autoFindsGrblHalOnAnyPortAndChangesNothing()
    {
        GrblHalPeer peer;
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        QVERIFY(peer.port() != 23);
        for (int i = 0; i < 2; ++i) {
            const Run run = cli(QStringList { u"--json"_s, u"--no-history"_s } + peer.cliTarget()
                + QStringList { u"status"_s });
            QVERIFY2(run.exitCode == 0, run.err.constData());
            QCOMPARE(json(run)[u"controller"_s].toString(), u"grblhal"_s);
            QCOMPARE(json(run)[u"state"_s].toString(), u"Idle"_s);
            QTest::qWait(200);
            const QList<QByteArray> modes = peer.ask("$G");
            QVERIFY(!modes.isEmpty());
            QVERIFY2(modes.front().contains(" M9 "), modes.front().constData());
        }
    }

    void aCarveraChosenAsGrblHalSaysSo()
    {
        // The built-in emulator over TCP, reached as grblHAL: $I gets no grblHAL answer, and the message says
        // which controller to choose.
        Emulator emulator(m_dir.filePath(u"tty"_s), { u"--listen"_s, u"127.0.0.1:0"_s });
        QVERIFY(emulator.started());
        const Run run = cli({ u"--no-history"_s, u"--controller"_s, u"grblhal"_s, u"--timeout"_s, u"5"_s,
            u"--host"_s, emulator.tcp(), u"status"_s });
        QVERIFY2(run.exitCode == 4 || run.exitCode == 5, run.err.constData());
        QVERIFY2(run.err.contains("--controller carvera"), run.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestGrblHalCli)
#include "tst_grblhalcli.moc"
