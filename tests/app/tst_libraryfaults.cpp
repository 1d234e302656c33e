// SPDX-License-Identifier: GPL-3.0-or-later
// The fault matrix's library column: toffee-cli measures on a machine (toffee-emulator on a pty) while the
// history library is busy, locked, tampered with or damaged — a real SQLite file locked by this process, a
// real PostgreSQL server (PgCluster) with a second connection holding a row lock. Each time: the command ends
// within its limit, the table file has the measurement, the measurement is kept on this computer and said so,
// and it reaches the library exactly once when the fault is gone. Tampered rows and versions are refused by
// name, never read into a wrong table, never crash.
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

#include "tests/support/pgcluster.h"
#include "tests/support/processes.h"

using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

QJsonObject lastJson(const QByteArray &out)
{
    return QJsonDocument::fromJson(out.trimmed().split('\n').last()).object();
}

// A connection of this process's own, to hold locks or tamper with rows as another program would.
class Connection
{
public:
    explicit Connection(const QString &driver)
        : m_name(u"tamper-"_s + QString::number(++s_count))
    {
        m_db = QSqlDatabase::addDatabase(driver, m_name);
    }
    ~Connection()
    {
        m_db.close();
        m_db = QSqlDatabase();
        QSqlDatabase::removeDatabase(m_name);
    }
    QSqlDatabase &db() { return m_db; }
    bool exec(const QString &sql)
    {
        QSqlQuery query(m_db);
        if (query.exec(sql))
            return true;
        qWarning() << sql << query.lastError().text();
        return false;
    }

private:
    static inline int s_count = 0;
    QString m_name;
    QSqlDatabase m_db;
};

} // namespace

class TestLibraryFaults : public QObject
{
    Q_OBJECT

    PgCluster m_cluster;
    QTemporaryDir m_dir;
    int m_case = 0;
    QString m_table; // this case's table file
    QString m_sqlite; // this case's SQLite library

    QString spoolFolder() const { return m_dir.filePath(u"data/Toffee/Toffee/outbox"_s); }
    // What waits in the outbox folder, for any library (each has a folder of its own there).
    QStringList spooled() const
    {
        QStringList files;
        const QDir outbox(spoolFolder());
        for (const QString &library : outbox.entryList({ u"library-*"_s }, QDir::Dirs))
            files += QDir(outbox.filePath(library)).entryList({ u"*.json"_s }, QDir::Files, QDir::Name);
        return files;
    }
    QString pgUrl() const { return m_cluster.url(u"shop"_s, u"tools"_s); }

    // The table's T1 as the file holds it.
    QJsonObject tableTool(int number) const
    {
        const QJsonArray tools
            = QJsonDocument::fromJson(readFile(m_table)).object().value(u"tools"_s).toArray();
        for (const QJsonValue &t : tools) {
            if (t.toObject().value(u"number"_s).toInt() == number)
                return t.toObject();
        }
        return {};
    }

    int events(const QString &library, const QString &machine, QByteArray *err = nullptr) const
    {
        const Run run = cli({ u"--json"_s, u"--library"_s, library, u"history"_s, u"--machine"_s, machine });
        if (err)
            *err = run.err;
        return run.exitCode == 0 ? int(lastJson(run.out).value(u"events"_s).toArray().size()) : -1;
    }

    bool openPg(Connection &c)
    {
        c.db().setHostName(m_cluster.socketDir());
        c.db().setPort(m_cluster.port());
        c.db().setUserName(PgCluster::adminUser());
        c.db().setDatabaseName(u"tools"_s);
        return c.db().open();
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QString error;
        QVERIFY2(m_cluster.start(&error), qPrintable(error));
        QVERIFY(m_cluster.createRole(u"shop"_s, u"Sh0p-pw"_s, true, &error));
        QVERIFY(m_cluster.createRole(u"viewer"_s, u"V1ew-pw"_s, true, &error));
        QVERIFY(m_cluster.createDatabase(u"tools"_s, u"shop"_s, &error));
        QVERIFY(m_cluster.writePassFile(m_dir.filePath(u"pgpass"_s),
            { { u"*"_s, u"shop"_s, u"Sh0p-pw"_s }, { u"*"_s, u"viewer"_s, u"V1ew-pw"_s } }, &error));
        qputenv("PGPASSFILE", m_dir.filePath(u"pgpass"_s).toLocal8Bit());
        // The children's own folder (their outbox, their standard library) is the test's, not the user's.
        qputenv("XDG_DATA_HOME", m_dir.filePath(u"data"_s).toLocal8Bit());
        const Run put = cli({ u"--library"_s, pgUrl(), u"library"_s, u"put"_s, u"--machine"_s, u"C1"_s,
            QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json") });
        QVERIFY2(put.exitCode == 0, put.err.constData());
    }

    void init()
    {
        ++m_case;
        m_table = m_dir.filePath(u"table%1.json"_s.arg(m_case));
        m_sqlite = m_dir.filePath(u"library%1.sqlite"_s.arg(m_case));
        QFile::remove(m_table);
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), m_table));
        QFile(m_table).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
        QDir(spoolFolder()).removeRecursively();
    }

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

    // A library whose schema version is not one Toffee writes is refused by name: no crash, no change.
    void aTamperedSchemaVersionIsRefused_data()
    {
        QTest::addColumn<QString>("version");
        QTest::addColumn<QString>("said");
        QTest::newRow("-1") << u"-1"_s << u"\"-1\""_s;
        QTest::newRow("2^63-1") << u"9223372036854775807"_s << u"\"9223372036854775807\""_s;
        QTest::newRow("2.5") << u"2.5"_s << u"\"2.5\""_s;
        QTest::newRow("text") << u"'two'"_s << u"\"two\""_s;
        QTest::newRow("no row") << QString() << u"is empty"_s;
    }
    void aTamperedSchemaVersionIsRefused()
    {
        QFETCH(QString, version);
        QFETCH(QString, said);
        QCOMPARE(events(m_sqlite, u"Carvera"_s), 0);
        {
            Connection tamper(u"QSQLITE"_s);
            tamper.db().setDatabaseName(m_sqlite);
            QVERIFY(tamper.db().open());
            QVERIFY(tamper.exec(u"DELETE FROM toffee_schema"_s));
            if (!version.isEmpty())
                QVERIFY(tamper.exec(u"INSERT INTO toffee_schema (version) VALUES (%1)"_s.arg(version)));
        }
        const QByteArray before = readFile(m_sqlite);
        const QByteArray table = readFile(m_table);
        for (const QStringList &command :
            { QStringList { u"history"_s }, QStringList { u"library"_s, u"tables"_s },
                QStringList { u"--emulator"_s, u"--table"_s, m_table, u"probe"_s } }) {
            const Run run = cli(QStringList { u"--library"_s, m_sqlite } + command);
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(run.err.contains("is damaged") && run.err.contains(said.toUtf8()), run.err.constData());
        }
        QCOMPARE(readFile(m_table), table); // nothing was sent to the machine
        QCOMPARE(readFile(m_sqlite), before);
    }

    // A row whose data is another tool's, or not a tool, is refused by name: `library get` writes nothing
    // over its output, and `library tables` still lists every other machine.
    void aTamperedRowIsRefusedByName_data()
    {
        QTest::addColumn<bool>("shared");
        QTest::addColumn<QString>("update");
        QTest::addColumn<QString>("said");
        for (const bool shared : { false, true }) {
            const char *where = shared ? "PostgreSQL: " : "SQLite: ";
            QTest::addRow("%sanother tool's data", where)
                << shared
                << u"UPDATE tools SET data = (SELECT data FROM tools WHERE machine = 'T' AND number = 3) "
                   u"WHERE "
                   "machine = 'T' AND number = 1"_s
                << u"T1's row: its data is T3's, not T1's"_s;
            QTest::addRow("%snot JSON", where)
                << shared << u"UPDATE tools SET data = 'abc' WHERE machine = 'T' AND number = 1"_s
                << u"T1's row:"_s;
            QTest::addRow("%sa tool twice in its data", where)
                << shared
                << u"UPDATE tools SET data = replace(data, '\"number\": 1,', '\"number\": 1, \"number\": "
                   u"7,') "
                   "WHERE machine = 'T' AND number = 1"_s
                << u"T1's row:"_s;
        }
        // Types PostgreSQL's columns would not take; SQLite's take anything.
        QTest::newRow("SQLite: a number out of range")
            << false << u"UPDATE tools SET number = 99999999999 WHERE machine = 'T' AND number = 2"_s
            << u"a row's tool number is 99999999999"_s;
        QTest::newRow("SQLite: a version that is text")
            << false << u"UPDATE tools SET version = 'x' WHERE machine = 'T' AND number = 1"_s
            << u"T1's row: its version is \"x\""_s;
        QTest::newRow("SQLite: a deleted mark of 2")
            << false << u"UPDATE tools SET deleted = 2 WHERE machine = 'T' AND number = 1"_s
            << u"T1's row: \"deleted\" is 2"_s;
        QTest::newRow("SQLite: units of neither")
            << false << u"UPDATE machine_tables SET units = 'furlongs' WHERE machine = 'T'"_s
            << u"its units are \"furlongs\""_s;
        QTest::newRow("PostgreSQL: 100 MB of data")
            << true << u"UPDATE tools SET data = repeat('x', 100000000) WHERE machine = 'T' AND number = 1"_s
            << u"T1's row: its data is 100000000 characters long"_s;
    }
    void aTamperedRowIsRefusedByName()
    {
        QFETCH(bool, shared);
        QFETCH(QString, update);
        QFETCH(QString, said);
        const QString library = shared ? pgUrl() : m_sqlite;
        const QString machine = u"T%1"_s.arg(m_case);
        for (const QString &name : QStringList { machine, machine + u"-after"_s }) {
            const Run put = cli({ u"--library"_s, library, u"library"_s, u"put"_s, u"--machine"_s, name,
                QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json") });
            QVERIFY2(put.exitCode == 0, put.err.constData());
        }
        {
            Connection tamper(shared ? u"QPSQL"_s : u"QSQLITE"_s);
            if (shared)
                QVERIFY(openPg(tamper));
            else {
                tamper.db().setDatabaseName(m_sqlite);
                QVERIFY(tamper.db().open());
                // As a program that does not care for the schema's checks would.
                QVERIFY(tamper.exec(u"PRAGMA ignore_check_constraints = ON"_s));
            }
            QVERIFY(tamper.exec(QString(update).replace(u"'T'"_s, u"'"_s + machine + u"'"_s)));
        }
        const QString out = m_dir.filePath(u"got%1.json"_s.arg(m_case));
        QFile file(out);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("the operator's file\n");
        file.close();
        MeasuredRun run = cliWithPeak(
            { u"--library"_s, library, u"library"_s, u"get"_s, u"--machine"_s, machine, u"-o"_s, out });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(said.toUtf8()), run.err.constData());
        QCOMPARE(readFile(out), QByteArray("the operator's file\n"));
        QVERIFY2(run.peakKb < 150 * 1024, qPrintable(QString::number(run.peakKb))); // the row is not fetched
        const Run tables = cli({ u"--json"_s, u"--library"_s, library, u"library"_s, u"tables"_s });
        QCOMPARE(tables.exitCode, 0);
        QStringList listed;
        for (const QJsonValue &t : lastJson(tables.out).value(u"tables"_s).toArray())
            listed << t.toObject().value(u"machine"_s).toString();
        QVERIFY2(listed.contains(machine) && listed.contains(machine + u"-after"_s), tables.out.constData());
        QVERIFY2(tables.err.contains(said.toUtf8()), tables.err.constData());
    }

    // Rows another program wrote into the history are named and left out; the rest is printed as it is.
    void hostileHistoryRowsAreNamedNotPrinted()
    {
        QCOMPARE(events(m_sqlite, u"Carvera"_s), 0);
        const Run probe = cli({ u"--library"_s, m_sqlite, u"--emulator"_s, u"probe"_s });
        QCOMPARE(probe.exitCode, 0);
        {
            Connection tamper(u"QSQLITE"_s);
            tamper.db().setDatabaseName(m_sqlite);
            QVERIFY(tamper.db().open());
            const QString insert
                = u"INSERT INTO events (id, machine, tool, measured_at, kind, tlo) VALUES "_s;
            QVERIFY(tamper.exec(
                insert + u"('huge', 'Carvera', 1, '2026-11-25T10:00:00.000Z', 'probe', 1e308)"_s));
            QVERIFY(
                tamper.exec(insert + u"('inf', 'Carvera', 1, '2026-11-25T10:00:01.000Z', 'probe', 9e999)"_s));
            QVERIFY(tamper.exec(
                insert + u"('text', 'Carvera', 1, '2026-11-25T10:00:02.000Z', 'probe', 'abc')"_s));
            QVERIFY(tamper.exec(
                insert + u"('tool', 'Carvera', 99999999999, '2026-11-25T10:00:03.000Z', 'probe', 1)"_s));
        }
        const Run run = cli({ u"--library"_s, m_sqlite, u"history"_s });
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains("1 event\n"), run.out.constData());
        for (const char *named : { "event huge: its tlo is 1e+308", "event inf: its tlo is",
                 "event text: its tlo is \"abc\"", "event tool: its tool is 99999999999" })
            QVERIFY2(run.err.contains(named), run.err.constData());
        QVERIFY(!run.out.contains("T1215752191"));
        QVERIFY(!run.out.contains("inf"));
    }

    // A role that may only read gets Toffee's words before the machine moves, not the driver's.
    void aReadOnlyRoleIsRefusedBeforeTheMachineMoves()
    {
        QString error;
        QVERIFY2(m_cluster.grantReadOnly(u"viewer"_s, u"tools"_s, &error), qPrintable(error));
        const QByteArray table = readFile(m_table);
        const Run run = cli({ u"--library"_s, m_cluster.url(u"viewer"_s, u"tools"_s), u"--machine"_s, u"C1"_s,
            u"--table"_s, m_table, u"--emulator"_s, u"probe"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(
            run.err.contains("read-only for viewer") && run.err.contains("Nothing was sent to the machine"),
            run.err.constData());
        QVERIFY(!run.err.contains("QPSQL"));
        QCOMPARE(readFile(m_table), table);
    }
};

QTEST_GUILESS_MAIN(TestLibraryFaults)
#include "tst_libraryfaults.moc"
