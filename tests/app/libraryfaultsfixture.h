// SPDX-License-Identifier: GPL-3.0-or-later
// What the fault matrix's library tests share (tst_libraryfaults, tst_librarytampering): a real PostgreSQL
// server (PgCluster) with a shop's and a viewer's role and the example table put in its library, a table file
// and an SQLite library for each case, and a connection of the test's own to lock or tamper with rows.
#pragma once

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>

#include "tests/support/pgcluster.h"
#include "tests/support/processes.h"

namespace Toffee::Test {

using namespace Qt::StringLiterals;

inline QJsonObject lastJson(const QByteArray &out)
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

// The server, the folders and what each case starts from; a test class calls setUpCase from initTestCase and
// setUpEach from init.
class LibraryFaultsFixture
{
protected:
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

    void setUpCase()
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

    void setUpEach()
    {
        ++m_case;
        m_table = m_dir.filePath(u"table%1.json"_s.arg(m_case));
        m_sqlite = m_dir.filePath(u"library%1.sqlite"_s.arg(m_case));
        QFile::remove(m_table);
        QVERIFY(QFile::copy(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json"), m_table));
        QFile(m_table).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
        QDir(spoolFolder()).removeRecursively();
    }
};

} // namespace Toffee::Test
