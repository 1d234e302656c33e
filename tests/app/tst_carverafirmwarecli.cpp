// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli against the Carvera's real firmware (TOFFEE_CARVERA_PEER: the community firmware in its
// simulator) over its serial port, as a script runs it: status, select-tool, probe, report, set-tlo, a break
// test that fails and one that passes, unlock; what the table file and the history hold after each.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/support/carverapeer.h"
#include "tests/support/processes.h"

using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

QJsonObject json(const Run &run)
{
    return QJsonDocument::fromJson(run.out.trimmed().split('\n').last()).object();
}

QString fixed3(const QJsonValue &v)
{
    return QString::number(v.toDouble(), 'f', 3);
}

} // namespace

class TestCarveraFirmwareCli : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_port;

    QString table() const { return m_dir.filePath(u"tools.json"_s); }
    Run machine(const QStringList &arguments)
    {
        return cli(QStringList { u"--json"_s, u"--library"_s, m_dir.filePath(u"library.sqlite"_s),
                       u"--table"_s, table(), u"--port"_s, m_port }
                + arguments,
            90000);
    }
    QJsonObject tool(int number) const
    {
        for (const QJsonValue &t :
            QJsonDocument::fromJson(readFile(table())).object()[u"tools"_s].toArray()) {
            if (t[u"number"_s].toInt() == number)
                return t.toObject();
        }
        return {};
    }

private Q_SLOTS:
    void initTestCase()
    {
        if (CarveraPeer::script().isEmpty())
            QSKIP(qPrintable(CarveraPeer::skipReason()));
        qputenv("XDG_DATA_HOME", m_dir.filePath(u"data"_s).toLocal8Bit());
    }

    void aScriptDrivesTheRealFirmware()
    {
        CarveraPeer peer;
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        m_port = peer.uart();
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), table()));
        QFile(table()).setPermissions(QFile::ReadOwner | QFile::WriteOwner);

        // It connects (the firmware answers `version` with no "ok") and knows the firmware for what it is.
        Run run = machine({ u"status"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"state"_s].toString(), u"Idle"_s);
        QCOMPARE(json(run)[u"tool"_s].toInt(), -1); // a fresh C1: nothing in the spindle
        QCOMPARE(json(run)[u"firmware"_s][u"kind"_s].toString(), u"community"_s);
        QCOMPARE(json(run)[u"firmware"_s][u"version"_s].toString(), u"2.1.0c-simulator"_s);
        QCOMPARE(json(run)[u"firmware"_s][u"break_test"_s].toBool(), true);

        // An empty spindle takes no TLO: the firmware would keep it for the next tool selected. Refused, and
        // the tool selected next runs with no TLO of 12.
        run = machine({ u"set-tlo"_s, u"--z"_s, u"12"_s });
        QVERIFY(run.exitCode != 0);
        QVERIFY2(run.err.contains("spindle is empty (T-1)") && run.err.contains("Nothing was sent"),
            run.err.constData());

        run = machine({ u"select-tool"_s, u"1"_s });
        QCOMPARE(run.exitCode, 0);
        QVERIFY(json(run)[u"warning"_s].toString().contains(u"another tool's"_s));
        QCOMPARE(fixed3(json(machine({ u"status"_s }))[u"tlo"_s]), u"0.000"_s);

        // Probed against the machine's own reference, its factory calibration: T1 does not become it.
        run = machine({ u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(fixed3(json(run)[u"tlo"_s]), u"6.915"_s);
        QCOMPARE(fixed3(json(run)[u"reference_mz"_s]), u"-115.340"_s);
        QCOMPARE(fixed3(json(run)[u"current_mz"_s]), u"-108.425"_s);
        QCOMPARE(fixed3(tool(1)[u"measured_tlo"_s]), u"6.915"_s);
        QCOMPARE(fixed3(tool(1)[u"reference_mz"_s]), u"-115.340"_s);
        run = machine({ u"report"_s });
        QCOMPARE(fixed3(json(run)[u"tlo"_s]), u"6.915"_s);

        // Set by hand: the firmware's TLO is the value set, and no MCS Z of the tool is claimed.
        run = machine({ u"set-tlo"_s, u"--z"_s, u"6.5"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(fixed3(json(run)[u"tlo"_s]), u"6.500"_s);
        QVERIFY(json(run)[u"current_mz"_s].isNull());
        QCOMPARE(tool(1)[u"tlo_source"_s].toString(), u"manual"_s);
        QCOMPARE(fixed3(json(machine({ u"status"_s }))[u"tlo"_s]), u"6.500"_s);

        // The break test against 6.500 finds 6.915: broken, marked, and the machine halts with the new length
        // in force.
        run = machine({ u"break-test"_s, u"--tolerance"_s, u"0.05"_s });
        QCOMPARE(run.exitCode, 3);
        QCOMPARE(json(run)[u"broken"_s].toBool(), true);
        QCOMPARE(fixed3(json(run)[u"old_tlo"_s]), u"6.500"_s);
        QCOMPARE(fixed3(json(run)[u"new_tlo"_s]), u"6.915"_s);
        QVERIFY2(run.err.contains("halted with the new length, 6.915 mm, in force"), run.err.constData());
        QVERIFY(tool(1)[u"break_test_failed"_s].toBool());
        run = machine({ u"status"_s });
        QCOMPARE(json(run)[u"state"_s].toString(), u"Alarm"_s);
        QCOMPARE(json(run)[u"halt_reason"_s].toInt(), 4);
        QCOMPARE(fixed3(json(run)[u"tlo"_s]), u"6.915"_s);
        QCOMPARE(machine({ u"probe"_s }).exitCode, 4); // halted: refused

        // Unlock sets the stored TLO back first: the broken tool's measured length is not left in force. The
        // history that recorded the test says which (no --table here), as the table would.
        run = cli({ u"--json"_s, u"--library"_s, m_dir.filePath(u"library.sqlite"_s), u"--port"_s, m_port,
                      u"unlock"_s },
            90000);
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"state"_s].toString(), u"Idle"_s);
        QCOMPARE(fixed3(json(machine({ u"status"_s }))[u"tlo"_s]), u"6.500"_s);
        QCOMPARE(machine({ u"unlock"_s }).exitCode, 0); // not halted: nothing sent, no hang

        // Probed again, the mark goes; a break test against that passes.
        QCOMPARE(machine({ u"probe"_s }).exitCode, 0);
        QVERIFY(!tool(1)[u"break_test_failed"_s].toBool());
        run = machine({ u"break-test"_s, u"--tolerance"_s, u"0.05"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"broken"_s].toBool(), false);

        // With neither the table nor the history, nothing can know the stored TLO later: the break test says
        // so, and the unlock says what it leaves in force (the length the test measured).
        const QStringList bare { u"--json"_s, u"--no-history"_s, u"--port"_s, m_port };
        QCOMPARE(cli(bare + QStringList { u"set-tlo"_s, u"--z"_s, u"6.5"_s }).exitCode, 0);
        run = cli(bare + QStringList { u"break-test"_s, u"--tolerance"_s, u"0.05"_s }, 90000);
        QCOMPARE(run.exitCode, 3);
        QVERIFY2(run.err.contains("cannot know the stored TLO: after unlocking, set it back (set-tlo 6.500)"),
            run.err.constData());
        run = cli(bare + QStringList { u"unlock"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(
            run.err.contains("The TLO in force is 6.915 mm, as the machine left it"), run.err.constData());
        QCOMPARE(fixed3(json(cli(bare + QStringList { u"status"_s }))[u"tlo"_s]), u"6.915"_s);
        QCOMPARE(machine({ u"probe"_s }).exitCode, 0);

        const Run history
            = cli({ u"--json"_s, u"--library"_s, m_dir.filePath(u"library.sqlite"_s), u"history"_s });
        QStringList kinds;
        for (const QJsonValue &e : json(history)[u"events"_s].toArray())
            kinds << e[u"kind"_s].toString() + (e[u"failed"_s].toBool() ? u"!"_s : QString());
        QCOMPARE(kinds,
            (QStringList {
                u"probe"_s, u"manual_set"_s, u"break_test!"_s, u"probe"_s, u"break_test"_s, u"probe"_s }));
    }

    // The firmware takes a TLO of 0.000 for none ("No previous TLO included", it measures without comparing):
    // a stored 0.000 goes in as 0.001 and the firmware compares it. Here T1 (6.915 mm) against a stored
    // 0.000: the firmware says "Old: 0.001 , new: 6.915", halts, and the check exits 3, not 0.
    void aStoredTloOfZeroIsComparedByTheFirmware()
    {
        CarveraPeer peer;
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        m_port = peer.uart();
        QFile::remove(table());
        {
            QFile file(table());
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(R"({"format": "toffee-tool-table", "version": 2, "units": "mm", "tools": [
{"number": 1, "pocket": 1, "measured_tlo": 0, "measured_at": "2026-11-21T08:00:00Z", "reference_mz": -115.34}]})");
        }
        QCOMPARE(machine({ u"select-tool"_s, u"1"_s }).exitCode, 0);
        const Run run = cli(QStringList { u"--library"_s, m_dir.filePath(u"zero.sqlite"_s), u"--table"_s,
                                table(), u"--port"_s, m_port, u"break-test"_s, u"--tolerance"_s, u"0.05"_s },
            90000);
        QVERIFY2(run.exitCode == 3, QByteArray(run.out + run.err).constData());
        QVERIFY2(run.out.contains("old TLO 0.000, new 6.915"), run.out.constData());
        QVERIFY(tool(1)[u"break_test_failed"_s].toBool());
        QCOMPARE(json(machine({ u"status"_s }))[u"halt_reason"_s].toInt(), 4); // the firmware's own verdict
    }

    // The firmware's own repeats and one-off touch-off point: M491 R3 (its summary read, every pass a touch,
    // the TLO the firmware keeps equal to Toffee's, which is the longest edge's), M491 X-5 Y-3, and an X the
    // machine cannot reach (its soft limit) said in its words, nothing recorded.
    void theFirmwareTouchesEachEdgeAndOffCentre()
    {
        CarveraPeer peer;
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        m_port = peer.uart();
        QFile::remove(table());
        {
            QFile file(table());
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(R"({"format": "toffee-tool-table", "version": 5, "units": "mm", "tools": [
{"number": 1, "pocket": 1, "flutes": 3, "spread_limit": 0.02}]})");
        }
        QCOMPARE(machine({ u"select-tool"_s, u"1"_s }).exitCode, 0);
        // Three edges: M491 R3.
        Run run = machine({ u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        const QJsonArray touches = json(run)[u"touches"_s].toArray();
        QCOMPARE(touches.size(), 3);
        for (const QJsonValue &z : touches)
            QCOMPARE(fixed3(z), u"-108.425"_s); // the simulator's setter gives every pass the same length
        QCOMPARE(json(run)[u"spread"_s].toDouble(), 0.0);
        QCOMPARE(fixed3(json(run)[u"tlo"_s]), u"6.915"_s);
        // What the firmware keeps in force is Toffee's TLO.
        QCOMPARE(fixed3(json(machine({ u"status"_s }))[u"tlo"_s]), u"6.915"_s);
        QCOMPARE(fixed3(tool(1)[u"measured_tlo"_s]), u"6.915"_s);
        QVERIFY2(
            run.err.contains("lifts 25 mm for you to turn the cutter to its next edge"), run.err.constData());
        // The firmware's break test touches once: said, the verdict its own.
        run = machine({ u"break-test"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(run.err.contains("touched T1 once, at one edge, not the 3 touches"), run.err.constData());
        // Off centre, within the machine: one touch at X−5 Y−3 from the setter.
        run = machine({ u"probe"_s, u"--touches"_s, u"1"_s, u"--offset"_s, u"-5,-3"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(fixed3(json(run)[u"tlo"_s]), u"6.915"_s);
        QCOMPARE(json(run)[u"touches"_s].toArray().size(), 0);
        const Run report = cli({ u"--port"_s, m_port, u"report"_s }, 30000);
        QVERIFY2(report.exitCode == 0, report.err.constData());
        // Beyond the machine's X travel (this C1's soft limit): the firmware halts, said, nothing recorded.
        const QByteArray before = readFile(table());
        run = machine({ u"probe"_s, u"--touches"_s, u"1"_s, u"--offset"_s, u"10,0"_s });
        QCOMPARE(run.exitCode, 4);
        QVERIFY2(run.err.contains("Soft Endstop X"), run.err.constData());
        QCOMPARE(readFile(table()), before);
    }
};

QTEST_GUILESS_MAIN(TestCarveraFirmwareCli)
#include "tst_carverafirmwarecli.moc"
