// SPDX-License-Identifier: GPL-3.0-or-later
#include "tests/support/pgclusterprocess.h"

#include <algorithm>
#include <grp.h>
#include <pwd.h>
#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>
#include <QThread>

using namespace Qt::StringLiterals;

namespace Toffee::Test::PgClusterProcess {

namespace {

// Field `number` (from 1, as in proc(5)) of /proc/PID/stat; the name in field 2 may hold spaces and
// parentheses, so the count starts after its last ')'.
QByteArray statField(qint64 pid, int number)
{
    QFile file(u"/proc/%1/stat"_s.arg(pid));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QByteArray stat = file.readAll();
    const qsizetype nameEnd = stat.lastIndexOf(')');
    if (nameEnd < 0)
        return {};
    const QList<QByteArray> fields = stat.mid(nameEnd + 2).split(' ');
    return number >= 3 && number - 3 < fields.size() ? fields.at(number - 3).trimmed() : QByteArray();
}

bool hasServer(const QString &dir)
{
    return !dir.isEmpty() && QFileInfo(dir + u"/initdb"_s).isExecutable()
        && QFileInfo(dir + u"/postgres"_s).isExecutable();
}

QString pgConfigBinDir()
{
    const QString pgConfig = QStandardPaths::findExecutable(u"pg_config"_s);
    if (pgConfig.isEmpty())
        return {};
    QProcess process;
    process.start(pgConfig, { u"--bindir"_s });
    if (!process.waitForFinished(10000))
        return {};
    return QString::fromLocal8Bit(process.readAllStandardOutput()).trimmed();
}

} // namespace

std::optional<Account> serverAccount(QString *error)
{
    if (::geteuid() != 0)
        return Account { ::geteuid(), ::getegid(), false };
    const passwd *nobody = ::getpwnam("nobody");
    if (!nobody) {
        if (error)
            *error = u"running as root, and there is no user nobody to run PostgreSQL as"_s;
        return std::nullopt;
    }
    const group *nogroup = ::getgrnam("nogroup");
    return Account { nobody->pw_uid, nogroup ? nogroup->gr_gid : nobody->pw_gid, true };
}

bool giveTo(const QString &path, const Account &account)
{
    return !account.switchUser || ::chown(QFile::encodeName(path).constData(), account.uid, account.gid) == 0;
}

void runAs(QProcess &process, const Account &account, int deathSignal)
{
    const pid_t parent = ::getpid();
    process.setChildProcessModifier([account, deathSignal, parent] {
        // Between fork and exec: the groups before the uid, which takes the right to change them; the death
        // signal after, since changing ids clears it.
        if (account.switchUser
            && (::setgroups(0, nullptr) != 0 || ::setgid(account.gid) != 0 || ::setuid(account.uid) != 0)) {
            static const char message[] = "pgcluster: cannot switch to the server's account\n";
            [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, message, sizeof message - 1);
            ::_exit(126);
        }
        if (deathSignal != 0 && (::prctl(PR_SET_PDEATHSIG, deathSignal) != 0 || ::getppid() != parent))
            ::_exit(125);
    });
}

QString findBinDir()
{
    if (const QString dir = pgConfigBinDir(); hasServer(dir))
        return dir;
    // Debian keeps each major version's server in a folder of its own, off PATH.
    QStringList versions = QDir(u"/usr/lib/postgresql"_s).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    std::sort(versions.begin(), versions.end(),
        [](const QString &a, const QString &b) { return a.toDouble() > b.toDouble(); });
    for (const QString &version : std::as_const(versions)) {
        if (const QString dir = u"/usr/lib/postgresql/%1/bin"_s.arg(version); hasServer(dir))
            return dir;
    }
    const QString initdb = QStandardPaths::findExecutable(u"initdb"_s);
    return !initdb.isEmpty() && hasServer(QFileInfo(initdb).absolutePath()) ? QFileInfo(initdb).absolutePath()
                                                                            : QString();
}

QList<qint64> childrenOf(qint64 pid)
{
    QList<qint64> children;
    const QStringList entries = QDir(u"/proc"_s).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    for (const QString &entry : entries) {
        bool numeric = false;
        const qint64 candidate = entry.toLongLong(&numeric);
        if (numeric && statField(candidate, 4).toLongLong() == pid)
            children.append(candidate);
    }
    return children;
}

bool isGone(qint64 pid)
{
    const QByteArray state = statField(pid, 3);
    return state.isEmpty() || state == "Z" || state == "X";
}

bool waitGone(const QList<qint64> &pids, int timeoutMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    for (;;) {
        if (std::all_of(pids.cbegin(), pids.cend(), isGone))
            return true;
        if (deadline.hasExpired())
            return false;
        QThread::msleep(5);
    }
}

QString startTime(qint64 pid)
{
    return QString::fromLatin1(statField(pid, 22));
}

} // namespace Toffee::Test::PgClusterProcess
