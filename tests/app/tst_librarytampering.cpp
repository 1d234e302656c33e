// SPDX-License-Identifier: GPL-3.0-or-later
// The fault matrix's library column, tampered with: a schema version and rows changed behind Toffee's back
// and hostile rows are refused by name, never read into a wrong table, never printed raw; a read-only role is
// refused before the machine moves. toffee-cli on toffee-emulator (a pty), a real PostgreSQL server and
// SQLite files (tests/app/libraryfaultsfixture.h).
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

class TestLibraryTampering : public QObject, public LibraryFaultsFixture
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { setUpCase(); }

    void init() { setUpEach(); }

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

QTEST_GUILESS_MAIN(TestLibraryTampering)
#include "tst_librarytampering.moc"
