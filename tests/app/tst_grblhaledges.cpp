// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli against grblHAL itself (TOFFEE_GRBLHAL_PEER), measuring like a machinist: a face mill's settings
// in the table (toffee-cli probing), its four edges touched off-centre (the peer's setter gives each approach
// the next edge's length), every touch and the spread in the JSON and the history, the spread beyond the
// tool's limit said by the probe, failed by the break test and warned by the job check, the setter's
// repeatability measured and kept, and one command's --touches and --offset over the table's.
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

// The setter at machine Z −100 and the fast feeds the peer's settings allow (a probe takes about 2 s).
const QString kSetter = u"0,0,-120,3000,300"_s;

QJsonObject toolIn(const QString &path, int number)
{
    for (const QJsonValue &t : QJsonDocument::fromJson(readFile(path)).object()[u"tools"_s].toArray()) {
        if (t[u"number"_s].toInt() == number)
            return t.toObject();
    }
    return {};
}

bool writeEmptyTable(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly)
        && file.write(R"({"format": "toffee-tool-table", "version": 1, "units": "mm", "tools": []})") > 0;
}

// The machine X grblHAL reports, from its status ("<Idle|MPos:20.000,0.000,0.000|…>").
double machineX(const GrblHalPeer &peer)
{
    const QByteArray status = peer.status();
    const qsizetype at = status.indexOf("MPos:");
    return at < 0 ? std::nan("") : status.mid(at + 5).split(',').value(0).toDouble();
}

} // namespace

class TestGrblHalEdges : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase()
    {
        if (GrblHalPeer::script().isEmpty())
            QSKIP(qPrintable(GrblHalPeer::skipReason()));
        qputenv("XDG_DATA_HOME", m_dir.filePath(u"data"_s).toLocal8Bit());
    }

    // A face mill's four edges, touched 20 mm off the setter's centre as its settings in the table say: the
    // peer's setter gives each approach the next edge's length (20, 20.03, 20.06, 20). Every touch printed
    // and kept in the history, the TLO from the longest edge, the spread beyond the tool's limit said; a
    // break test finds the chipped edge; one command's --touches and --offset override the table's.
    void aFaceMillIsTouchedOnEachEdgeOffCentre()
    {
        QTemporaryDir state;
        GrblHalPeer peer(state.path());
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        QVERIFY(peer.writeSetterText("setter -100\nT1 30\nT3 20 20.03 20.06 20\n"));
        const QString path = m_dir.filePath(u"facemill.json"_s);
        QVERIFY(writeEmptyTable(path));
        const QString library = m_dir.filePath(u"facemill.sqlite"_s);
        const auto run = [&](const QStringList &arguments) {
            return cli(QStringList { u"--json"_s, u"--library"_s, library, u"--machine"_s, u"Router"_s,
                           u"--setter"_s, kSetter, u"--table"_s, path }
                    + peer.cliTarget() + arguments,
                120000);
        };
        QCOMPARE(run({ u"select-tool"_s, u"1"_s }).exitCode, 0);
        Run r = run({ u"probe"_s });
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(json(r)[u"touches"_s].toArray().size(), 0); // one touch: no list, no spread
        QVERIFY(json(r)[u"spread"_s].isNull());
        QCOMPARE(run({ u"select-tool"_s, u"3"_s }).exitCode, 0);
        // Not in the table yet: refused by name, the file unchanged.
        Run settings = cli({ u"--json"_s, u"probing"_s, u"3"_s, u"--table"_s, path, u"--set"_s, u"X 20"_s });
        QCOMPARE(settings.exitCode, 2);
        QVERIFY2(settings.err.contains("T3 is not in"), settings.err.constData());

        // Added by hand, then its settings: four edges, 20 mm off centre, edges apart by 0.03 at most.
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(
            R"({"format": "toffee-tool-table", "version": 1, "units": "mm", "tools": [)"
            R"({"number": 1, "measured_tlo": 0, "reference_mz": -70}, {"number": 3, "description": "50 mm face mill"}]})");
        file.close();
        settings = cli({ u"--json"_s, u"probing"_s, u"3"_s, u"--table"_s, path, u"--set"_s,
            u"X 20, 4 edges, spread 0.03"_s });
        QVERIFY2(settings.exitCode == 0, settings.err.constData());
        QCOMPARE(json(settings)[u"touches"_s].toInt(), 4);
        QCOMPARE(json(settings)[u"offset_x_mm"_s].toDouble(), 20.0);
        QCOMPARE(toolIn(path, 3)[u"probe_x"_s].toDouble(), 20.0);
        QCOMPARE(toolIn(path, 3)[u"flutes"_s].toInt(), 4);

        r = run({ u"probe"_s });
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonArray touches = json(r)[u"touches"_s].toArray();
        QCOMPARE(touches.size(), 4);
        QList<double> zs;
        for (const QJsonValue &z : touches)
            zs << z.toDouble();
        QVERIFY2(std::fabs(zs[0] + 80.0) < 0.005 && std::fabs(zs[1] + 79.97) < 0.005
                && std::fabs(zs[2] + 79.94) < 0.005 && std::fabs(zs[3] + 80.0) < 0.005,
            r.out.constData());
        QVERIFY(std::fabs(json(r)[u"spread"_s].toDouble() - 0.06) < 0.005);
        // The TLO from the longest edge (the highest touch): −79.94 against the reference's −70.
        QCOMPARE(json(r)[u"current_mz"_s].toDouble(), zs[2]);
        QVERIFY(std::fabs(json(r)[u"tlo"_s].toDouble() - (zs[2] + 70.0)) < 1e-9);
        QCOMPARE(toolIn(path, 3)[u"measured_tlo"_s].toDouble(), json(r)[u"tlo"_s].toDouble());
        QCOMPARE(peer.tableZ(3), std::optional(json(r)[u"tlo"_s].toDouble()));
        QVERIFY2(
            r.err.contains("T3's edges differ by 0.06") && r.err.contains("chipped edge"), r.err.constData());
        QVERIFY2(r.err.contains("cannot turn its spindle"), r.err.constData());
        // Off centre: the spindle stands at X 20 over the setter's centre at 0.
        QVERIFY2(std::fabs(machineX(peer) - 20.0) < 0.01, peer.status().constData());
        // The history keeps each touch and the spread.
        const Run history = cli({ u"--json"_s, u"--library"_s, library, u"history"_s, u"--machine"_s,
            u"Router"_s, u"--tool"_s, u"3"_s });
        const QJsonArray events = QJsonDocument::fromJson(history.out).object()[u"events"_s].toArray();
        QCOMPARE(events.size(), 1);
        QCOMPARE(events[0][u"touches"_s].toArray().size(), 4);
        QVERIFY(std::fabs(events[0][u"spread"_s].toDouble() - 0.06) < 0.005);

        // The job check says it too, from the history, before the program runs.
        const QString program = m_dir.filePath(u"face.nc"_s);
        QFile nc(program);
        QVERIFY(nc.open(QIODevice::WriteOnly));
        nc.write("G21 G90\nM6 T3\nG43 H3\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X50\nM30\n");
        nc.close();
        const Run check = cli({ u"--json"_s, u"--library"_s, library, u"job"_s, u"check"_s, program,
            u"--table"_s, path, u"--machine"_s, u"Router"_s, u"--rack"_s, u"none"_s });
        QVERIFY2(
            check.out.contains("\"spread_exceeded\"") && check.out.contains("T3's edges differed by 0.06"),
            check.out.constData());

        // A break test touches every edge too: within the tolerance, but the edges' spread is a chipped edge.
        r = run({ u"break-test"_s });
        QCOMPARE(r.exitCode, 3);
        QCOMPARE(json(r)[u"touches"_s].toArray().size(), 4);
        QVERIFY2(r.err.contains("chipped edge"), r.err.constData());
        QCOMPARE(toolIn(path, 3)[u"break_test_failed"_s].toBool(), true);

        // The setter's own repeatability, with T1 (one length) touched three times on the same edge.
        QCOMPARE(run({ u"select-tool"_s, u"1"_s }).exitCode, 0);
        r = run({ u"measure-repeatability"_s, u"3"_s, u"--touches"_s, u"3"_s });
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("put T3 in"), r.err.constData());
        r = run({ u"measure-repeatability"_s, u"1"_s, u"--touches"_s, u"3"_s });
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(json(r)[u"touches"_s].toArray().size(), 3);
        QVERIFY(json(r)[u"spread"_s].toDouble() <= 0.004);
        QCOMPARE(json(r)[u"smallest_tolerance"_s].toDouble(), 0.02);
        QVERIFY2(json(r)[u"history"_s].toString() == u"recorded"_s, r.err.constData());
        QVERIFY2(!r.err.contains("cannot turn"), r.err.constData()); // the same edge was asked for
        QCOMPARE(run({ u"select-tool"_s, u"3"_s }).exitCode, 0);

        // This command's own: one touch at the centre.
        r = run({ u"probe"_s, u"--touches"_s, u"1"_s, u"--offset"_s, u"0,0"_s });
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(json(r)[u"touches"_s].toArray().size(), 0);
        QVERIFY2(std::fabs(machineX(peer)) < 0.01, peer.status().constData());
        r = run({ u"probe"_s, u"--touches"_s, u"40"_s });
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--touches"), r.err.constData());

        // A setter that repeats within 0.03 to 0.06 (T3's edges stand in for it): a break test finer than twice
        // that is said to be one that may find an intact tool broken.
        r = run({ u"measure-repeatability"_s, u"3"_s, u"--touches"_s, u"3"_s });
        QVERIFY2(r.exitCode == 0, r.err.constData());
        // Three touches of the four-edge cycle, from wherever the peer's cycle stands: 0.03 or 0.06 apart.
        const double spread = json(r)[u"spread"_s].toDouble();
        QVERIFY2(spread > 0.025 && spread < 0.065, r.out.constData());
        QVERIFY(std::fabs(json(r)[u"smallest_tolerance"_s].toDouble() - 2.0 * spread) < 0.0015);
        r = run({ u"break-test"_s, u"--tolerance"_s, u"0.05"_s, u"--touches"_s, u"1"_s });
        QVERIFY2(r.err.contains("may find an intact tool broken"), r.err.constData());
        r = run({ u"break-test"_s, u"--tolerance"_s, u"0.5"_s, u"--touches"_s, u"1"_s });
        QVERIFY2(!r.err.contains("may find an intact tool broken"), r.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestGrblHalEdges)
#include "tst_grblhaledges.moc"
