// SPDX-License-Identifier: GPL-3.0-or-later
// The fault matrix's library column: toffee-cli measures on a machine (toffee-emulator on a pty) while the
// history library is busy, locked, tampered with or damaged — a real SQLite file locked by this process, a
// real PostgreSQL server (PgCluster) with a second connection holding a row lock. Each time: the command ends
// within its limit, the table file has the measurement, the measurement is kept on this computer and said so,
// and it reaches the library exactly once when the fault is gone. Tampered rows and versions:
// tst_librarytampering; what both share: tests/app/libraryfaultsfixture.h.
#include <csignal>

#include <QDir>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>

#include "tests/app/libraryfaultsfixture.h"

using namespace Toffee::Test;
using namespace Qt::StringLiterals;

class TestLibraryFaults : public QObject, public LibraryFaultsFixture
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { setUpCase(); }

    void init() { setUpEach(); }

    // The history library (SQLite) is locked by another program while the machine measures: the probe ends
    // at its limit with the measurement in the table and kept on this computer, and it is written once.
    void aProbeIntoALockedSqliteLibraryIsKeptAndSentOnce()
    {
        QCOMPARE(events(m_sqlite, u"Carvera"_s), 0); // creates the library
        Emulator emulator(m_dir.filePath(u"tty-a"_s), { u"--probe-ms"_s, u"1500"_s });
        QVERIFY(emulator.started());
        QProcess probe;
        probe.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"),
            { u"--json"_s, u"--library"_s, m_sqlite, u"--table"_s, m_table, u"--timeout"_s, u"2"_s,
                u"--port"_s, m_dir.filePath(u"tty-a"_s), u"probe"_s });
        QTest::qWait(700); // the library is open, the tool is on its way to the setter
        Connection lock(u"QSQLITE"_s);
        lock.db().setDatabaseName(m_sqlite);
        QVERIFY(lock.db().open());
        QVERIFY(lock.exec(u"BEGIN EXCLUSIVE"_s));
        QVERIFY(probe.waitForFinished(30000));
        const QString err = QString::fromUtf8(probe.readAllStandardError());
        QCOMPARE(probe.exitCode(), 0); // the machine measured: the probe itself succeeded
        QVERIFY2(err.contains(u"was busy"_s) && err.contains(u"is kept on this computer"_s), qPrintable(err));
        QCOMPARE(lastJson(probe.readAllStandardOutput()).value(u"history"_s).toString(), u"kept"_s);
        QVERIFY(tableTool(1).contains(u"measured_tlo"_s));
        QCOMPARE(spooled().size(), 1);
        QVERIFY(lock.exec(u"ROLLBACK"_s));
        QByteArray said;
        QCOMPARE(events(m_sqlite, u"Carvera"_s, &said), 1);
        QVERIFY2(said.contains("sent 1 measurement"), said.constData());
        QCOMPARE(spooled().size(), 0);
        QCOMPARE(events(m_sqlite, u"Carvera"_s, &said), 1); // once
        QVERIFY(!said.contains("sent"));
    }

    // The matrix: every command that records, against every way the library can fail it. Each ends within its
    // limit, with the measurements in the table file; whatever the library could not take is kept on this
    // computer, said so, and reaches the library exactly once when the fault is gone (a tampered row: once
    // it is mended). A library damaged before the command is refused before the machine moves.
    void everyRecordingCommandAgainstEveryLibraryFault_data()
    {
        QTest::addColumn<QStringList>("command");
        QTest::addColumn<int>("recorded");
        QTest::addColumn<QString>("fault");
        const QList<std::pair<QStringList, int>> commands {
            { { u"probe"_s }, 1 },
            { { u"set-tlo"_s, u"--z"_s, u"42.5"_s }, 1 },
            { { u"break-test"_s, u"--tolerance"_s, u"0.1"_s }, 1 },
            { { u"measure-rack"_s }, 6 },
            { { u"check-rack"_s, u"--tolerance"_s, u"0.1"_s }, 6 },
        };
        for (const QString &fault : { u"SQLite locked"_s, u"PostgreSQL rows locked"_s,
                 u"PostgreSQL row tampered"_s, u"SQLite events table gone"_s }) {
            for (const auto &[command, recorded] : commands)
                QTest::addRow("%s, %s", qPrintable(command.first()), qPrintable(fault))
                    << command << recorded << fault;
        }
    }
    void everyRecordingCommandAgainstEveryLibraryFault()
    {
        QFETCH(QStringList, command);
        QFETCH(int, recorded);
        QFETCH(QString, fault);
        const bool shared = fault.startsWith(u"PostgreSQL"_s);
        const QString library = shared ? pgUrl() : m_sqlite;
        const QString machine = shared ? u"M%1"_s.arg(m_case) : u"Carvera"_s;
        if (shared) {
            const Run put = cli({ u"--library"_s, library, u"library"_s, u"put"_s, u"--machine"_s, machine,
                QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json") });
            QVERIFY2(put.exitCode == 0, put.err.constData());
        }
        const QStringList base { u"--json"_s, u"--library"_s, library, u"--machine"_s, machine, u"--table"_s,
            m_table, u"--timeout"_s, u"1"_s, u"--emulator"_s };
        if (command.first() == u"check-rack") { // a check needs the rack measured first, fault-free
            const Run measured = cli(base + QStringList { u"measure-rack"_s });
            QVERIFY2(measured.exitCode == 0, measured.err.constData());
        }
        const int before = events(library, machine);
        QVERIFY(before >= 0);
        const QByteArray tableBefore = readFile(m_table);

        Connection other(shared ? u"QPSQL"_s : u"QSQLITE"_s);
        if (shared)
            QVERIFY(openPg(other));
        else {
            other.db().setDatabaseName(m_sqlite);
            QVERIFY(other.db().open());
        }
        const QString rows = u"machine = '%1'"_s.arg(machine);
        if (fault == u"SQLite locked") {
            QVERIFY(other.exec(u"BEGIN EXCLUSIVE"_s));
        } else if (fault == u"PostgreSQL rows locked") {
            QVERIFY(other.exec(u"BEGIN"_s));
            QVERIFY(other.exec(u"SELECT * FROM tools WHERE %1 FOR UPDATE"_s.arg(rows)));
        } else if (fault == u"PostgreSQL row tampered") { // T1's row holds T2's data
            QVERIFY(other.exec(u"UPDATE tools SET data = (SELECT data FROM tools WHERE %1 AND number = 2) "
                               "WHERE %1 AND number = 1"_s.arg(rows)));
        } else {
            QVERIFY(other.exec(u"DROP TABLE events"_s));
        }

        QElapsedTimer clock;
        clock.start();
        const Run run = cli(base + command);
        const qint64 took = clock.elapsed();
        QVERIFY2(took < 20000, qPrintable(QString::number(took)));

        if (fault == u"SQLite events table gone") { // refused by name before the machine moved
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(run.err.contains("its table \"events\" is missing")
                    && run.err.contains("Nothing was sent to the machine"),
                run.err.constData());
            QCOMPARE(readFile(m_table), tableBefore);
            QCOMPARE(spooled().size(), 0);
            return;
        }
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(run.err.contains("is kept on this computer"), run.err.constData());
        if (command.first() != u"check-rack" && command.first() != u"break-test") // a pass changes no TLO
            QVERIFY(readFile(m_table) != tableBefore);
        QVERIFY(tableTool(1).contains(u"measured_tlo"_s));
        QVERIFY(!spooled().isEmpty());
        QCOMPARE(lastJson(run.out).value(u"history"_s).toString(u"kept"_s), u"kept"_s);

        // The fault goes: what was kept is sent, once.
        if (fault == u"PostgreSQL row tampered") {
            QByteArray said;
            // T1's row is named and its measurement still kept; the other tools' went in.
            const int meanwhile = events(library, machine, &said);
            QVERIFY(meanwhile >= before && meanwhile < before + recorded);
            QVERIFY2(said.contains("T1's row"), said.constData());
            QVERIFY(!spooled().isEmpty());
            QVERIFY(other.exec(u"UPDATE tools SET data = replace(data, '\"number\": 2', '\"number\": 1') "
                               "WHERE %1 AND number = 1"_s.arg(rows)));
        } else {
            QVERIFY(other.exec(u"ROLLBACK"_s));
        }
        QByteArray said;
        QCOMPARE(events(library, machine, &said), before + recorded);
        QVERIFY2(said.contains("sent "), said.constData());
        QCOMPARE(spooled().size(), 0);
        QCOMPARE(events(library, machine), before + recorded); // exactly once
    }

    // Reading the history takes no write lock: another program's long write does not stop it.
    void theHistoryIsReadWhileAnotherProgramWrites()
    {
        QCOMPARE(events(m_sqlite, u"Carvera"_s), 0);
        Connection lock(u"QSQLITE"_s);
        lock.db().setDatabaseName(m_sqlite);
        QVERIFY(lock.db().open());
        QVERIFY(lock.exec(u"BEGIN EXCLUSIVE"_s));
        QVERIFY(lock.exec(u"INSERT INTO machines (name) VALUES ('X')"_s));
        const Run run = cli({ u"--library"_s, m_sqlite, u"history"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY(!run.err.contains("cannot be written"));
        QVERIFY(lock.exec(u"ROLLBACK"_s));
    }

    // Another station holds the machine's tool rows (SELECT … FOR UPDATE) while this one probes: it waits
    // no longer than its --timeout, keeps the measurement, and writes it once the rows are free.
    void aProbeUnderAPostgresRowLockEndsWithinItsLimit_data()
    {
        QTest::addColumn<QStringList>("limit");
        QTest::addColumn<int>("seconds");
        QTest::newRow("--timeout 3") << QStringList { u"--timeout"_s, u"3"_s } << 3;
        QTest::newRow("no --timeout: 5 s") << QStringList {} << 5;
    }
    void aProbeUnderAPostgresRowLockEndsWithinItsLimit()
    {
        QFETCH(QStringList, limit);
        QFETCH(int, seconds);
        const int before = events(pgUrl(), u"C1"_s);
        Connection lock(u"QPSQL"_s);
        QVERIFY(openPg(lock));
        QVERIFY(lock.exec(u"BEGIN"_s));
        QVERIFY(lock.exec(u"SELECT * FROM tools WHERE machine = 'C1' FOR UPDATE"_s));
        QElapsedTimer clock;
        clock.start();
        const Run run = cli(QStringList { u"--json"_s, u"--library"_s, pgUrl(), u"--machine"_s, u"C1"_s,
                                u"--table"_s, m_table, u"--emulator"_s }
            + limit + QStringList { u"probe"_s });
        const qint64 took = clock.elapsed();
        QVERIFY2(run.exitCode == 0, run.err.constData());
        // It waited for the lock, and gave up at its limit (it waited forever before).
        QVERIFY2(took >= seconds * 1000 && took < (seconds + 10) * 1000, qPrintable(QString::number(took)));
        QVERIFY2(run.err.contains("was busy") && run.err.contains("is kept on this computer"),
            run.err.constData());
        QCOMPARE(lastJson(run.out).value(u"history"_s).toString(), u"kept"_s);
        const double tlo = lastJson(run.out).value(u"tlo"_s).toDouble();
        QCOMPARE(tableTool(1).value(u"measured_tlo"_s).toDouble(), tlo);
        QCOMPARE(spooled().size(), 1);
        QVERIFY(lock.exec(u"ROLLBACK"_s));
        QByteArray said;
        QCOMPARE(events(pgUrl(), u"C1"_s, &said), before + 1);
        QVERIFY2(said.contains("sent 1 measurement"), said.constData());
        QCOMPARE(events(pgUrl(), u"C1"_s), before + 1); // exactly once
        QCOMPARE(spooled().size(), 0);
    }

    // Ctrl-C while toffee-cli waits for the library: it stops at once, and what the machine measured is in
    // the table and kept on this computer, sent once later.
    void interruptedWhileWaitingForTheLibraryLosesNothing_data()
    {
        QTest::addColumn<int>("signal");
        QTest::newRow("SIGINT") << int(SIGINT);
        QTest::newRow("SIGTERM") << int(SIGTERM);
    }
    void interruptedWhileWaitingForTheLibraryLosesNothing()
    {
        QFETCH(int, signal);
        const int before = events(pgUrl(), u"C1"_s);
        Connection lock(u"QPSQL"_s);
        QVERIFY(openPg(lock));
        QVERIFY(lock.exec(u"BEGIN"_s));
        QVERIFY(lock.exec(u"SELECT * FROM tools WHERE machine = 'C1' FOR UPDATE"_s));
        QProcess probe;
        probe.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"),
            { u"--library"_s, pgUrl(), u"--machine"_s, u"C1"_s, u"--table"_s, m_table, u"--timeout"_s,
                u"120"_s, u"--emulator"_s, u"probe"_s });
        QVERIFY(probe.waitForStarted());
        // The measurement is kept before the library is asked: once it is there, toffee-cli is waiting.
        QTRY_COMPARE_WITH_TIMEOUT(spooled().size(), 1, 20000);
        QTest::qWait(300);
        QCOMPARE(probe.state(), QProcess::Running);
        ::kill(pid_t(probe.processId()), signal);
        QVERIFY(probe.waitForFinished(5000));
        QCOMPARE(probe.exitCode(), 128 + signal);
        QVERIFY(tableTool(1).contains(u"measured_tlo"_s));
        QCOMPARE(spooled().size(), 1);
        QVERIFY(lock.exec(u"ROLLBACK"_s));
        QCOMPARE(events(pgUrl(), u"C1"_s), before + 1);
        QCOMPARE(events(pgUrl(), u"C1"_s), before + 1);
    }

    // The events table is dropped under a running probe: the measurement is kept, and what is wrong with the
    // library is said in Toffee's words, not the driver's "Parameter count mismatch".
    void aProbeIntoALibraryWhoseEventsTableWentIsKept()
    {
        QCOMPARE(events(m_sqlite, u"Carvera"_s), 0);
        Emulator emulator(m_dir.filePath(u"tty-b"_s), { u"--probe-ms"_s, u"1500"_s });
        QVERIFY(emulator.started());
        QProcess probe;
        probe.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"),
            { u"--library"_s, m_sqlite, u"--table"_s, m_table, u"--port"_s, m_dir.filePath(u"tty-b"_s),
                u"probe"_s });
        QTest::qWait(700);
        {
            Connection tamper(u"QSQLITE"_s);
            tamper.db().setDatabaseName(m_sqlite);
            QVERIFY(tamper.db().open());
            QVERIFY(tamper.exec(u"DROP TABLE events"_s));
        }
        QVERIFY(probe.waitForFinished(30000));
        const QString err = QString::fromUtf8(probe.readAllStandardError());
        QCOMPARE(probe.exitCode(), 0);
        QVERIFY2(err.contains(u"is damaged: its table \"events\" is missing"_s), qPrintable(err));
        QVERIFY2(!err.contains(u"Parameter count"_s), qPrintable(err));
        QVERIFY(err.contains(u"is kept on this computer"_s));
        QVERIFY(tableTool(1).contains(u"measured_tlo"_s));
        QCOMPARE(spooled().size(), 1);
        // Opening it again says the same, and the measurement stays kept.
        const Run run = cli({ u"--library"_s, m_sqlite, u"history"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("its table \"events\" is missing"), run.err.constData());
        QCOMPARE(spooled().size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestLibraryFaults)
#include "tst_libraryfaults.moc"
