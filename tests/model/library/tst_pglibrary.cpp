// SPDX-License-Identifier: GPL-3.0-or-later
// The library on a real PostgreSQL server the test starts itself (PgCluster): the machine tables' cases of
// tst_librarytables, what a station is told when it cannot open the library, a read-only role, and the
// server killed in the middle of a save and of a measurement.
#include <csignal>

#include <QProcess>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>

#include "model/library/historyrecorder.h"
#include "tests/model/library/sharedtablecases.h"
#include "tests/support/pgcluster.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

class TestPgLibrary : public SharedTableCases
{
    Q_OBJECT

protected:
    LibraryLocation freshLocation() override
    {
        const QString name = u"lib%1"_s.arg(++m_databases);
        QString error;
        if (!m_cluster.createDatabase(name, u"toffee"_s, &error))
            qFatal("%s", qPrintable(error));
        return location(u"toffee"_s, name);
    }

    LibraryLocation location(const QString &user, const QString &database) const
    {
        return LibraryLocation::parse(m_cluster.url(user, database)).value();
    }

    QString openError(const LibraryLocation &where, Library::Options options = {}) const
    {
        auto opened = Library::open(where, options);
        return opened ? QString() : opened.error().message;
    }

    // A connection of the test's own that holds T1's row locked, so that a station's write waits on it.
    struct RowLock
    {
        QString name = u"row-lock"_s;
        RowLock(const PgCluster &cluster, const QString &database)
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(u"QPSQL"_s, name);
            db.setHostName(cluster.socketDir());
            db.setPort(cluster.port());
            db.setUserName(PgCluster::adminUser());
            db.setDatabaseName(database);
            if (!db.open() || !db.transaction())
                qFatal("the row lock cannot connect");
            QSqlQuery query(db);
            if (!query.exec(u"SELECT number FROM tools WHERE machine = 'C1' AND number = 1 FOR UPDATE"_s))
                qFatal("the row lock cannot lock");
        }
        ~RowLock()
        {
            QSqlDatabase::database(name, false).close();
            QSqlDatabase::removeDatabase(name);
        }
    };

    // A library with C1's table, and station A's recorder on it with its outbox in `own`.
    bool stationA(HistoryRecorder &recorder, const LibraryLocation &where, const QTemporaryDir &own)
    {
        if (!station(where, u"setup"_s)->createTable(u"C1"_s, threeTools()))
            return false;
        recorder.setOutboxLocation({ own.filePath(u"outbox.sqlite"_s) });
        return bool(
            recorder.setLocation(where, Library::Options { .connectTimeoutS = 1, .station = u"A"_s }));
    }

    // SIGKILL to the postmaster in `ms`, from a process of its own: the test's thread is then waiting in a
    // write.
    void killServerIn(int ms)
    {
        QProcess::startDetached(
            u"sh"_s, { u"-c"_s, u"sleep %1; kill -9 %2"_s.arg(ms / 1000.0).arg(m_cluster.postmasterPid()) });
    }

private Q_SLOTS:
    void initTestCase()
    {
        QString error;
        QVERIFY2(m_cluster.start(&error), qPrintable(error));
        QVERIFY2(m_cluster.createRole(u"toffee"_s, u"s3cret"_s, true, &error), qPrintable(error));
        QVERIFY(m_cluster.createRole(u"reader"_s, u"r3ad"_s, true, &error));
        QVERIFY(m_cluster.createRole(u"wrongpw"_s, u"Corr3ct-pw"_s, true, &error));
        QVERIFY(m_cluster.createRole(u"nopass"_s, u"unknown"_s, true, &error));
        QVERIFY(m_cluster.writePassFile(m_home.filePath(u"pgpass"_s),
            { { u"*"_s, u"toffee"_s, u"s3cret"_s }, { u"*"_s, u"reader"_s, u"r3ad"_s },
                { u"*"_s, u"wrongpw"_s, u"wrong-pw"_s } },
            &error));
        qputenv("PGPASSFILE", m_home.filePath(u"pgpass"_s).toLocal8Bit());
    }

    void eachFailureToOpenSaysWhatToFix_data()
    {
        QTest::addColumn<QString>("user");
        QTest::addColumn<QString>("database");
        QTest::addColumn<QString>("expected");
        QTest::newRow("wrong password") << u"wrongpw"_s << u"postgres"_s << u"password file"_s;
        QTest::newRow("no password") << u"nopass"_s << u"postgres"_s << u"password file"_s;
        QTest::newRow("missing database") << u"toffee"_s << u"nosuch"_s << u"has no database \"nosuch\""_s;
        QTest::newRow("unknown role") << u"ghost"_s << u"postgres"_s << u"password file"_s;
    }
    void eachFailureToOpenSaysWhatToFix()
    {
        QFETCH(QString, user);
        QFETCH(QString, database);
        QFETCH(QString, expected);
        const QString error = openError(location(user, database));
        QVERIFY2(error.contains(expected), qPrintable(error));
        QVERIFY2(!error.contains(u"s3cret"_s) && !error.contains(u"Corr3ct-pw"_s)
                && !error.contains(u"wrong-pw"_s),
            "never a password");
    }

    void anUnreachableOrTooOldServerIsNamed()
    {
        LibraryLocation nowhere = location(u"toffee"_s, u"postgres"_s);
        nowhere.port = m_cluster.port() + 1; // no server on that socket
        QString error = openError(nowhere);
        QVERIFY2(error.contains(u"cannot be reached"_s), qPrintable(error));
        const LibraryLocation where = freshLocation();
        error = openError(where, Library::Options { .oldestServerVersion = 990000 });
        QVERIFY2(error.contains(u"does not support"_s) && error.contains(u"needs 99 or newer"_s),
            qPrintable(error));
        QVERIFY(openError(where).isEmpty()); // the library itself is fine
        // And a station whose shared library will not open still records into its own file.
        QTemporaryDir own;
        auto embedded = Library::open(LibraryLocation { own.filePath(u"l.sqlite"_s) });
        QVERIFY(embedded && embedded.value()->append({ probe(u"C1"_s, 1, -1.0) }).value() == 1);
    }

    void aReadOnlyRoleReadsButNeverWrites()
    {
        const LibraryLocation where = freshLocation();
        QVERIFY(station(where, u"A"_s)->createTable(u"C1"_s, threeTools()));
        QString error;
        QVERIFY2(m_cluster.grantReadOnly(u"reader"_s, where.database, &error), qPrintable(error));
        auto reader = station(location(u"reader"_s, where.database), u"R"_s);
        QVERIFY(reader && reader->isReadOnly());
        QCOMPARE(reader->readTable(u"C1"_s).value().table(), threeTools());
        auto refused = reader->writeTools(u"C1"_s, { { 1, tool(1, u"x"_s, 1), 1 } });
        QVERIFY(!refused);
        QVERIFY2(
            refused.error().message.contains(u"read-only for reader"_s), qPrintable(refused.error().message));
        QVERIFY(!reader->append({ probe(u"C1"_s, 1, -1.0) }));
    }

    void theServerKilledMidSaveAndMidMeasurementLosesAndDuplicatesNothing()
    {
        const LibraryLocation where = freshLocation();
        QTemporaryDir own;
        HistoryRecorder recorder;
        QVERIFY(stationA(recorder, where, own));
        QSignalSpy down(&recorder, &HistoryRecorder::unavailable);
        const HistoryEvent measured = probe(u"C1"_s, 1, -30.5);
        {
            RowLock lock(m_cluster, where.database); // the save waits on T1's row ...
            killServerIn(700); // ... and the server dies under it
            auto saved = recorder.writeTools(
                { u"C1"_s, Units::Millimetre, { { 1, tool(1, u"reground"_s, 29), 1 } } });
            QVERIFY2(saved, qPrintable(saved ? QString() : saved.error().message));
            QVERIFY(saved.value().queued);
        }
        QString error;
        m_cluster.kill9(&error);
        QSignalSpy counted(&recorder, &HistoryRecorder::pendingChanged);
        recorder.record(measured); // a measurement while the server is down
        for (const QList<QVariant> &count : counted) // never counted twice on its way to the outbox
            QVERIFY2(count.first().toLongLong() <= 2, qPrintable(count.first().toString()));
        QCOMPARE(down.size(), 1);
        QVERIFY2(down.first().first().toString().contains(u"cannot be reached"_s)
                || !down.first().first().toString().isEmpty(),
            qPrintable(down.first().first().toString()));
        QCOMPARE(recorder.pendingCount(), 2); // kept in the station's own library, not in memory
        QVERIFY2(m_cluster.restart(&error), qPrintable(error));
        QSignalSpy back(&recorder, &HistoryRecorder::available);
        QVERIFY(back.wait(3 * HistoryRecorder::kRetryMs));
        QCOMPARE(recorder.pendingCount(), 0);
        auto check = station(where, u"check"_s);
        const StoredTable table = check->readTable(u"C1"_s).value();
        QCOMPARE(table.row(1)->tool->description, u"reground"_s);
        QCOMPARE(table.row(1)->tool->measuredTlo, -30.5);
        QCOMPARE(table.row(1)->version, 3); // the save once, the measurement once
        QCOMPARE(check->history({ u"C1"_s, 1, {}, 0 }).value().size(), 1);
    }

    void aMeasurementKilledMidWriteIsWrittenOnceWhenTheServerReturns()
    {
        const LibraryLocation where = freshLocation();
        QTemporaryDir own;
        HistoryRecorder recorder;
        QVERIFY(stationA(recorder, where, own));
        const HistoryEvent measured = probe(u"C1"_s, 1, -29.75);
        {
            RowLock lock(m_cluster, where.database); // the event's row update waits on T1 ...
            killServerIn(700);
            recorder.record(measured); // ... and the server dies under it
        }
        QString error;
        m_cluster.kill9(&error);
        QVERIFY(!recorder.isAvailable());
        QCOMPARE(recorder.pendingCount(), 1);
        // The station itself crashes now: a new one finds the measurement in the outbox.
        HistoryRecorder restarted;
        restarted.setOutboxLocation({ own.filePath(u"outbox.sqlite"_s) });
        QVERIFY(!restarted.setLocation(where, Library::Options { .connectTimeoutS = 1 }));
        QCOMPARE(restarted.pendingCount(), 1);
        QVERIFY2(m_cluster.restart(&error), qPrintable(error));
        // As if the first write had reached the server and only its acknowledgement was lost.
        auto check = station(where, u"check"_s);
        QCOMPARE(check->append({ measured }).value(), 1);
        QSignalSpy back(&restarted, &HistoryRecorder::available);
        QVERIFY(back.wait(3 * HistoryRecorder::kRetryMs));
        QCOMPARE(restarted.pendingCount(), 0);
        QCOMPARE(check->history({ u"C1"_s, 1, {}, 0 }).value().size(), 1);
        QCOMPARE(check->readTable(u"C1"_s).value().row(1)->version, 2);
        QCOMPARE(check->readTable(u"C1"_s).value().row(1)->tool->measuredTlo, -29.75);
    }

private:
    PgCluster m_cluster;
    QTemporaryDir m_home;
    int m_databases = 0;
};

QTEST_GUILESS_MAIN(TestPgLibrary)
#include "tst_pglibrary.moc"
