// SPDX-License-Identifier: GPL-3.0-or-later
// The operator is present, or nothing moves: a manual tool change waits for a person, so toffee-cli refuses
// it before anything is sent when its input is not a terminal (cron, ssh -n, a pipe, </dev/null), and at a
// terminal it says how long it waits; a terminal that closes, the time limit (--timeout) and Ctrl-C end the
// change on the machine, and nothing is measured or recorded. On grblHAL itself (TOFFEE_GRBLHAL_PEER) and the
// Carvera's firmware (TOFFEE_CARVERA_PEER); each case skips, and says so, without its peer.
#include <csignal>

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include "tests/support/carverapeer.h"
#include "tests/support/grblhalpeer.h"
#include "tests/support/processes.h"

using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

QJsonObject json(const QByteArray &out)
{
    return QJsonDocument::fromJson(out.trimmed().split('\n').last()).object();
}

// The setter at machine Z −100 and the fast feeds the peer's settings allow.
const QString kSetter = u"0,0,-120,3000,300"_s;

// How the person's absence ends a waiting change.
enum class Ending { HangUp, TimeLimit, CtrlC };

// toffee-cli started at a terminal nobody types on, until it says it waits for the person; then ended as
// `ending` says.
struct Attended
{
    int exitCode = -1;
    QByteArray out;
    QByteArray err;
    qint64 waitedMs = 0; // from "put T… in" to its end
};

Attended attend(const QStringList &arguments, Ending ending)
{
    Terminal terminal;
    QProcess process;
    terminal.attach(process);
    process.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"), arguments);
    Attended result;
    if (!process.waitForStarted())
        return result;
    QElapsedTimer clock;
    clock.start();
    while (!result.err.contains("Ctrl-C or end of input ends the change") && clock.elapsed() < 60000
        && process.state() == QProcess::Running) {
        process.waitForReadyRead(100);
        result.err += process.readAllStandardError();
    }
    QElapsedTimer waited;
    waited.start();
    if (ending == Ending::HangUp)
        terminal.hangUp();
    else if (ending == Ending::CtrlC)
        ::kill(pid_t(process.processId()), SIGINT);
    if (!process.waitForFinished(60000))
        process.kill();
    result.waitedMs = waited.elapsed();
    result.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    result.out = process.readAllStandardOutput();
    result.err += process.readAllStandardError();
    return result;
}

} // namespace

class TestOperatorPresence : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    QString table() const { return m_dir.filePath(u"tools.json"_s); }
    QString library() const { return m_dir.filePath(u"library.sqlite"_s); }
    QStringList grblHal(const GrblHalPeer &peer, const QStringList &more) const
    {
        return QStringList { u"--json"_s, u"--library"_s, library(), u"--machine"_s, u"LongMill"_s,
            u"--controller"_s, u"grblhal"_s, u"--setter"_s, kSetter, u"--table"_s, table() }
        + peer.cliTarget() + more;
    }
    QStringList carvera(const CarveraPeer &peer, const QStringList &more) const
    {
        return QStringList { u"--json"_s, u"--library"_s, library(), u"--table"_s, table(), u"--port"_s,
            peer.uart() }
        + more;
    }
    int historyCount() const
    {
        const Run run = cli({ u"--json"_s, u"--library"_s, library(), u"history"_s });
        return int(QJsonDocument::fromJson(run.out).object()[u"events"_s].toArray().size());
    }
    bool freshTable() const
    {
        QFile::remove(table());
        return QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), table())
            && QFile(table()).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
    }

    // grblHAL with its setter at machine Z -100, T1 (30 mm) in the spindle and T2 (45.3 mm) to come, and the
    // example table fresh. Each story's grblHAL is the same machine, LongMill, which it calls itself ($I=):
    // Toffee knows it again on whatever port it answers.
    bool startWithT1(GrblHalPeer &peer)
    {
        return peer.started() && peer.writeSetter(-100.0, { { 1, 30.0 }, { 2, 45.3 } }) && freshTable()
            && peer.ask("$I=LongMill").contains("ok") && peer.ask("M61 Q1").contains("ok");
    }

private Q_SLOTS:
    void initTestCase() { qputenv("XDG_DATA_HOME", m_dir.filePath(u"data"_s).toLocal8Bit()); }

    void grblHalRefusesAChangeFromAScriptBeforeSendingIt()
    {
        if (GrblHalPeer::script().isEmpty())
            QSKIP(qPrintable(GrblHalPeer::skipReason()));
        QTemporaryDir state;
        GrblHalPeer peer(state.path());
        QVERIFY2(startWithT1(peer), qPrintable(peer.errors()));
        const QByteArray file = readFile(table());
        const int events = historyCount();

        // </dev/null, as cron or ssh -n run it: end of input at once.
        const Run run = cli(grblHal(peer, { u"change-tool"_s, u"2"_s }), 60000);
        QCOMPARE(run.exitCode, 2);
        const QString error = json(run.out)[u"error"_s].toString();
        QVERIFY2(error.startsWith(u"T2 is put in by hand (grblHAL's manual tool change) on this machine"_s),
            qPrintable(error));
        QVERIFY2(
            error.contains(u"not a terminal"_s) && error.contains(u"Nothing was sent"_s), qPrintable(error));
        // No M6 reached grblHAL: T1 is its tool, it is idle, and nothing was measured or written.
        const QList<QByteArray> modal = peer.ask("$G");
        QVERIFY(!modal.isEmpty() && modal.first().contains(" T1 "));
        QVERIFY2(peer.status().startsWith("<Idle|"), peer.status().constData());
        QCOMPARE(readFile(table()), file);
        QCOMPARE(historyCount(), events);
    }

    void grblHalEndsAWaitingChangeWhenNobodyAnswers_data()
    {
        QTest::addColumn<Ending>("ending");
        QTest::addColumn<QStringList>("options");
        QTest::addColumn<QString>("why");
        QTest::newRow("the terminal closes") << Ending::HangUp << QStringList {} << u"The terminal closed"_s;
        QTest::newRow("--timeout 3") << Ending::TimeLimit << QStringList { u"--timeout"_s, u"3"_s }
                                     << u"Nobody put T2 in within the 3 s the change waits."_s;
        QTest::newRow("Ctrl-C") << Ending::CtrlC << QStringList {} << u"Ctrl-C ended the wait."_s;
    }

    void grblHalEndsAWaitingChangeWhenNobodyAnswers()
    {
        QFETCH(Ending, ending);
        QFETCH(QStringList, options);
        QFETCH(QString, why);
        if (GrblHalPeer::script().isEmpty())
            QSKIP(qPrintable(GrblHalPeer::skipReason()));
        QTemporaryDir state;
        GrblHalPeer peer(state.path());
        QVERIFY2(startWithT1(peer), qPrintable(peer.errors()));
        const QByteArray file = readFile(table());
        const int events = historyCount();

        const Attended run
            = attend(grblHal(peer, options + QStringList { u"change-tool"_s, u"2"_s }), ending);
        QVERIFY2(
            run.err.contains("toffee-cli: put T2 in the spindle, then press the machine's cycle start, or "
                             "Enter here. Waiting up to "),
            run.err.constData());
        QVERIFY2(run.err.contains(ending == Ending::TimeLimit ? "Waiting up to 3 s" : "Waiting up to 600 s"),
            run.err.constData());
        QVERIFY2(run.exitCode == 4, QByteArray(run.out + run.err).constData());
        const QString error = json(run.out)[u"error"_s].toString();
        QVERIFY2(error.startsWith(why), qPrintable(error));
        QVERIFY2(
            error.contains(u"The change to T2 was ended: nothing was measured or recorded. grblHAL was reset "
                           "to end it: its tool is still T1"_s),
            qPrintable(error));
        QVERIFY2(run.waitedMs < 30000, qPrintable(QString::number(run.waitedMs))); // not the 600 s
        // grblHAL no longer waits: a reset ended its tool change, and it went on to nothing.
        QVERIFY2(peer.status().startsWith("<Idle|"), peer.status().constData());
        const QList<QByteArray> modal = peer.ask("$G");
        QVERIFY(!modal.isEmpty() && modal.first().contains(" T1 "));
        QVERIFY(peer.ask("$#").contains("[PRB:0.000,0.000,0.000:0]")); // never probed
        QCOMPARE(readFile(table()), file);
        QCOMPARE(historyCount(), events);
    }

    void theCarveraRefusesAChangeByHandFromAScriptBeforeSendingIt()
    {
        if (CarveraPeer::script().isEmpty())
            QSKIP(qPrintable(CarveraPeer::skipReason()));
        CarveraPeer peer;
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        QVERIFY(freshTable());
        const QByteArray file = readFile(table());
        const int events = historyCount();

        const Run run = cli(carvera(peer, { u"change-tool"_s, u"8"_s }), 60000);
        QCOMPARE(run.exitCode, 2);
        const QString error = json(run.out)[u"error"_s].toString();
        QVERIFY2(error.startsWith(u"T8 is put in by hand on this machine"_s), qPrintable(error));
        QVERIFY2(error.contains(u"Nothing was sent"_s), qPrintable(error));
        // The machine never went to its change position: idle where it started, the spindle empty.
        const Run status = cli(carvera(peer, { u"status"_s }), 60000);
        QCOMPARE(json(status.out)[u"state"_s].toString(), u"Idle"_s);
        QCOMPARE(json(status.out)[u"mpos"_s].toArray(), (QJsonArray { -2.0, -2.0, -2.0 }));
        QCOMPARE(json(status.out)[u"tool"_s].toInt(), -1);
        QCOMPARE(readFile(table()), file);
        QCOMPARE(historyCount(), events);
        // A rack tool's change needs nobody: it is sent (the peer's empty rack then halts it, as its README
        // says).
        const Run rack = cli(carvera(peer, { u"change-tool"_s, u"2"_s }), 90000);
        QVERIFY2(!json(rack.out)[u"error"_s].toString().contains(u"by hand"_s), rack.out.constData());
    }

    void theCarveraEndsAWaitingChangeWhenNobodyAnswers_data()
    {
        QTest::addColumn<Ending>("ending");
        QTest::addColumn<QStringList>("options");
        QTest::addColumn<QString>("why");
        QTest::newRow("the terminal closes") << Ending::HangUp << QStringList {} << u"The terminal closed"_s;
        QTest::newRow("--timeout 5") << Ending::TimeLimit << QStringList { u"--timeout"_s, u"5"_s }
                                     << u"Nobody put T8 in within the 5 s the change waits."_s;
    }

    void theCarveraEndsAWaitingChangeWhenNobodyAnswers()
    {
        QFETCH(Ending, ending);
        QFETCH(QStringList, options);
        QFETCH(QString, why);
        if (CarveraPeer::script().isEmpty())
            QSKIP(qPrintable(CarveraPeer::skipReason()));
        CarveraPeer peer;
        QVERIFY2(peer.started(), qPrintable(peer.errors()));
        QVERIFY(freshTable());
        const QByteArray file = readFile(table());
        const int events = historyCount();

        const Attended run
            = attend(carvera(peer, options + QStringList { u"change-tool"_s, u"8"_s }), ending);
        QVERIFY2(run.err.contains("toffee-cli: put T8 in the spindle, then press the machine's button."),
            run.err.constData());
        QVERIFY2(run.exitCode == 4, QByteArray(run.out + run.err).constData());
        const QString error = json(run.out)[u"error"_s].toString();
        QVERIFY2(error.startsWith(why), qPrintable(error));
        QVERIFY2(error.contains(u"The machine halted to end it"_s), qPrintable(error));
        QVERIFY2(run.waitedMs < 30000, qPrintable(QString::number(run.waitedMs)));
        // The firmware no longer waits for its button: Ctrl-X halted it (reason 1), T8 never measured.
        const Run status = cli(carvera(peer, { u"status"_s }), 60000);
        QCOMPARE(json(status.out)[u"state"_s].toString(), u"Alarm"_s);
        QCOMPARE(json(status.out)[u"halt_reason"_s].toInt(), 1);
        QCOMPARE(readFile(table()), file);
        QCOMPARE(historyCount(), events);
    }
};

QTEST_GUILESS_MAIN(TestOperatorPresence)
#include "tst_operatorpresence.moc"
