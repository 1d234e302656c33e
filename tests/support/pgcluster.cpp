// SPDX-License-Identifier: GPL-3.0-or-later
#include "tests/support/pgcluster.h"

#include <atomic>
#include <signal.h>
#include <sys/shm.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QThread>

#include "tests/support/pgclusterprocess.h"

using namespace Qt::StringLiterals;

namespace Toffee::Test {

namespace {

// Crash recovery included; initdb takes about half a second.
constexpr int kStartTimeoutMs = 60000;
constexpr int kStopTimeoutMs = 30000;
constexpr int kBackendsTimeoutMs = 10000;

// The server listens on no TCP address, so the port only names the socket file in the cluster's own folder
// and never collides; counting up still gives each cluster of a process a different one.
int nextPort()
{
    static const int base = int(QRandomGenerator::global()->bounded(20000));
    static std::atomic<int> count = 0;
    return 5433 + (base + count++) % 20000;
}

QStringList pidFileLines(const QString &dataDir)
{
    QFile file(dataDir + u"/postmaster.pid"_s);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QString::fromLocal8Bit(file.readAll()).split(u'\n');
}

// Every process of a cluster is attached to the System V segment named on line 7 of postmaster.pid (key and
// id): once none is, even a backend forked after childrenOf() looked, a restart can start. The segment is
// removed then, which the killed postmaster never did and nothing would do before a reboot.
bool releaseSharedMemory(const QStringList &pidFile, int timeoutMs)
{
    bool ok = false;
    const int id = pidFile.value(6).split(u' ', Qt::SkipEmptyParts).value(1).toInt(&ok);
    const QDeadlineTimer deadline(timeoutMs);
    shmid_ds info {};
    while (ok && ::shmctl(id, IPC_STAT, &info) == 0) {
        if (info.shm_nattch == 0)
            return ::shmctl(id, IPC_RMID, nullptr) == 0;
        if (deadline.hasExpired())
            return false;
        QThread::msleep(5);
    }
    return true;
}

} // namespace

PgCluster::PgCluster() = default;

PgCluster::~PgCluster()
{
    shutDown(SIGQUIT, nullptr);
}

QString PgCluster::adminUser()
{
    return u"toffee_admin"_s;
}

QString PgCluster::root()
{
    return QDir::tempPath() + u"/toffee-pgtest"_s;
}

bool PgCluster::start(QString *error)
{
    if (m_dir)
        return restart(error);
    m_binDir = PgClusterProcess::findBinDir();
    if (m_binDir.isEmpty())
        return fail(
            error, u"no PostgreSQL server (initdb, postgres) found; on Debian: apt install postgresql"_s);
    m_port = nextPort();
    if (makeFolder(error) && initDataDir(error) && launch(error))
        return true;
    m_server.reset();
    m_dir.reset();
    return false;
}

bool PgCluster::stop(QString *error)
{
    return shutDown(SIGINT, error);
}

bool PgCluster::kill9(QString *error)
{
    if (!isRunning())
        return fail(error, u"the server is not running"_s);
    const qint64 pid = m_server->processId();
    const QList<qint64> backends = PgClusterProcess::childrenOf(pid);
    ::kill(pid_t(pid), SIGKILL);
    m_server->waitForFinished(-1);
    // The backends notice their postmaster's death and exit; a restart before they have would find the
    // shared memory still in use and refuse to start.
    if (!PgClusterProcess::waitGone(backends, kBackendsTimeoutMs)) {
        for (const qint64 backend : backends)
            ::kill(pid_t(backend), SIGKILL);
        PgClusterProcess::waitGone(backends, kBackendsTimeoutMs);
    }
    if (!releaseSharedMemory(pidFileLines(dataDir()), kBackendsTimeoutMs))
        return fail(error, u"a backend of the killed postmaster is still attached to its shared memory"_s);
    // Postgres would judge these stale itself, unless another process of the same user has the old pid by
    // then.
    QFile::remove(dataDir() + u"/postmaster.pid"_s);
    QFile::remove(socketDir() + u"/.s.PGSQL.%1.lock"_s.arg(m_port));
    return true;
}

bool PgCluster::restart(QString *error)
{
    if (!m_dir)
        return fail(error, u"the cluster was never started"_s);
    return isRunning() || launch(error);
}

bool PgCluster::isRunning() const
{
    return m_server && m_server->state() != QProcess::NotRunning;
}

QString PgCluster::socketDir() const
{
    return m_dir ? m_dir->path() : QString();
}

QString PgCluster::dataDir() const
{
    return m_dir ? m_dir->filePath(u"data"_s) : QString();
}

qint64 PgCluster::postmasterPid() const
{
    return pidFileLines(dataDir()).value(0).toLongLong();
}

QString PgCluster::serverLog() const
{
    QFile file(m_dir ? m_dir->filePath(u"server.log"_s) : QString());
    return file.open(QIODevice::ReadOnly) ? QString::fromLocal8Bit(file.readAll()) : QString();
}

bool PgCluster::makeFolder(QString *error)
{
    const QString common = root();
    if (!QDir().mkpath(common))
        return fail(error, u"cannot create %1"_s.arg(common));
    // Every user's tests share the root, as they share /tmp: world-writable and sticky like it.
    const QByteArray commonPath = QFile::encodeName(common);
    struct stat info
    {
    };
    if (::stat(commonPath.constData(), &info) == 0 && info.st_uid == ::geteuid())
        ::chmod(commonPath.constData(), 01777);
    m_dir = std::make_unique<QTemporaryDir>(common + u"/cluster-XXXXXX"_s);
    if (!m_dir->isValid())
        return fail(error, u"cannot create a folder in %1: %2"_s.arg(common, m_dir->errorString()));
    // The cleanup fixture removes only the clusters whose test process is gone, not a parallel ctest's.
    QFile owner(m_dir->filePath(u"owner"_s));
    const qint64 self = ::getpid();
    if (!owner.open(QIODevice::WriteOnly)
        || owner.write(QByteArray::number(self) + ' ' + PgClusterProcess::startTime(self).toLatin1() + '\n')
            < 0)
        return fail(error, u"cannot write %1"_s.arg(owner.fileName()));
    const auto account = PgClusterProcess::serverAccount(error);
    if (!account)
        return false;
    if (!PgClusterProcess::giveTo(m_dir->path(), *account))
        return fail(error, u"cannot hand %1 to the server's account"_s.arg(m_dir->path()));
    return true;
}

bool PgCluster::initDataDir(QString *error)
{
    const auto account = PgClusterProcess::serverAccount(error);
    if (!account)
        return false;
    QProcess initdb;
    initdb.setWorkingDirectory(m_dir->path());
    initdb.setProcessChannelMode(QProcess::MergedChannels);
    PgClusterProcess::runAs(initdb, *account, SIGTERM);
    // --no-sync: an OS crash may corrupt the files initdb wrote, which cannot matter to a throwaway cluster
    // and saves time; the server itself keeps fsync on.
    initdb.start(m_binDir + u"/initdb"_s,
        { u"--pgdata="_s + dataDir(), u"--username="_s + adminUser(), u"--encoding=UTF8"_s, u"--locale=C"_s,
            u"--no-sync"_s, u"--auth-local=trust"_s, u"--auth-host=reject"_s });
    if (!initdb.waitForFinished(kStartTimeoutMs) || initdb.exitStatus() != QProcess::NormalExit
        || initdb.exitCode() != 0) {
        const QString hint = account->switchUser
            ? u" (it runs as nobody, who must be able to reach %1)"_s.arg(root())
            : QString();
        return fail(error, u"initdb failed%1: %2"_s.arg(hint, QString::fromLocal8Bit(initdb.readAll())));
    }
    // The superuser is trusted on the socket, so that the helpers need no password; every other role proves
    // its password, as on a real server.
    QFile hba(dataDir() + u"/pg_hba.conf"_s);
    if (!hba.open(QIODevice::WriteOnly | QIODevice::Truncate)
        || hba.write("local all " + adminUser().toUtf8() + " trust\nlocal all all scram-sha-256\n") < 0)
        return fail(error, u"cannot write %1"_s.arg(hba.fileName()));
    return true;
}

bool PgCluster::launch(QString *error)
{
    const auto account = PgClusterProcess::serverAccount(error);
    if (!account)
        return false;
    m_server = std::make_unique<QProcess>();
    m_server->setWorkingDirectory(m_dir->path());
    m_server->setStandardInputFile(QProcess::nullDevice());
    m_server->setProcessChannelMode(QProcess::MergedChannels);
    m_server->setStandardOutputFile(m_dir->filePath(u"server.log"_s), QIODevice::Append);
    // SIGQUIT (an immediate shutdown) when this thread ends without the destructor having run.
    PgClusterProcess::runAs(*m_server, *account, SIGQUIT);
    // No TCP: the socket in our folder is the only way in. fsync and synchronous_commit are the defaults,
    // said here because the fault tests kill the postmaster and expect every committed row back. syncfs:
    // crash recovery first makes the data directory durable, with one syncfs() rather than an fsync() per
    // file (50 ms rather than 4 s here, the files initdb --no-sync left unsynced).
    const QStringList settings = { u"listen_addresses="_s, u"fsync=on"_s, u"synchronous_commit=on"_s,
        u"recovery_init_sync_method=syncfs"_s };
    QStringList arguments = { u"-D"_s, dataDir(), u"-k"_s, socketDir(), u"-p"_s, QString::number(m_port) };
    for (const QString &setting : settings)
        arguments << u"-c"_s << setting;
    m_server->start(m_binDir + u"/postgres"_s, arguments);
    if (!m_server->waitForStarted())
        return fail(error, u"cannot run %1/postgres: %2"_s.arg(m_binDir, m_server->errorString()));
    return waitUntilReady(error);
}

bool PgCluster::waitUntilReady(QString *error)
{
    const QString pid = QString::number(m_server->processId());
    const QDeadlineTimer deadline(kStartTimeoutMs);
    while (!deadline.hasExpired()) {
        // As pg_ctl -w waits: the postmaster writes "ready" on line 8 of postmaster.pid once it accepts
        // connections, crash recovery done.
        const QStringList lines = pidFileLines(dataDir());
        if (lines.value(0) == pid && lines.value(7).trimmed() == u"ready")
            return true;
        if (m_server->state() == QProcess::NotRunning || m_server->waitForFinished(10))
            return fail(
                error, u"postgres exited with code %1:\n%2"_s.arg(m_server->exitCode()).arg(serverLog()));
    }
    shutDown(SIGQUIT, nullptr);
    return fail(error, u"postgres was not ready in %1 s:\n%2"_s.arg(kStartTimeoutMs / 1000).arg(serverLog()));
}

bool PgCluster::shutDown(int signal, QString *error)
{
    if (!isRunning())
        return true;
    ::kill(pid_t(m_server->processId()), signal);
    // The postmaster exits after its backends, so nothing is left once it has.
    if (m_server->waitForFinished(kStopTimeoutMs))
        return true;
    kill9(nullptr);
    return fail(error, u"postgres did not stop in %1 s, and was killed"_s.arg(kStopTimeoutMs / 1000));
}

bool PgCluster::fail(QString *error, const QString &message) const
{
    if (error)
        *error = message;
    return false;
}

} // namespace Toffee::Test
