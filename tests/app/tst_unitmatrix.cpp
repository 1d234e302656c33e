// SPDX-License-Identifier: GPL-3.0-or-later
// One unit boundary: machines speak millimetres, a table its own units, and a length crosses at one place
// each way (ToolTable::recordMeasurement, ToolTable::storedTlo). An inch table against each millimetre
// controller family, through toffee-cli as an operator runs it: probe, break test, set, restore, push, pull,
// the history, the job check and its preparation; at each step what the file holds (inches), what the machine
// holds and what the history keeps (millimetres). And the reverse: a controller set to inches (grblHAL's G20,
// $13=1) is refused by name before anything is written. The Carvera's firmware takes no inches (G20 halts
// it): there is no reverse to run on it.
#include <cmath>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
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

double inches(double millimetres)
{
    return std::round(millimetres / 25.4 * 10000.0) / 10000.0;
}

const QString kSetter = u"0,0,-120,3000,300"_s;

} // namespace

class TestUnitMatrix : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QStringList m_target;
    QStringList m_controller;

    QString table() const { return m_dir.filePath(u"inch.json"_s); }
    QString library() const { return m_dir.filePath(u"library.sqlite"_s); }
    Run machine(const QStringList &arguments, const QString &tablePath = {})
    {
        return cli(QStringList { u"--json"_s, u"--library"_s, library(), u"--machine"_s, u"Mill"_s,
                       u"--table"_s, tablePath.isEmpty() ? table() : tablePath }
                + m_controller + m_target + arguments,
            90000);
    }
    QJsonObject tool(int number, const QString &path = {}) const
    {
        const QJsonObject file = QJsonDocument::fromJson(readFile(path.isEmpty() ? table() : path)).object();
        for (const QJsonValue &t : file[u"tools"_s].toArray()) {
            if (t[u"number"_s].toInt() == number)
                return t.toObject();
        }
        return {};
    }
    QJsonObject lastEvent(int number)
    {
        const Run run = cli({ u"--json"_s, u"--library"_s, library(), u"history"_s, u"--machine"_s, u"Mill"_s,
            u"--tool"_s, QString::number(number) });
        return QJsonDocument::fromJson(run.out).object()[u"events"_s].toArray().last().toObject();
    }
    bool writeTable(const QString &path, const QByteArray &units, const QByteArray &tools)
    {
        QFile file(path);
        return file.open(QIODevice::WriteOnly)
            && file.write(R"({"format": "toffee-tool-table", "version": 1, "units": ")" + units
                   + R"(", "tools": [)" + tools + "]}")
            > 0;
    }
    QByteArray program(const QString &name, const QByteArray &text)
    {
        QFile file(m_dir.filePath(name));
        return file.open(QIODevice::WriteOnly) && file.write(text) == text.size() ? file.fileName().toUtf8()
                                                                                  : QByteArray();
    }

    // grblHAL with its setter at machine Z -100, T1 30 mm and T2 45.3 mm long, as toffee-cli's target.
    bool useGrblHal(GrblHalPeer &peer)
    {
        if (!peer.started() || !peer.writeSetter(-100.0, { { 1, 30.0 }, { 2, 45.3 } }))
            return false;
        m_target = peer.cliTarget();
        m_controller = { u"--controller"_s, u"grblhal"_s, u"--setter"_s, kSetter };
        return true;
    }

private Q_SLOTS:
    void initTestCase() { qputenv("XDG_DATA_HOME", m_dir.filePath(u"data"_s).toLocal8Bit()); }
    void init()
    {
        QFile::remove(library());
        QVERIFY(writeTable(table(), "in",
            R"({"number": 1, "pocket": 1, "description": "1/8 in end mill"},
               {"number": 2, "pocket": 2, "description": "1/4 in end mill"})"));
    }

    void anInchTableAgainstTheCarvera()
    {
        const QString tty = m_dir.filePath(u"ttyCARVERA"_s);
        Emulator emulator(tty, { u"--tool"_s, u"1=41.575"_s, u"--tool"_s, u"2=30"_s });
        QVERIFY(emulator.started());
        m_target = { u"--port"_s, tty };
        m_controller = {};

        // Probe: the machine's millimetres, the file's inches, the history's millimetres.
        QCOMPARE(machine({ u"select-tool"_s, u"1"_s }).exitCode, 0);
        Run run = machine({ u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        const double t1 = json(run)[u"tlo"_s].toDouble();
        QVERIFY(t1 > 1.0);
        QCOMPARE(tool(1)[u"measured_tlo"_s].toDouble(), inches(t1));
        QCOMPARE(tool(1)[u"reference_mz"_s].toDouble(), inches(-115.34));
        QCOMPARE(lastEvent(1)[u"tlo"_s].toDouble(), t1);
        QCOMPARE(lastEvent(1)[u"reference_mz"_s].toDouble(), -115.34);

        // A break test compares the machine's length with the stored one, in millimetres: intact.
        run = machine({ u"break-test"_s });
        QVERIFY2(run.exitCode == 0, run.out.constData());
        QCOMPARE(json(run)[u"broken"_s].toBool(), false);
        QVERIFY(std::fabs(json(run)[u"old_tlo"_s].toDouble() - t1) < 0.002);

        // Set by hand: the value typed is the machine's millimetres.
        QCOMPARE(machine({ u"select-tool"_s, u"2"_s }).exitCode, 0);
        run = machine({ u"set-tlo"_s, u"--z"_s, u"12.7"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(tool(2)[u"measured_tlo"_s].toDouble(), 0.5);
        QCOMPARE(lastEvent(2)[u"tlo"_s].toDouble(), 12.7);
        QCOMPARE(json(machine({ u"status"_s }))[u"tlo"_s].toDouble(), 12.7);

        // Restore T1: the file's inches go to the machine as millimetres, and its reference fits.
        QCOMPARE(machine({ u"select-tool"_s, u"1"_s }).exitCode, 0);
        run = machine({ u"restore"_s, u"1"_s });
        QVERIFY2(run.exitCode == 0, run.out.constData());
        const double restored = json(machine({ u"status"_s }))[u"tlo"_s].toDouble();
        QVERIFY2(std::fabs(restored - t1) < 0.002, qPrintable(QString::number(restored)));
        QCOMPARE(lastEvent(1)[u"kind"_s].toString(), u"restore"_s);
        QVERIFY(std::fabs(lastEvent(1)[u"tlo"_s].toDouble() - t1) < 0.002);

        // The job check reads the file's TLOs as the history's: no "newer measurement" for T1, its TLO in mm.
        const QByteArray job = program(u"job.nc"_s, "G21 G90\nM6 T1\nG0 Z5\nG1 Z-1 F100\nM30\n");
        run = cli({ u"--json"_s, u"job"_s, u"check"_s, QString::fromUtf8(job), u"--table"_s, table(),
            u"--library"_s, library(), u"--machine"_s, u"Mill"_s });
        const QJsonObject report = json(run);
        QVERIFY(std::fabs(report[u"tools"_s].toArray().first()[u"tlo"_s].toDouble() - t1) < 0.002);
        for (const QJsonValue &f : report[u"findings"_s].toArray())
            QVERIFY2(!f[u"message"_s].toString().contains(u"newer measurement"_s),
                qPrintable(f[u"message"_s].toString()));

        // Prepared for a manual change (no rack here): M6 T1 H takes the stored TLO in millimetres.
        const QString out = m_dir.filePath(u"prepared.nc"_s);
        run = cli({ u"job"_s, u"prepare"_s, QString::fromUtf8(job), u"--table"_s, table(),
            u"--use-stored-tlo"_s, u"--rack"_s, u"none"_s, u"-o"_s, out });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        // The file holds T1 to 0.0001 in (2.5 µm), so the H is T1's millimetres within that.
        const QByteArray prepared = readFile(out);
        const qsizetype at = prepared.indexOf("M6 T1 H");
        QVERIFY2(at >= 0, prepared.constData());
        const double h = prepared.mid(at + 7, prepared.indexOf(' ', at + 7) - at - 7).toDouble();
        QVERIFY2(std::fabs(h - t1) <= 0.0018, prepared.constData());
        QVERIFY2(
            prepared.contains(QByteArray("M493.3 Z" + QByteArray::number(h, 'f', 3))), prepared.constData());
    }

    void anInchTableAgainstGrblHal()
    {
        if (GrblHalPeer::script().isEmpty())
            QSKIP(qPrintable(GrblHalPeer::skipReason()));
        QTemporaryDir state;
        GrblHalPeer peer(state.path());
        QVERIFY2(useGrblHal(peer), qPrintable(peer.errors()));

        // The reference, then T2 against it: 15.3 mm on grblHAL, 0.6024 in in the file.
        QCOMPARE(machine({ u"select-tool"_s, u"1"_s }).exitCode, 0);
        QCOMPARE(machine({ u"probe"_s }).exitCode, 0);
        QCOMPARE(machine({ u"select-tool"_s, u"2"_s }).exitCode, 0);
        Run run = machine({ u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"tlo"_s].toDouble(), 15.3);
        QCOMPARE(tool(2)[u"measured_tlo"_s].toDouble(), 0.6024);
        QCOMPARE(tool(2)[u"reference_mz"_s].toDouble(), inches(-70.0));
        QCOMPARE(peer.tableZ(2), std::optional(15.3));
        QCOMPARE(lastEvent(2)[u"tlo"_s].toDouble(), 15.3);

        // The break test: intact against the stored 0.6024 in (15.301 mm).
        run = machine({ u"break-test"_s });
        QVERIFY2(run.exitCode == 0, run.out.constData());
        QCOMPARE(json(run)[u"broken"_s].toBool(), false);

        // Push: what someone set behind Toffee's back goes back to 15.3 mm, not 25.4 times that.
        QVERIFY(peer.ask("G10 L1 P2 Z7").contains("ok"));
        run = machine({ u"push-offsets"_s });
        QVERIFY2(run.exitCode == 0, run.out.constData());
        QVERIFY(std::fabs(*peer.tableZ(2) - 15.3) < 0.002);
        QVERIFY(peer.ask("$#").join('\n').contains("[T:2|0.000,0.000,15.30"));

        // Pull: 25.4 mm set on grblHAL is 1 in in the file, and 25.4 mm in the history.
        QVERIFY(peer.ask("G10 L1 P3 Z25.4").contains("ok"));
        run = machine({ u"pull-offsets"_s });
        QVERIFY2(run.exitCode == 0, run.out.constData());
        QCOMPARE(tool(3)[u"measured_tlo"_s].toDouble(), 1.0);
        QCOMPARE(lastEvent(3)[u"tlo"_s].toDouble(), 25.4);
        QCOMPARE(lastEvent(3)[u"kind"_s].toString(), u"import"_s); // read in from the controller's table

        // Set by hand and restored: millimetres to grblHAL, inches in the file.
        run = machine({ u"set-tlo"_s, u"--z"_s, u"12.7"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(tool(2)[u"measured_tlo"_s].toDouble(), 0.5);
        QCOMPARE(peer.tableZ(2), std::optional(12.7));
        QCOMPARE(machine({ u"probe"_s }).exitCode, 0); // back to the measured 15.3
        QCOMPARE(machine({ u"select-tool"_s, u"1"_s }).exitCode, 0);
        run = machine({ u"restore"_s, u"2"_s });
        QVERIFY2(run.exitCode == 0, run.out.constData());
        QVERIFY2(peer.ask("$#").join('\n').contains("[TLO:0.000,0.000,15.30"),
            peer.ask("$#").join('\n').constData());

        // The job check as grblHAL's: T2's TLO the history's millimetres, no "newer measurement", no units
        // mismatch for a controller that measures its TLOs; prepared with G43 H after the change.
        const QByteArray job = program(u"grbl.nc"_s, "G21 G90\nM6 T2\nG0 Z5\nG1 Z-1 F100\nM30\n");
        run = cli({ u"--json"_s, u"job"_s, u"check"_s, QString::fromUtf8(job), u"--dialect"_s, u"grblhal"_s,
            u"--table"_s, table(), u"--library"_s, library(), u"--machine"_s, u"Mill"_s });
        const QJsonObject report = json(run);
        QVERIFY2(std::fabs(report[u"tools"_s].toArray().first()[u"tlo"_s].toDouble() - 15.3) < 0.002,
            run.out.constData());
        for (const QJsonValue &f : report[u"findings"_s].toArray()) {
            const QString message = f[u"message"_s].toString();
            QVERIFY2(!message.contains(u"newer measurement"_s) && !message.contains(u"inches"_s),
                qPrintable(message));
        }
        const QString out = m_dir.filePath(u"grbl-prepared.nc"_s);
        run = cli({ u"job"_s, u"prepare"_s, QString::fromUtf8(job), u"--dialect"_s, u"grblhal"_s,
            u"--table"_s, table(), u"-o"_s, out });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(readFile(out).contains("G43 H2"), readFile(out).constData());
    }

    // The reverse: a millimetre table, and grblHAL set to take inches (G20): nothing is written, by name.
    void grblHalInInchesIsRefusedBeforeAnythingIsWritten()
    {
        if (GrblHalPeer::script().isEmpty())
            QSKIP(qPrintable(GrblHalPeer::skipReason()));
        QTemporaryDir state;
        GrblHalPeer peer(state.path());
        QVERIFY2(useGrblHal(peer), qPrintable(peer.errors()));
        const QString mmTable = m_dir.filePath(u"mm.json"_s);
        QVERIFY(writeTable(mmTable, "mm",
            R"({"number": 2, "pocket": 2, "measured_tlo": 15.3, "measured_at": "2026-11-21T08:00:00Z", "reference_mz": -70})"));
        QVERIFY(peer.ask("M61 Q2").contains("ok"));
        QVERIFY(peer.ask("G20").contains("ok"));
        const QByteArray before = peer.ask("$#").join('\n');
        for (const QStringList &command : { QStringList { u"probe"_s },
                 QStringList { u"set-tlo"_s, u"--z"_s, u"12.7"_s }, QStringList { u"push-offsets"_s } }) {
            const Run run = machine(command, mmTable);
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(json(run)[u"error"_s].toString().contains(u"grblHAL is in inches (G20)"_s),
                run.out.constData());
            QVERIFY2(json(run)[u"error"_s].toString().contains(u"Nothing was sent"_s), run.out.constData());
        }
        QCOMPARE(peer.ask("$#").join('\n'), before);
        QVERIFY(peer.ask("$G").value(0).contains(" G20 ")); // left as the operator set it

        // Reporting in inches ($13=1): refused on connecting, before a number is taken for millimetres.
        QVERIFY(peer.ask("G21").contains("ok"));
        QVERIFY(peer.ask("$13=1").contains("ok"));
        const Run run = machine({ u"status"_s }, mmTable);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(json(run)[u"error"_s].toString().contains(u"grblHAL reports in inches ($13=1)"_s),
            run.out.constData());
    }
};

QTEST_GUILESS_MAIN(TestUnitMatrix)
#include "tst_unitmatrix.moc"
