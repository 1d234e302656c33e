// SPDX-License-Identifier: GPL-3.0-or-later
// The process side of PgCluster: which account runs the server, where its binaries are, and reading /proc.
#pragma once

#include <optional>
#include <sys/types.h>

#include <QList>
#include <QString>

class QProcess;

namespace Toffee::Test::PgClusterProcess {

// The account initdb and postgres run as: ours, or nobody/nogroup when we are root.
struct Account
{
    uid_t uid = 0;
    gid_t gid = 0;
    bool switchUser = false;
};

[[nodiscard]] std::optional<Account> serverAccount(QString *error);
// Hands `path` to the account when it is not ours.
bool giveTo(const QString &path, const Account &account);
// `process` runs as the account; with a `deathSignal`, it gets that signal when this thread ends.
void runAs(QProcess &process, const Account &account, int deathSignal = 0);
// The folder holding initdb and postgres: pg_config --bindir, the newest /usr/lib/postgresql/*/bin, or PATH.
[[nodiscard]] QString findBinDir();

[[nodiscard]] QList<qint64> childrenOf(qint64 pid);
// True when no process has the pid, or only a zombie that nobody has reaped yet.
[[nodiscard]] bool isGone(qint64 pid);
bool waitGone(const QList<qint64> &pids, int timeoutMs);
// Field 22 of /proc/PID/stat, which tells a process from a later one given the same pid.
[[nodiscard]] QString startTime(qint64 pid);

} // namespace Toffee::Test::PgClusterProcess
