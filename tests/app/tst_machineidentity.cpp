// SPDX-License-Identifier: GPL-3.0-or-later
// A machine is an identity, not a name typed once: toffee-cli against grblHAL itself and the built-in emulator
// sharing one history library. Unnamed, each machine is called after its kind and is new the first time; a
// reference measured on one is never applied to the other (once, the emulator's probe handed its reference to
// grblHAL, which then wrote a TLO 45 mm off); a name bound to one machine refuses another with nothing sent
// but the questions that tell the controller, and nothing recorded; status --json names the machine and its
// identity.
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

const QString kSetter = u"0,0,-120,3000,300"_s;

} // namespace

class TestMachineIdentity : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    QString library() const { return m_dir.filePath(u"library.sqlite"_s); }
    int events(const QString &machine) const
    {
        const Run run = cli({ u"--json"_s, u"--library"_s, library(), u"history"_s, u"--machine"_s, machine });
        return int(QJsonDocument::fromJson(run.out).object()[u"events"_s].toArray().size());
    }

private Q_SLOTS:
    void initTestCase()
    {
        if (GrblHalPeer::script().isEmpty())
            QSKIP(qPrintable(GrblHalPeer::skipReason()));
        qputenv("XDG_DATA_HOME", m_dir.filePath(u"data"_s).toLocal8Bit());
    }

    void twoMachinesShareALibraryAndKeepTheirOwnReference()
    {
        GrblHalPeer peer;
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        QVERIFY(peer.writeSetter(-100.0, { { 1, 30.0 }, { 2, 45.3 } }));
        const QStringList grbl = QStringList { u"--json"_s, u"--library"_s, library(), u"--setter"_s, kSetter }
            + peer.cliTarget();
        const QString identity = u"grblhal:127.0.0.1:%1"_s.arg(peer.port());

        // grblHAL, unnamed: "grblHAL", new to the library; its first probe is its reference.
        Run run = cli(grbl + QStringList { u"select-tool"_s, u"1"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        run = cli(grbl + QStringList { u"probe"_s }, 90000);
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(run.err.contains("\"grblHAL\" is grblHAL at 127.0.0.1:") && run.err.contains("new to the library")
                && run.err.contains("becomes its reference"),
            run.err.constData());
        QCOMPARE(json(run)[u"tlo"_s].toDouble(), 0.0);
        QCOMPARE(json(run)[u"reference_mz"_s].toDouble(), -70.0);

        // The built-in emulator, unnamed, with the same library: its own machine, "Emulator", new.
        run = cli({ u"--json"_s, u"--library"_s, library(), u"--emulator"_s, u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(run.err.contains("\"Emulator\" is the built-in emulator, new to the library"), run.err.constData());
        QCOMPARE(json(run)[u"reference_mz"_s].toDouble(), -115.34);
        QCOMPARE(events(u"Emulator"_s), 1);
        QCOMPARE(events(u"grblHAL"_s), 1);

        // grblHAL again: its own reference (−70), not the emulator's (−115.340, which made T2 45.340 once).
        run = cli(grbl + QStringList { u"status"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QCOMPARE(json(run)[u"machine"_s].toString(), u"grblHAL"_s);
        QCOMPARE(json(run)[u"identity"_s].toString(), identity);
        QCOMPARE(json(run)[u"controller"_s].toString(), u"grblhal"_s);
        QVERIFY(!run.err.contains("new to the library"));
        run = cli(grbl + QStringList { u"select-tool"_s, u"2"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        run = cli(grbl + QStringList { u"probe"_s }, 90000);
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(!run.err.contains("new to the library"), run.err.constData());
        QCOMPARE(json(run)[u"reference_mz"_s].toDouble(), -70.0);
        QCOMPARE(json(run)[u"tlo"_s].toDouble(), 15.3);
        QCOMPARE(peer.tableZ(2), std::optional(15.3));
        QCOMPARE(events(u"grblHAL"_s), 2);

        // A name bound to the emulator refuses grblHAL: nothing recorded, grblHAL's table as it was.
        run = cli({ u"--json"_s, u"--library"_s, library(), u"--machine"_s, u"Shop"_s, u"--emulator"_s,
            u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        run = cli(grbl + QStringList { u"--machine"_s, u"Shop"_s, u"select-tool"_s, u"1"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData()); // it records nothing: no library asked
        run = cli(grbl + QStringList { u"--machine"_s, u"Shop"_s, u"probe"_s }, 90000);
        QCOMPARE(run.exitCode, 2);
        const QString said = json(run)[u"error"_s].toString();
        QVERIFY2(said.contains(u"The library's machine \"Shop\" is the built-in emulator; this is grblHAL at "
                               "127.0.0.1:%1"_s.arg(peer.port()))
                && said.contains(u"--machine NAME"_s) && said.contains(u"--same-machine"_s),
            qPrintable(said));
        QCOMPARE(events(u"Shop"_s), 1);
        QCOMPARE(peer.tableZ(1), std::optional(0.0));
        QCOMPARE(peer.tableZ(2), std::optional(15.3));
    }

    // A Carvera keeps its reference itself: the same name on another port (a USB device that came back as
    // another) follows it, and says so; nothing is refused.
    void aCarveraOnAnotherPortFollowsItsName()
    {
        for (const QString &tty : { u"first"_s, u"second"_s }) {
            Emulator carvera(m_dir.filePath(tty), {});
            QVERIFY(carvera.started());
            const Run run = cli({ u"--json"_s, u"--library"_s, library(), u"--machine"_s, u"C1"_s, u"--port"_s,
                m_dir.filePath(tty), u"probe"_s });
            QVERIFY2(run.exitCode == 0, run.err.constData());
            if (tty == u"first")
                QVERIFY2(run.err.contains("new to the library"), run.err.constData());
            else
                QVERIFY2(QString::fromUtf8(run.err).contains(u"\"C1\" was the Carvera at %1 before; now it is the "
                                                             "Carvera at %2"_s.arg(m_dir.filePath(u"first"_s),
                                                                 m_dir.filePath(u"second"_s))),
                    run.err.constData());
        }
        QCOMPARE(events(u"C1"_s), 2);
    }
};

QTEST_GUILESS_MAIN(TestMachineIdentity)
#include "tst_machineidentity.moc"
