// SPDX-License-Identifier: GPL-3.0-or-later
// A throwaway PostgreSQL server for the tests: its own data directory and Unix socket in a folder under
// $TMPDIR/toffee-pgtest (root()), no TCP, stopped and removed by the destructor. A test binary that dies
// before its destructor runs leaves a server that shuts itself down (it gets SIGQUIT when the thread that
// started it ends) and a folder that the pgcluster_cleanup fixture removes (toffee_use_pgcluster in CMake).
// Run as root, the server runs as nobody/nogroup, since PostgreSQL refuses to run as root.
// In CMake: toffee_add_test(tst_x ...) then toffee_use_pgcluster(tst_x) (tests/support/CMakeLists.txt).
#pragma once

#include <memory>

#include <QList>
#include <QString>
#include <QVariant>

class QProcess;
class QTemporaryDir;

namespace Toffee::Test {

// One line of a libpq password file; the host and port are the cluster's.
struct PgPassEntry
{
    QString database;
    QString user;
    QString password;
};

class PgCluster
{
public:
    PgCluster();
    ~PgCluster();
    Q_DISABLE_COPY_MOVE(PgCluster)

    // The superuser, trusted over the socket; every other role logs in with its SCRAM password.
    [[nodiscard]] static QString adminUser();
    // ${TMPDIR:-/tmp}/toffee-pgtest, where every cluster has its folder.
    [[nodiscard]] static QString root();

    // initdb and a server that accepts connections; false with the reason (and the server's log) in `error`.
    // After stop() or kill9(), the same as restart().
    bool start(QString *error);
    // A fast shutdown (pg_ctl stop -m fast): committed work is checkpointed, the folder is kept.
    bool stop(QString *error = nullptr);
    // SIGKILL to the postmaster, as a crash would; returns once it and its backends are gone.
    bool kill9(QString *error = nullptr);
    // The server again on the same data directory and socket, with crash recovery after kill9().
    bool restart(QString *error);

    [[nodiscard]] bool isRunning() const;
    [[nodiscard]] QString socketDir() const;
    [[nodiscard]] QString dataDir() const;
    [[nodiscard]] int port() const { return m_port; }
    // The pid in postmaster.pid, 0 when there is none.
    [[nodiscard]] qint64 postmasterPid() const;
    // postgresql://USER@/DB?host=SOCKETDIR&port=PORT
    [[nodiscard]] QString url(const QString &user, const QString &database) const;
    [[nodiscard]] QString serverLog() const;

    // SQL as the superuser, on a connection of its own to `database` (postgres when empty).
    bool exec(const QString &sql, QString *error, const QString &database = {}) const;
    // The first column of the first row of `sql`; invalid on an error, or when there is no row.
    [[nodiscard]] QVariant value(const QString &sql, QString *error, const QString &database = {}) const;
    bool createRole(
        const QString &name, const QString &password, bool canLogin, QString *error = nullptr) const;
    bool createDatabase(const QString &name, const QString &owner, QString *error = nullptr) const;
    // CONNECT, USAGE on schema public, SELECT on its tables, now and those its owner creates later.
    bool grantReadOnly(const QString &role, const QString &database, QString *error = nullptr) const;
    // A libpq password file (mode 0600) for this cluster's socket: point PGPASSFILE at it.
    bool writePassFile(
        const QString &path, const QList<PgPassEntry> &entries, QString *error = nullptr) const;

private:
    bool makeFolder(QString *error);
    bool initDataDir(QString *error);
    bool launch(QString *error);
    bool waitUntilReady(QString *error);
    bool shutDown(int signal, QString *error);
    bool fail(QString *error, const QString &message) const;

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<QProcess> m_server;
    QString m_binDir;
    int m_port = 0;
};

} // namespace Toffee::Test
