// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli against LinuxCNC itself (TOFFEE_LINUXCNC_PEER: Debian's LinuxCNC run headless, with a simulated
// tool setter), as a script runs it: found by asking; status names LinuxCNC and its version; refused before
// it is ready; two tools probed, the second against the reference kept in the history; a break test that
// finds a worn tool (exit 3, nothing adopted); push refused for a tool LinuxCNC lacks and then written; pull
// from the file LinuxCNC rewrote; a change with nobody at the terminal refused; stop. The table file, the
// history and LinuxCNC's tool.tbl are checked at each step.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/support/linuxcncpeer.h"
#include "tests/support/processes.h"

using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

QJsonObject json(const Run &run)
{
    return QJsonDocument::fromJson(run.out.trimmed().split('\n').last()).object();
}

// The latch slow enough that the contact is latched within 0.001 mm (LinuxCNC samples the probe each 1 ms
// servo period: 30 mm/min moves 0.0005 mm in one).
const QString kSetter = u"10,10,-140,3000,30,0.5"_s;

} // namespace

class TestLinuxCncCli : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    std::unique_ptr<LinuxCncPeer> m_peer;

    QString table() const { return m_dir.filePath(u"tools.json"_s); }
    Run machine(const QStringList &arguments)
    {
        return cli(
            QStringList { u"--json"_s, u"--library"_s, m_dir.filePath(u"library.sqlite"_s), u"--machine"_s,
                u"Mill"_s, u"--setter"_s, kSetter, u"--table"_s, table(), u"--host"_s, m_peer->address() }
                + arguments,
            120000);
    }
    static bool writeFile(const QString &path, const QByteArray &bytes)
    {
        QFile file(path);
        return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(bytes) == bytes.size();
    }
    QJsonObject tool(int number) const
    {
        QFile file(table());
        if (!file.open(QIODevice::ReadOnly))
            return {};
        for (const QJsonValue &t : QJsonDocument::fromJson(file.readAll()).object()[u"tools"_s].toArray()) {
            if (t[u"number"_s].toInt() == number)
                return t.toObject();
        }
        return {};
    }

private Q_SLOTS:
    void initTestCase()
    {
        if (const QString why = LinuxCncPeer::skipReason(); !why.isEmpty())
            QSKIP(qPrintable(why));
        qputenv("XDG_DATA_HOME", m_dir.filePath(u"data"_s).toLocal8Bit());
        m_peer = std::make_unique<LinuxCncPeer>(std::map<int, double> { { 1, 30.0 }, { 2, 45.3 } });
        QVERIFY2(m_peer->started(), qPrintable(m_peer->errors()));
        QFile file(table());
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "toffee-tool-table", "version": 1, "units": "mm", "tools": []})");
    }

    void aScriptKeepsLinuxCncsTableMeasured()
    {
        // In estop, status still answers and names LinuxCNC; a probe is refused with what to do.
        Run run = machine({ u"status"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"identity"_s].toString(), u"linuxcnc:%1"_s.arg(m_peer->address()));
        QCOMPARE(json(run)[u"firmware"_s].toObject()[u"controller"_s].toString(), u"linuxcnc"_s);
        QCOMPARE(json(run)[u"state"_s].toString(), u"Estop"_s);
        run = machine({ u"probe"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("estop"), run.err.constData());

        QVERIFY(m_peer->makeReady());
        run = machine({ u"status"_s });
        QCOMPARE(json(run)[u"state"_s].toString(), u"Idle"_s);
        QVERIFY2(json(run)[u"firmware"_s].toObject()[u"version"_s].toString().startsWith(u"2."_s),
            run.out.constData());

        // T1 the reference; T2 15.3 mm longer, against the reference the history kept between runs.
        QCOMPARE(machine({ u"select-tool"_s, u"1"_s }).exitCode, 0);
        run = machine({ u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"tlo"_s].toDouble(), 0.0);
        QCOMPARE(json(run)[u"reference_mz"_s].toDouble(), -70.0);
        QCOMPARE(json(run)[u"history"_s].toString(), u"recorded"_s);
        QCOMPARE(machine({ u"select-tool"_s, u"2"_s }).exitCode, 0);
        run = machine({ u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"tlo"_s].toDouble(), 15.3);
        QCOMPARE(tool(2)[u"measured_tlo"_s].toDouble(), 15.3);
        QCOMPARE(m_peer->tableZ(2), std::optional(15.3));

        // Worn 0.4 mm: exit 3, the table, the history's stored TLO and LinuxCNC's own keep 15.3.
        QVERIFY(m_peer->setLength(2, 44.9));
        run = machine({ u"break-test"_s, u"--tolerance"_s, u"0.1"_s });
        QCOMPARE(run.exitCode, 3);
        QCOMPARE(tool(2)[u"measured_tlo"_s].toDouble(), 15.3);
        QCOMPARE(m_peer->tableZ(2), std::optional(15.3));
        QVERIFY(m_peer->setLength(2, 45.3));

        // A change needs someone at LinuxCNC's screen: with nobody at this terminal, refused, nothing sent.
        run = machine({ u"change-tool"_s, u"1"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("LinuxCNC's own screen"), run.err.constData());
        QCOMPARE(m_peer->get("tool"), QByteArray("2"));
    }

    void pushAndPullThroughTheToolTableFile()
    {
        // T7 is not in LinuxCNC's table: the whole push is refused by name and tool.tbl is untouched.
        const QByteArray measured = readFile(table());
        QVERIFY(writeFile(table(),
            QByteArray(measured).replace("\"tools\": [\n",
                "\"tools\": [\n    {\"number\": 7, \"measured_tlo\": 2.5, \"measured_at\": "
                "\"2026-11-20T08:00:00.000Z\"},\n")));
        QVERIFY(readFile(table()).contains("\"number\": 7"));
        const QByteArray before = m_peer->tableFile();
        Run run = machine({ u"push-offsets"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("T7") && run.err.contains("not in the controller's tool table"),
            run.err.constData());
        QCOMPARE(m_peer->tableFile(), before);
        QVERIFY(writeFile(table(), measured));

        // Someone sets T2 at LinuxCNC's screen: pull takes it from tool.tbl, named in the INI.
        QCOMPARE(m_peer->ask({ "set mdi G10 L1 P2 Z15.1" }), QList<QByteArray> { "SET MDI ACK" });
        run = machine({ u"--ini"_s, m_peer->ini(), u"--controller"_s, u"linuxcnc"_s, u"pull-offsets"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(tool(2)[u"measured_tlo"_s].toDouble(), 15.1);

        // T2 at 15.2 in the file: the push writes what differs and reads it back from tool.tbl.
        QVERIFY(writeFile(
            table(), readFile(table()).replace("\"measured_tlo\": 15.1", "\"measured_tlo\": 15.2")));
        run = machine({ u"push-offsets"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(m_peer->tableZ(2), std::optional(15.2));
        QCOMPARE(m_peer->tableZ(1), std::optional(0.0));
    }

    void stopEndsWhatRuns()
    {
        const Run run = machine({ u"stop"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(m_peer->get("program_status"), QByteArray("IDLE"));
    }
};

QTEST_GUILESS_MAIN(TestLinuxCncCli)
#include "tst_linuxcnccli.moc"
