// SPDX-License-Identifier: GPL-3.0-or-later
// The rack from toffee-cli, through a real QSerialPort, against toffee-emulator on a pseudo-terminal: measure
// it, check it with one tool broken, load a manual tool with its stored TLO, and the stock firmware's limits.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include "model/library/library.h"
#include "tests/support/processes.h"

using namespace Qt::StringLiterals;
using Toffee::Test::cli;
using Toffee::Test::Emulator;
using Toffee::Test::Run;

namespace {

QJsonObject json(const Run &run)
{
    return QJsonDocument::fromJson(run.out).object();
}

QStringList states(const QJsonObject &o)
{
    QStringList out;
    for (const QJsonValue &t : o.value(u"tools"_s).toArray())
        out << t.toObject().value(u"state"_s).toString();
    return out;
}

} // namespace

class TestRackEndToEnd : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString tty() const { return m_dir.filePath(u"ttyCARVERA"_s); }
    QString library() const { return m_dir.filePath(u"library.sqlite"_s); }
    QString table() const { return m_dir.filePath(u"rack.json"_s); }
    // The operator types each command at the machine (a terminal): a manual change may wait for them, and
    // the emulator's operator puts the tool in. `script`: run as a script runs it, nobody to answer.
    Run machine(const QStringList &arguments, bool asJson = true, bool script = false)
    {
        QStringList args { u"--library"_s, library(), u"--port"_s, tty(), u"--table"_s, table() };
        if (asJson)
            args.prepend(u"--json"_s);
        return cli(args + arguments, 60000, !script);
    }
    int historyCount(const QString &kind)
    {
        const Run run = cli({ u"--json"_s, u"--library"_s, library(), u"history"_s });
        int n = 0;
        for (const QJsonValue &e : json(run).value(u"events"_s).toArray())
            n += e.toObject().value(u"kind"_s).toString() == kind;
        return n;
    }

private Q_SLOTS:
    void init()
    {
        QFile::remove(table());
        QFile::remove(library());
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), table()));
        QFile(table()).setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
    }

    void checksSixToolsAndNamesTheBrokenOne()
    {
        {
            Emulator emulator(tty(), {});
            QVERIFY(emulator.started());
            Run run = machine({ u"measure-rack"_s });
            QVERIFY2(run.exitCode == 0, run.err.constData());
            QCOMPARE(states(json(run)), QStringList(6, u"measured"_s));
            run = machine({ u"rack"_s });
            QCOMPARE(run.exitCode, 0);
            const QJsonArray rackSlots = json(run).value(u"slots"_s).toArray();
            QCOMPARE(rackSlots.size(), 6);
            QCOMPARE(
                QString::number(rackSlots.at(1).toObject().value(u"tlo"_s).toDouble(), 'f', 3), u"9.652"_s);
            QCOMPARE(json(run).value(u"spindle"_s).toInt(), 6);
            QCOMPARE(json(run)[u"firmware"_s][u"kind"_s].toString(), u"community"_s);
        }
        // The next morning: T3 chipped overnight.
        Emulator emulator(tty(), { u"--break-tool"_s, u"3=0.5"_s });
        QVERIFY(emulator.started());
        Run run = machine({ u"check-rack"_s, u"--tolerance"_s, u"0.1"_s });
        QCOMPARE(run.exitCode, 3);
        const QJsonObject o = json(run);
        QCOMPARE(states(o),
            (QStringList {
                u"passed"_s, u"passed"_s, u"broken"_s, u"not_run"_s, u"not_run"_s, u"not_run"_s }));
        QCOMPARE(o.value(u"broken"_s).toArray(), QJsonArray { 3 });
        QVERIFY2(
            o.value(u"error"_s).toString().contains(u"T3"_s), qPrintable(o.value(u"error"_s).toString()));
        // The table marks T3, and keeps its TLO as measured; the history has six probes and three verdicts.
        const Run shown = cli({ u"--json"_s, u"show"_s, table() });
        for (const QJsonValue &t : json(shown).value(u"tools"_s).toArray()) {
            if (t.toObject().value(u"number"_s).toInt() == 3)
                QVERIFY(t.toObject().value(u"break_test_failed"_s).toBool());
        }
        QCOMPARE(historyCount(u"probe"_s), 6);
        QCOMPARE(historyCount(u"break_test"_s), 3);
        // The machine halted, as the firmware does; in words, the broken tool is named.
        QCOMPARE(json(machine({ u"status"_s })).value(u"halt_reason"_s).toInt(), 4);
        run = machine({ u"unlock"_s });
        QCOMPARE(run.exitCode, 0);
        run = machine({ u"check-rack"_s }, false);
        QCOMPARE(run.exitCode, 3);
        QVERIFY2(run.out.contains("T3: broken"), run.out.constData());
        QVERIFY2(run.err.contains("T3 may be broken"), run.err.constData());
    }

    void aManualChangeTakesTheStoredTlo()
    {
        Emulator emulator(tty(), {});
        QVERIFY(emulator.started());
        QCOMPARE(machine({ u"measure-rack"_s }).exitCode, 0);
        QCOMPARE(machine({ u"change-tool"_s, u"8"_s }).exitCode, 0); // measured: a TLO for T8 in the table
        QCOMPARE(machine({ u"change-tool"_s, u"2"_s }).exitCode, 0);
        const int probes = historyCount(u"probe"_s);
        Run run = machine({ u"change-tool"_s, u"8"_s, u"--use-stored-tlo"_s });
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(historyCount(u"probe"_s), probes); // no probe
        QCOMPARE(historyCount(u"restore"_s), 1);
        // A rack tool is always measured by the machine: the option says so, and it probes.
        run = machine({ u"change-tool"_s, u"3"_s, u"--use-stored-tlo"_s });
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.err.contains("T3 is in the rack"));
        QCOMPARE(historyCount(u"probe"_s), probes + 1);
        // The end of the day: the spindle emptied, nothing measured.
        run = machine({ u"change-tool"_s, u"-1"_s }, false);
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(run.out, QByteArray("The spindle is empty.\n"));
        QCOMPARE(json(machine({ u"status"_s })).value(u"tool"_s).toInt(), -1);
        QCOMPARE(historyCount(u"probe"_s), probes + 1);
    }

    // A safety check that did not check says so in its exit status. The reference tool's TLO is 0.000, which
    // the firmware's break test takes for none: it was skipped and the check exited 0, the tool 0.5 mm short
    // or not. Now it is measured and compared; and a tool the firmware cannot test at all (T9, its wireless
    // probe's number) leaves the check incomplete: exit 1, never 0.
    void aCheckThatCouldNotCompareEveryToolDoesNotPass()
    {
        Emulator emulator(tty(), {});
        QVERIFY(emulator.started());
        QCOMPARE(machine({ u"measure-rack"_s }).exitCode, 0);
        {
            // T2's stored TLO made what the reference tool's is (the file holds a tool a line).
            QFile file(table());
            QVERIFY(file.open(QIODevice::ReadOnly));
            QStringList lines = QString::fromUtf8(file.readAll()).split(u'\n');
            file.close();
            for (QString &line : lines) {
                if (line.contains(u"\"number\": 2,"_s))
                    line.replace(
                        QRegularExpression(u"\"measured_tlo\": [-0-9.e]+"_s), u"\"measured_tlo\": 0"_s);
            }
            QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
            file.write(lines.join(u'\n').toUtf8());
        }
        Run run = machine({ u"check-rack"_s }, false);
        QVERIFY2(run.exitCode == 3, QByteArray(run.out + run.err).constData());
        QVERIFY2(run.out.contains("T2: broken"), run.out.constData());
        QVERIFY2(run.err.contains("against 0.000 mm before"), run.err.constData());
        QCOMPARE(json(machine({ u"status"_s })).value(u"halt_reason"_s).toInt(), 4); // the firmware compared
        QCOMPARE(machine({ u"unlock"_s }).exitCode, 0);

        QCOMPARE(machine({ u"measure-rack"_s }).exitCode, 0);
        run = machine({ u"check-rack"_s, u"--rack"_s, u"1,9"_s }, false);
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.out.contains("T9: skipped"), run.out.constData());
        QVERIFY2(run.err.contains("not every rack tool was checked: T9"), run.err.constData());
    }

    // A script (cron, ssh -n, a pipe) has nobody at the machine: a change that waits for a person is refused
    // before anything is sent, whichever tool it drops or picks by hand; a rack change goes on.
    void aChangeByHandFromAScriptIsRefusedBeforeAnythingMoves()
    {
        Emulator emulator(tty(), {});
        QVERIFY(emulator.started());
        QCOMPARE(machine({ u"measure-rack"_s }, true, true).exitCode, 0); // rack tools only: nobody needed
        const QJsonObject before = json(machine({ u"status"_s }));
        QCOMPARE(before.value(u"tool"_s).toInt(), 6);
        const int probes = historyCount(u"probe"_s);

        Run run = machine({ u"change-tool"_s, u"8"_s }, true, true);
        QCOMPARE(run.exitCode, 2);
        const QString error = json(run).value(u"error"_s).toString();
        QVERIFY2(error.startsWith(u"T8 is put in by hand on this machine"_s), qPrintable(error));
        QVERIFY2(
            error.contains(u"not a terminal"_s) && error.contains(u"Nothing was sent"_s), qPrintable(error));
        const QJsonObject after = json(machine({ u"status"_s }));
        QCOMPARE(after.value(u"tool"_s).toInt(), 6);
        QCOMPARE(after.value(u"mpos"_s), before.value(u"mpos"_s)); // it never went to the change position
        QCOMPARE(historyCount(u"probe"_s), probes);

        // At a terminal the same change is made (the emulator's operator puts T8 in); from a script, the way
        // back to the rack drops T8 by hand: refused too.
        QCOMPARE(machine({ u"change-tool"_s, u"8"_s }).exitCode, 0);
        run = machine({ u"change-tool"_s, u"2"_s }, true, true);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(
            json(run).value(u"error"_s).toString().startsWith(u"T8 is taken out by hand on this machine"_s),
            run.out.constData());
        QCOMPARE(json(machine({ u"status"_s })).value(u"tool"_s).toInt(), 8);
    }

    void aStoredTloIsTakenOnlyAgainstItsOwnReference()
    {
        {
            Emulator emulator(tty(), {});
            QVERIFY(emulator.started());
            QCOMPARE(machine({ u"measure-rack"_s }).exitCode, 0);
            QCOMPARE(machine({ u"change-tool"_s, u"8"_s }).exitCode, 0); // T8 against the reference -115.340
        }
        // Calibrated again, 1 mm lower: T8's stored TLO is against the reference before.
        Emulator emulator(tty(), { u"--reference"_s, u"-116.34"_s });
        QVERIFY(emulator.started());
        QCOMPARE(machine({ u"change-tool"_s, u"3"_s }).exitCode, 0);
        const int probes = historyCount(u"probe"_s);
        const Run run = machine({ u"change-tool"_s, u"8"_s, u"--use-stored-tlo"_s });
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.err.contains("reference MCS Z"), run.err.constData());
        QCOMPARE(historyCount(u"probe"_s), probes + 1); // probed, not restored
        QCOMPARE(historyCount(u"restore"_s), 0);
        // Nor is T1's restored: measured against the reference before.
        QCOMPARE(machine({ u"restore"_s, u"1"_s }).exitCode, 2);
    }

    // Makera's current firmware (framed, found as such) and the one before 1.0.4 (plain text): the same
    // limits.
    void theStockFirmwareHasNoRackCheck_data()
    {
        QTest::addColumn<QStringList>("options");
        QTest::addColumn<QString>("version");
        QTest::newRow("current, framed") << QStringList { u"--firmware"_s, u"stock"_s } << u"1.0.5"_s;
        QTest::newRow("before 1.0.4, plain")
            << QStringList { u"--firmware"_s, u"stock"_s, u"--plain"_s } << u"1.0.1"_s;
    }
    void theStockFirmwareHasNoRackCheck()
    {
        QFETCH(QStringList, options);
        QFETCH(QString, version);
        Emulator emulator(tty(), options);
        QVERIFY(emulator.started());
        Run run = machine({ u"measure-rack"_s });
        QCOMPARE(run.exitCode, 0);
        run = machine({ u"check-rack"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY(json(run).value(u"error"_s).toString().contains(u"stock firmware"_s));
        run = machine({ u"rack"_s });
        QCOMPARE(json(run)[u"firmware"_s][u"break_test"_s].toBool(), false);
        run = machine({ u"status"_s });
        QCOMPARE(json(run)[u"firmware"_s][u"kind"_s].toString(), u"stock"_s);
        QCOMPARE(json(run)[u"firmware"_s][u"version"_s].toString(), version);
        QCOMPARE(json(run)[u"firmware"_s][u"manual_offset"_s].toBool(), false);
        run = machine({ u"status"_s }, false);
        QVERIFY2(run.out.contains(QByteArray(
                     "Makera stock firmware " + version.toUtf8() + ": no break test, no manual offset")),
            run.out.constData());
        // It reports no reference: a stored TLO cannot be checked against it, so a manual change probes.
        QCOMPARE(machine({ u"change-tool"_s, u"8"_s }).exitCode, 0);
        QCOMPARE(machine({ u"change-tool"_s, u"2"_s }).exitCode, 0);
        run = machine({ u"change-tool"_s, u"8"_s, u"--use-stored-tlo"_s });
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.err.contains("reports no reference"), run.err.constData());
        QCOMPARE(historyCount(u"restore"_s), 0);
        run = machine({ u"break-test"_s });
        QCOMPARE(run.exitCode, 2);
        run = machine({ u"set-tlo"_s, u"--z"_s, u"-3"_s });
        QCOMPARE(run.exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TestRackEndToEnd)
#include "tst_rackendtoend.moc"
