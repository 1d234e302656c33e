// SPDX-License-Identifier: GPL-3.0-or-later
// The throwaway PostgreSQL server the suite starts for itself: roles log in with the password from a libpq
// password file, a killed postmaster comes back with every committed row, and nothing outlives the cluster.
#include <memory>
#include <unistd.h>

#include <QElapsedTimer>
#include <QFileInfo>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>

#include "tests/support/pgcluster.h"
#include "tests/support/pgclusterprocess.h"

using namespace Qt::StringLiterals;
using Toffee::Test::PgCluster;
using Toffee::Test::PgPassEntry;
namespace Process = Toffee::Test::PgClusterProcess;

namespace {

const QString kOwner = u"toffee_owner"_s;
// A colon and a backslash, which the password file escapes.
const QString kPassword = u"pa:ss\\word"_s;
const QString kDatabase = u"toffee"_s;

// A QPSQL connection given no password: libpq reads it from the file PGPASSFILE names.
class Connection
{
public:
    Connection(const PgCluster &cluster, const QString &user, const QString &database)
        : m_name(u"tst_pgcluster-%1"_s.arg(++s_count))
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(u"QPSQL"_s, m_name);
        db.setHostName(cluster.socketDir());
        db.setPort(cluster.port());
        db.setUserName(user);
        db.setDatabaseName(database);
        m_open = db.open();
        m_error = db.lastError().text();
    }
    ~Connection()
    {
        QSqlDatabase::database(m_name, false).close();
        QSqlDatabase::removeDatabase(m_name);
    }
    Q_DISABLE_COPY_MOVE(Connection)

    [[nodiscard]] bool isOpen() const { return m_open; }
    [[nodiscard]] QString error() const { return m_error; }

    // The first value `sql` returns (true when it returns none), or its error in error().
    QVariant exec(const QString &sql)
    {
        QSqlQuery query(QSqlDatabase::database(m_name, false));
        if (!query.exec(sql)) {
            m_error = query.lastError().text();
            return {};
        }
        return query.next() ? query.value(0) : QVariant(true);
    }

private:
    static inline int s_count = 0;
    QString m_name;
    QString m_error;
    bool m_open = false;
};

} // namespace

class TestPgCluster : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void startsAServerOnItsOwnSocketOnly();
    void roleLogsInWithThePasswordFromThePassFile();
    void refusesAWrongPasswordWithTheServersReason();
    void readOnlyRoleReadsTablesMadeLaterButWritesNone();
    void committedRowSurvivesKill9AndRestart();
    void stopAndDestructorLeaveNoProcessAndNoFolder();
    void twoClustersHaveTheirOwnFolderAndPort();

private:
    bool passFile(const PgCluster &cluster, const QList<PgPassEntry> &entries);
    bool startWithOwner(PgCluster &cluster);

    QTemporaryDir m_home;
    PgCluster m_cluster;
};

bool TestPgCluster::passFile(const PgCluster &cluster, const QList<PgPassEntry> &entries)
{
    const QString path = m_home.filePath(u"pgpass"_s);
    qputenv("PGPASSFILE", QFile::encodeName(path));
    return cluster.writePassFile(path, entries);
}

// A running cluster with a login role that owns a database, and a password file for it.
bool TestPgCluster::startWithOwner(PgCluster &cluster)
{
    QString error;
    const bool ok = cluster.start(&error) && cluster.createRole(kOwner, kPassword, true, &error)
        && cluster.createDatabase(kDatabase, kOwner, &error)
        && passFile(cluster, { { kDatabase, kOwner, kPassword } });
    if (!ok)
        qWarning("%s", qPrintable(error));
    return ok;
}

void TestPgCluster::initTestCase()
{
    QVERIFY(m_home.isValid());
    QVERIFY(QSqlDatabase::isDriverAvailable(u"QPSQL"_s));
    QElapsedTimer clock;
    clock.start();
    QVERIFY(startWithOwner(m_cluster));
    qInfo("start() and a role with its database: %lld ms", qint64(clock.elapsed()));
}

void TestPgCluster::startsAServerOnItsOwnSocketOnly()
{
    PgCluster cluster;
    QElapsedTimer clock;
    clock.start();
    QString error;
    QVERIFY2(cluster.start(&error), qPrintable(error));
    qInfo("start(): %lld ms", qint64(clock.elapsed()));
    QVERIFY(cluster.isRunning());
    QVERIFY(cluster.socketDir().startsWith(PgCluster::root() + u"/cluster-"_s));
    QVERIFY(QFileInfo::exists(cluster.socketDir() + u"/.s.PGSQL.%1"_s.arg(cluster.port())));
    QCOMPARE(cluster.value(u"SELECT current_user"_s, &error).toString(), PgCluster::adminUser());
    QCOMPARE(cluster.value(u"SHOW listen_addresses"_s, &error).toString(), QString());
    QCOMPARE(cluster.value(u"SHOW fsync"_s, &error).toString(), u"on"_s);
    QCOMPARE(cluster.value(u"SHOW synchronous_commit"_s, &error).toString(), u"on"_s);
    QCOMPARE(cluster.url(u"me"_s, u"db"_s),
        u"postgresql://me@/db?host=%1&port=%2"_s.arg(cluster.socketDir()).arg(cluster.port()));
    // PostgreSQL refuses to run as root: under a root suite it runs as nobody.
    const uint serverUid = QFileInfo(u"/proc/%1"_s.arg(cluster.postmasterPid())).ownerId();
    QCOMPARE(serverUid == 0, false);
    QCOMPARE(serverUid == ::geteuid(), ::geteuid() != 0);
}

void TestPgCluster::roleLogsInWithThePasswordFromThePassFile()
{
    QVERIFY(passFile(m_cluster, { { kDatabase, kOwner, kPassword } }));
    const QFile::Permissions others = QFile::ReadGroup | QFile::WriteGroup | QFile::ExeGroup
        | QFile::ReadOther | QFile::WriteOther | QFile::ExeOther;
    QCOMPARE(QFile::permissions(m_home.filePath(u"pgpass"_s)) & others, QFile::Permissions());
    Connection connection(m_cluster, kOwner, kDatabase);
    QVERIFY2(connection.isOpen(), qPrintable(connection.error()));
    QCOMPARE(connection.exec(u"SELECT current_user"_s).toString(), kOwner);
    QVERIFY2(
        connection.exec(u"CREATE TABLE tools (number integer)"_s).isValid(), qPrintable(connection.error()));
}

void TestPgCluster::refusesAWrongPasswordWithTheServersReason()
{
    QVERIFY(passFile(m_cluster, { { kDatabase, kOwner, u"wrong"_s } }));
    Connection wrong(m_cluster, kOwner, kDatabase);
    QVERIFY(!wrong.isOpen());
    QVERIFY2(wrong.error().contains(u"password authentication failed for user \"%1\""_s.arg(kOwner)),
        qPrintable(wrong.error()));
    QVERIFY(passFile(m_cluster, {}));
    Connection none(m_cluster, kOwner, kDatabase);
    QVERIFY(!none.isOpen());
    QVERIFY2(none.error().contains(u"no password supplied"_s), qPrintable(none.error()));
}

void TestPgCluster::readOnlyRoleReadsTablesMadeLaterButWritesNone()
{
    QString error;
    QVERIFY2(m_cluster.createRole(u"reader"_s, u"r"_s, true, &error), qPrintable(error));
    QVERIFY2(m_cluster.grantReadOnly(u"reader"_s, kDatabase, &error), qPrintable(error));
    QVERIFY(passFile(m_cluster, { { kDatabase, kOwner, kPassword }, { u"*"_s, u"reader"_s, u"r"_s } }));
    Connection owner(m_cluster, kOwner, kDatabase);
    QVERIFY2(owner.exec(u"CREATE TABLE later (number integer)"_s).isValid(), qPrintable(owner.error()));
    QVERIFY2(owner.exec(u"INSERT INTO later VALUES (7)"_s).isValid(), qPrintable(owner.error()));
    Connection reader(m_cluster, u"reader"_s, kDatabase);
    QVERIFY2(reader.isOpen(), qPrintable(reader.error()));
    QCOMPARE(reader.exec(u"SELECT number FROM later"_s).toInt(), 7);
    QVERIFY(!reader.exec(u"INSERT INTO later VALUES (8)"_s).isValid());
    QVERIFY2(reader.error().contains(u"permission denied"_s), qPrintable(reader.error()));
    QVERIFY(!reader.exec(u"CREATE TABLE mine (number integer)"_s).isValid());
}

void TestPgCluster::committedRowSurvivesKill9AndRestart()
{
    PgCluster cluster;
    QVERIFY(startWithOwner(cluster));
    Connection before(cluster, kOwner, kDatabase);
    QVERIFY2(before.exec(u"CREATE TABLE tools (number integer)"_s).isValid(), qPrintable(before.error()));
    QVERIFY(before.exec(u"INSERT INTO tools VALUES (42)"_s).isValid());
    const qint64 pid = cluster.postmasterPid();
    QVERIFY(pid > 0);
    QString error;
    QElapsedTimer clock;
    clock.start();
    QVERIFY2(cluster.kill9(&error), qPrintable(error));
    qInfo("kill9(): %lld ms", qint64(clock.elapsed()));
    QVERIFY(Process::isGone(pid));
    QVERIFY(!cluster.isRunning());
    QVERIFY(!before.exec(u"SELECT 1"_s).isValid());

    clock.restart();
    QVERIFY2(cluster.restart(&error), qPrintable(error));
    qInfo("restart() with crash recovery: %lld ms", qint64(clock.elapsed()));
    QVERIFY(cluster.postmasterPid() != pid);
    Connection after(cluster, kOwner, kDatabase);
    QVERIFY2(after.isOpen(), qPrintable(after.error()));
    QCOMPARE(after.exec(u"SELECT number FROM tools"_s).toInt(), 42);
    QVERIFY(cluster.serverLog().contains(u"database system was interrupted"_s));
}

void TestPgCluster::stopAndDestructorLeaveNoProcessAndNoFolder()
{
    auto cluster = std::make_unique<PgCluster>();
    QString error;
    QVERIFY2(cluster->start(&error), qPrintable(error));
    const qint64 pid = cluster->postmasterPid();
    const QList<qint64> backends = Process::childrenOf(pid);
    QVERIFY(!backends.isEmpty());
    const QString folder = cluster->socketDir();
    QVERIFY2(cluster->stop(&error), qPrintable(error));
    QVERIFY(Process::isGone(pid));
    QVERIFY(Process::waitGone(backends, 0));
    QVERIFY(cluster->serverLog().contains(u"received fast shutdown request"_s));
    QVERIFY(QFileInfo::exists(folder + u"/data/PG_VERSION"_s));
    cluster.reset();
    QVERIFY(!QFileInfo::exists(folder));
}

void TestPgCluster::twoClustersHaveTheirOwnFolderAndPort()
{
    auto first = std::make_unique<PgCluster>();
    PgCluster second;
    QString error;
    QVERIFY2(first->start(&error), qPrintable(error));
    QVERIFY2(second.start(&error), qPrintable(error));
    QVERIFY(first->socketDir() != second.socketDir());
    QVERIFY(first->port() != second.port());
    QVERIFY2(first->exec(u"CREATE DATABASE one"_s, &error), qPrintable(error));
    QVERIFY(second.value(u"SELECT count(*) FROM pg_database WHERE datname = 'one'"_s, &error).toInt() == 0);
    // The destructor of a running cluster: an immediate shutdown, then the folder goes.
    const qint64 pid = first->postmasterPid();
    const QList<qint64> backends = Process::childrenOf(pid);
    const QString folder = first->socketDir();
    first.reset();
    QVERIFY(Process::isGone(pid));
    QVERIFY(Process::waitGone(backends, 0));
    QVERIFY(!QFileInfo::exists(folder));
    QVERIFY(second.exec(u"SELECT 1"_s, &error));
}

QTEST_GUILESS_MAIN(TestPgCluster)
#include "tst_pgcluster.moc"
