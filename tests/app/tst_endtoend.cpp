// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli, through a real QSerialPort, against toffee-emulator on a pseudo-terminal.
#include <unistd.h>

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTest>

#include "model/formats/tablefile.h"
#include "model/library/library.h"
#include "tests/support/processes.h"

using namespace Qt::StringLiterals;
using Toffee::Test::cli;
using Toffee::Test::Emulator;
using Toffee::Test::readFile;
using Toffee::Test::Run;

namespace {

QJsonObject json(const Run &run)
{
    return QJsonDocument::fromJson(run.out).object();
}

QString fixed3(const QJsonValue &v)
{
    return QString::number(v.toDouble(), 'f', 3);
}

} // namespace

class TestEndToEnd : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString tty() const { return m_dir.filePath(u"ttyCARVERA"_s); }
    QString library() const { return m_dir.filePath(u"library.sqlite"_s); }
    Run machine(const QStringList &arguments)
    {
        return cli(QStringList { u"--json"_s, u"--library"_s, library(), u"--port"_s, tty() } + arguments);
    }

private Q_SLOTS:
    // The seed's worked example on the machine as its firmware is: the reference is the machine's calibration
    // (-115.340), every TLO the firmware's own.
    void followsTheSeedsWorkedExampleOverAPty()
    {
        Emulator emulator(tty(), {});
        QVERIFY(emulator.started());
        const QString table = m_dir.filePath(u"tools.json"_s);
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), table));

        Run run = machine({ u"probe"_s });
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(fixed3(json(run).value(u"reference_mz"_s)), u"-115.340"_s); // the machine's, not T1's
        QCOMPARE(fixed3(json(run).value(u"tlo"_s)), u"43.040"_s);

        run = machine({ u"select-tool"_s, u"2"_s });
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(json(run).value(u"tool"_s).toInt(), 2);
        // Never silently: the machine still has T1's TLO.
        QVERIFY(json(run).value(u"warning"_s).toString().contains(u"another tool's"_s));

        run = machine({ u"--table"_s, table, u"probe"_s });
        QCOMPARE(run.exitCode, 0);
        QJsonObject o = json(run);
        QCOMPARE(o.value(u"tool"_s).toInt(), 2);
        QCOMPARE(fixed3(o.value(u"current_mz"_s)), u"-105.688"_s);
        QCOMPARE(fixed3(o.value(u"reference_mz"_s)), u"-115.340"_s);
        QCOMPARE(fixed3(o.value(u"tlo"_s)), u"9.652"_s);
        const Run shown = cli({ u"--json"_s, u"show"_s, table });
        const QJsonObject t2
            = QJsonDocument::fromJson(shown.out).object()[u"tools"_s].toArray().at(1).toObject();
        QCOMPARE(fixed3(t2.value(u"measured_tlo"_s)), u"9.652"_s); // recorded, with its time
        QVERIFY(QDateTime::fromString(t2.value(u"measured_at"_s).toString(), Qt::ISODateWithMs)
                    .secsTo(QDateTime::currentDateTimeUtc())
            < 60);

        run = machine({ u"break-test"_s, u"--tolerance"_s, u"0.05"_s });
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(json(run).value(u"broken"_s).toBool(), false);

        // "Adding 2.9mm length to the current tool": 9.652 + 2.9 = 12.552, recorded as set by hand.
        run = machine({ u"--table"_s, table, u"set-tlo"_s, u"--z"_s, u"12.552"_s });
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(fixed3(json(run).value(u"tlo"_s)), u"12.552"_s);
        auto shownTool = [&table](int index) {
            const Run shown = cli({ u"--json"_s, u"show"_s, table });
            return QJsonDocument::fromJson(shown.out).object()[u"tools"_s].toArray().at(index).toObject();
        };
        QCOMPARE(fixed3(shownTool(1).value(u"measured_tlo"_s)), u"12.552"_s);
        QCOMPARE(shownTool(1).value(u"tlo_source"_s).toString(), u"manual"_s);
        QCOMPARE(shownTool(0).value(u"tlo_source"_s).toString(), u"probe"_s);
        run = machine({ u"report"_s });
        QCOMPARE(fixed3(json(run).value(u"tlo"_s)), u"12.552"_s);
        // After M493.3 Z the firmware's "current tool offset" is the TLO itself, no MCS Z: none is claimed.
        QVERIFY(json(run).value(u"current_mz"_s).isNull());

        run = machine({ u"status"_s });
        QCOMPARE(run.exitCode, 0);
        o = json(run);
        QCOMPARE(o.value(u"state"_s).toString(), u"Idle"_s);
        QCOMPARE(o.value(u"tool"_s).toInt(), 2);
        QCOMPARE(fixed3(o.value(u"tlo"_s)), u"12.552"_s);
        QVERIFY(o.value(u"halt_reason"_s).isNull());
        QCOMPARE(o.value(u"mpos"_s).toArray().size(), 3);

        // The break test against the hand-set TLO finds the real T2 2.9 mm off: the table marks it.
        run = machine({ u"--table"_s, table, u"break-test"_s });
        QCOMPARE(run.exitCode, 3);
        QVERIFY(shownTool(1).value(u"break_test_failed"_s).toBool());
        const Run text = cli({ u"show"_s, table });
        QVERIFY(text.out.contains("FAILED ITS LAST BREAK TEST"));
        QVERIFY(text.out.contains("TLO set by hand"));
        QCOMPARE(machine({ u"unlock"_s }).exitCode, 0);
        // Probed again: measured, unmarked.
        QCOMPARE(machine({ u"--table"_s, table, u"probe"_s }).exitCode, 0);
        QVERIFY(!shownTool(1).value(u"break_test_failed"_s).toBool());
        QCOMPARE(shownTool(1).value(u"tlo_source"_s).toString(), u"probe"_s);
        QCOMPARE(fixed3(shownTool(1).value(u"measured_tlo"_s)), u"9.652"_s);

        // Every measurement is in the history library, in order, with what the machine reported.
        run = cli({ u"--json"_s, u"--library"_s, library(), u"history"_s, u"--tool"_s, u"2"_s });
        QCOMPARE(run.exitCode, 0);
        const QJsonArray events = json(run).value(u"events"_s).toArray();
        QStringList kinds;
        for (const QJsonValue &e : events)
            kinds << e[u"kind"_s].toString();
        QCOMPARE(kinds,
            (QStringList { u"probe"_s, u"break_test"_s, u"manual_set"_s, u"break_test"_s, u"probe"_s }));
        QCOMPARE(fixed3(events.at(0)[u"tlo"_s]), u"9.652"_s);
        QCOMPARE(fixed3(events.at(0)[u"current_mz"_s]), u"-105.688"_s);
        QCOMPARE(fixed3(events.at(0)[u"reference_mz"_s]), u"-115.340"_s);
        QCOMPARE(events.at(1)[u"failed"_s].toBool(), false);
        QCOMPARE(events.at(1)[u"tolerance"_s].toDouble(), 0.05);
        QCOMPARE(fixed3(events.at(2)[u"tlo"_s]), u"12.552"_s);
        QVERIFY(events.at(2)[u"current_mz"_s].isNull());
        QCOMPARE(events.at(3)[u"failed"_s].toBool(), true);
        QCOMPARE(fixed3(events.at(3)[u"old_tlo"_s]), u"12.552"_s);
        QCOMPARE(fixed3(events.at(3)[u"new_tlo"_s]), u"9.652"_s);
        QCOMPARE(events.at(4)[u"machine"_s].toString(), u"Carvera"_s);
        {
            auto opened = Toffee::Library::open({ library() });
            QVERIFY(opened);
            const auto machines = opened.value()->machines().value();
            QCOMPARE(machines.size(), 1);
            QCOMPARE(machines.front().dialect, u"carvera"_s);
            QCOMPARE(machines.front().connection, tty() + u" 115200"_s);
        }
        const Run csv = cli({ u"--library"_s, library(), u"history"_s, u"--csv"_s });
        QCOMPARE(csv.exitCode, 0);
        QVERIFY(csv.out.startsWith("id,machine,tool,measured_at,kind,tlo,"));
        QCOMPARE(csv.out.count('\n'), 7); // the header, T1's probe and T2's five
    }

    void warnsWhenAProbeIsOffItsTrend()
    {
        {
            Emulator emulator(tty(), {});
            QVERIFY(emulator.started());
            QCOMPARE(machine({ u"probe"_s }).exitCode, 0); // T1, the reference
            QCOMPARE(machine({ u"--machine"_s, u"Mill 2"_s, u"change-tool"_s, u"2"_s }).exitCode, 0);
            const Run again = machine({ u"--machine"_s, u"Mill 2"_s, u"probe"_s });
            QCOMPARE(again.exitCode, 0);
            QVERIFY(!json(again).contains(u"trend_warning"_s)); // the same length: on its trend
        }
        // The same machine later, with T2 0.2 mm shorter than it was.
        Emulator emulator(tty(), { u"--break-tool"_s, u"2=0.2"_s });
        QVERIFY(emulator.started());
        QCOMPARE(machine({ u"--machine"_s, u"Mill 2"_s, u"probe"_s }).exitCode, 0);
        const Run run = machine({ u"--machine"_s, u"Mill 2"_s, u"change-tool"_s, u"2"_s });
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(json(run).value(u"trend_warning"_s).toString(),
            u"T2 measured 0.200 mm shorter than its trend predicts (±0.1): check the tip."_s);
        QVERIFY(run.err.contains("warning: T2 measured 0.200 mm shorter"));
    }

    void aTableThatCannotBeWrittenIsRefusedBeforeTheMachineMoves()
    {
        Emulator emulator(tty(), {});
        QVERIFY(emulator.started());
        // A read-only file system: unwritable even for root, as CI runs.
        QTemporaryDir folder;
        const bool mounted = ::geteuid() == 0
            && QProcess::execute(
                   u"mount"_s, { u"-t"_s, u"tmpfs"_s, u"-o"_s, u"size=1m"_s, u"tmpfs"_s, folder.path() })
                == 0;
        const QString table = folder.filePath(u"tools.json"_s);
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), table));
        if (mounted)
            QCOMPARE(QProcess::execute(u"mount"_s, { u"-o"_s, u"remount,ro"_s, folder.path() }), 0);
        else
            QVERIFY(QFile::setPermissions(table, QFileDevice::ReadOwner));
        auto unmount = qScopeGuard([&] {
            if (mounted)
                QProcess::execute(u"umount"_s, { folder.path() });
        });
        if (QFileInfo(table).isWritable())
            QSKIP("no way to make a file unwritable here");
        const Run run = machine({ u"--table"_s, table, u"probe"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("nothing was sent to the machine"));
        // The machine never probed: nothing is measured, no MCS Z of a tool.
        const QJsonObject report = json(machine({ u"report"_s }));
        QCOMPARE(fixed3(report.value(u"tlo"_s)), u"0.000"_s);
        QVERIFY(report.value(u"current_mz"_s).isNull());
    }

    void findsABrokenToolAndUnlocks()
    {
        Emulator emulator(tty(), { u"--fault"_s, u"break:0.5@M491.1"_s });
        QVERIFY(emulator.started());
        QCOMPARE(machine({ u"probe"_s }).exitCode, 0);
        Run run = machine({ u"break-test"_s });
        QCOMPARE(run.exitCode, 3);
        const QJsonObject o = json(run);
        QCOMPARE(o.value(u"broken"_s).toBool(), true);
        QCOMPARE(fixed3(o.value(u"difference"_s)), u"0.500"_s);
        QCOMPARE(o.value(u"tolerance"_s).toDouble(), 0.1);
        QVERIFY(run.err.contains("may be broken"));
        run = machine({ u"status"_s });
        QCOMPARE(json(run).value(u"state"_s).toString(), u"Alarm"_s);
        QCOMPARE(json(run).value(u"halt_reason"_s).toInt(), 4);
        QCOMPARE(machine({ u"probe"_s }).exitCode, 4); // Alarm lock
        run = machine({ u"unlock"_s });
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(json(run).value(u"state"_s).toString(), u"Idle"_s);
    }

    void reachesAHaltedMachine()
    {
        Emulator emulator(tty(), { u"--halted"_s, u"3"_s });
        QVERIFY(emulator.started());
        Run run = machine({ u"status"_s });
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(json(run).value(u"halt_reason"_s).toInt(), 3);
        run = machine({ u"report"_s });
        QCOMPARE(run.exitCode, 4);
        QVERIFY(json(run).value(u"error"_s).toString().contains(u"Alarm lock"_s));
        QCOMPARE(machine({ u"unlock"_s }).exitCode, 0);
        QCOMPARE(machine({ u"report"_s }).exitCode, 0);
    }

    // A stored TLO set back on the machine without probing, only against the reference it was measured with.
    void restoresAStoredTloAndRecordsTheRestore()
    {
        const QString table = m_dir.filePath(u"restore.json"_s);
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), table));
        QFile::setPermissions(table, QFile::ReadOwner | QFile::WriteOwner);
        Emulator emulator(tty(), {});
        QVERIFY(emulator.started());
        QCOMPARE(machine({ u"--table"_s, table, u"probe"_s }).exitCode, 0); // T1: 43.040
        QCOMPARE(machine({ u"--table"_s, table, u"change-tool"_s, u"2"_s }).exitCode, 0); // T2: 9.652
        QCOMPARE(machine({ u"select-tool"_s, u"1"_s }).exitCode, 0);
        QCOMPARE(machine({ u"--table"_s, table, u"probe"_s }).exitCode, 0);

        const Run run = machine({ u"--table"_s, table, u"restore"_s, u"2"_s });
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(json(run).value(u"tool"_s).toInt(), 2);
        QCOMPARE(fixed3(json(run).value(u"tlo"_s)), u"9.652"_s);
        QCOMPARE(fixed3(json(machine({ u"report"_s })).value(u"tlo"_s)), u"9.652"_s);
        const QJsonArray events
            = json(cli({ u"--json"_s, u"--library"_s, library(), u"history"_s, u"--tool"_s, u"2"_s }))
                  .value(u"events"_s)
                  .toArray();
        QCOMPARE(events.last()[u"kind"_s].toString(), u"restore"_s);
        QCOMPARE(fixed3(events.last()[u"tlo"_s]), u"9.652"_s);

        // T3 has no TLO in the table: nothing to restore, nothing sent.
        const Run none = machine({ u"--table"_s, table, u"restore"_s, u"3"_s });
        QCOMPARE(none.exitCode, 2);
        QVERIFY(none.err.contains("T3 has no measured TLO"));

        // A stored TLO set by hand, failed in its break test, or older than the stale limit: refused by name
        // before anything is sent (the job preparation refuses the same); --anyway restores it all the same.
        {
            // T2's stored 9.652, said to be set by hand, failed, and measured eight days ago.
            auto loaded = Toffee::loadTableFile(table);
            QVERIFY(loaded.ok());
            Toffee::ToolTable edited = loaded.value();
            Toffee::Tool t2 = *edited.find(2);
            t2.tloSource = Toffee::TloSource::Manual;
            t2.breakTestFailed = true;
            t2.measuredAt = QDateTime::currentDateTimeUtc().addDays(-8);
            QVERIFY(edited.replace(2, t2).ok());
            QVERIFY(Toffee::saveTableFile(table, edited, Toffee::TableFormat::Json).ok());
            QCOMPARE(machine({ u"select-tool"_s, u"1"_s }).exitCode, 0);
            QCOMPARE(machine({ u"--table"_s, table, u"probe"_s }).exitCode, 0); // T1 again: 43.040 in force
            const QJsonObject before = json(machine({ u"report"_s }));
            QCOMPARE(fixed3(before.value(u"tlo"_s)), u"43.040"_s);

            Run run = machine({ u"--table"_s, table, u"restore"_s, u"2"_s });
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(run.err.contains(
                         "it was set by hand, not measured; it failed its last break test; it is 8 days "
                         "old, older than the stale limit (7 d, --stale-days)")
                    && run.err.contains("--anyway") && run.err.contains("Nothing was sent"),
                run.err.constData());
            QCOMPARE(json(machine({ u"report"_s })), before);
            // A longer stale limit leaves the other two.
            run = machine({ u"--table"_s, table, u"--stale-days"_s, u"30"_s, u"restore"_s, u"2"_s });
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(!run.err.contains("stale limit"), run.err.constData());
            run = machine({ u"--table"_s, table, u"--anyway"_s, u"restore"_s, u"2"_s });
            QVERIFY2(run.exitCode == 0, run.err.constData());
            QCOMPARE(fixed3(json(machine({ u"report"_s })).value(u"tlo"_s)), u"9.652"_s);
        }
    }

    void refusesToRestoreAgainstAnotherReference()
    {
        const QString table = m_dir.filePath(u"other-reference.json"_s);
        {
            Emulator emulator(tty(), {});
            QVERIFY(emulator.started());
            QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), table));
            QFile::setPermissions(table, QFile::ReadOwner | QFile::WriteOwner);
            QCOMPARE(machine({ u"--table"_s, table, u"probe"_s }).exitCode, 0);
            QCOMPARE(
                machine({ u"--table"_s, table, u"change-tool"_s, u"2"_s }).exitCode, 0); // against -115.340
        }
        // Another day, calibrated 10 mm lower: T2's stored TLO would be 10 mm off.
        Emulator emulator(tty(), { u"--reference"_s, u"-125.34"_s });
        QVERIFY(emulator.started());
        const QJsonObject before = json(machine({ u"report"_s }));
        const Run run = machine({ u"--table"_s, table, u"restore"_s, u"2"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("(10.000 mm apart): probe T2 instead"), run.err.constData());
        QCOMPARE(json(machine({ u"report"_s })), before); // nothing was set
    }

    void aLibraryThatIsNotOneIsRefusedBeforeTheMachineMoves()
    {
        Emulator emulator(tty(), {});
        QVERIFY(emulator.started());
        const QString folder = m_dir.filePath(u"not-a-file"_s);
        QVERIFY(QDir().mkpath(folder));
        const Run run = cli({ u"--library"_s, folder, u"--port"_s, tty(), u"probe"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QByteArray(folder.toUtf8() + " is a folder")), run.err.constData());
        QVERIFY(run.err.contains("--no-history"));
        // What records nothing needs no library: the status still answers.
        QCOMPARE(cli({ u"--library"_s, folder, u"--port"_s, tty(), u"status"_s }).exitCode, 0);
        // Nothing moved: the machine still has nothing measured.
        QVERIFY(json(machine({ u"report"_s })).value(u"current_mz"_s).isNull());
        QCOMPARE(cli({ u"--no-history"_s, u"--port"_s, tty(), u"probe"_s }).exitCode, 0);
    }

    void refusesATooSmallToleranceWithoutTouchingTheMachine()
    {
        const Run run
            = cli({ u"--port"_s, u"/dev/nonexistent-port"_s, u"break-test"_s, u"--tolerance"_s, u"0.01"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("too small"));
    }

    void reportsFaultsAndWorksAgain_data()
    {
        QTest::addColumn<QString>("fault");
        QTest::addColumn<QStringList>("command");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("message");
        QTest::newRow("dropped ok") << u"drop-ok@M493.4"_s << QStringList { u"report"_s } << 5
                                    << u"did not answer"_s;
        QTest::newRow("no answer") << u"no-answer@M493.3"_s << QStringList { u"set-tlo"_s, u"--z"_s, u"-1"_s }
                                   << 5 << u"did not answer"_s;
        QTest::newRow("garbled reply")
            << u"garble@M493.4"_s << QStringList { u"report"_s } << 4 << u"could not be read"_s;
        QTest::newRow("link closed") << u"close@M493.2"_s << QStringList { u"select-tool"_s, u"3"_s } << 5
                                     << u"lost"_s;
        QTest::newRow("probe fails") << u"fail-probe@M491"_s << QStringList { u"probe"_s } << 4
                                     << u"Calibrate fail! The tool setter was never touched"_s;
    }
    void reportsFaultsAndWorksAgain()
    {
        QFETCH(QString, fault);
        QFETCH(QStringList, command);
        QFETCH(int, exitCode);
        QFETCH(QString, message);
        Emulator emulator(tty(), { u"--fault"_s, fault });
        QVERIFY(emulator.started());
        const QString table = m_dir.filePath(u"fault.json"_s);
        QFile::remove(table);
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), table));
        const QByteArray before = readFile(table);

        const Run run = machine(QStringList { u"--timeout"_s, u"1"_s, u"--table"_s, table } + command);
        QCOMPARE(run.exitCode, exitCode);
        const QString error = json(run).value(u"error"_s).toString();
        QVERIFY2(error.contains(message), qPrintable(error));
        QCOMPARE(readFile(table), before);

        // A new connection (through the same link, even when the emulator had to open a new terminal) works.
        if (exitCode == 4)
            QCOMPARE(machine({ u"unlock"_s }).exitCode, 0);
        const Run again = machine({ u"report"_s });
        QVERIFY2(again.exitCode == 0, again.err.constData());
    }

    void aPortThatVanishesMidProbeIsALinkFailure()
    {
        auto emulator = std::make_unique<Emulator>(tty(), QStringList { u"--probe-ms"_s, u"5000"_s });
        QVERIFY(emulator->started());
        const QString table = m_dir.filePath(u"vanish.json"_s);
        QFile::remove(table);
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), table));
        const QByteArray before = readFile(table);
        QProcess probe;
        probe.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"),
            { u"--json"_s, u"--port"_s, tty(), u"--table"_s, table, u"probe"_s });
        QVERIFY(probe.waitForStarted());
        QTest::qWait(1000); // connected and probing
        emulator.reset(); // the machine goes away
        QVERIFY(probe.waitForFinished(20000));
        QCOMPARE(probe.exitCode(), 5);
        const QString error
            = QJsonDocument::fromJson(probe.readAllStandardOutput()).object()[u"error"_s].toString();
        QVERIFY2(error.contains(u"lost"_s) || error.contains(u"did not answer"_s), qPrintable(error));
        QCOMPARE(readFile(table), before);
    }

    void saysWhenThePortCannotBeOpened()
    {
        const Run run = cli({ u"--port"_s, u"/dev/nonexistent-port"_s, u"status"_s });
        QCOMPARE(run.exitCode, 5);
        QVERIFY2(run.err.contains("Cannot open /dev/nonexistent-port"), run.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestEndToEnd)
#include "tst_endtoend.moc"
