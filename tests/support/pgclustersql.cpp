// SPDX-License-Identifier: GPL-3.0-or-later
// PgCluster's helpers for the tests: SQL as the superuser, roles, databases, grants and password files.
#include "tests/support/pgcluster.h"

#include <atomic>

#include <QFile>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QUrl>

using namespace Qt::StringLiterals;

namespace Toffee::Test {

namespace {

QString identifier(const QString &name)
{
    return u'"' + QString(name).replace(u'"', u"\"\""_s) + u'"';
}

QString literal(const QString &text)
{
    return u'\'' + QString(text).replace(u'\'', u"''"_s) + u'\'';
}

// A field of a password file, where ':' and '\' are escaped.
QString passField(const QString &text)
{
    return QString(text).replace(u'\\', u"\\\\"_s).replace(u':', u"\\:"_s);
}

// `statements` in order on one connection of their own as the superuser; `value` gets the first column of
// the last statement's first row.
bool runAsAdmin(const PgCluster &cluster, const QStringList &statements, const QString &database,
    QVariant *value, QString *error)
{
    const auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    if (!QSqlDatabase::isDriverAvailable(u"QPSQL"_s))
        return fail(u"Qt's QPSQL driver is missing; on Debian: apt install libqt6sql6-psql"_s);
    static std::atomic<int> count = 0;
    const QString name = u"toffee-pgcluster-admin-%1"_s.arg(++count);
    bool ok = true;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(u"QPSQL"_s, name);
        db.setHostName(cluster.socketDir());
        db.setPort(cluster.port());
        db.setUserName(PgCluster::adminUser());
        db.setDatabaseName(database.isEmpty() ? u"postgres"_s : database);
        if (!db.open())
            ok = fail(db.lastError().text());
        for (qsizetype i = 0; ok && i < statements.size(); ++i) {
            QSqlQuery query(db);
            if (!query.exec(statements.at(i)))
                ok = fail(u"%1: %2"_s.arg(statements.at(i), query.lastError().text()));
            else if (value && i + 1 == statements.size())
                *value = query.next() ? query.value(0) : QVariant();
        }
        db.close();
    }
    QSqlDatabase::removeDatabase(name);
    return ok;
}

} // namespace

bool PgCluster::exec(const QString &sql, QString *error, const QString &database) const
{
    return runAsAdmin(*this, { sql }, database, nullptr, error);
}

QVariant PgCluster::value(const QString &sql, QString *error, const QString &database) const
{
    QVariant result;
    return runAsAdmin(*this, { sql }, database, &result, error) ? result : QVariant();
}

bool PgCluster::createRole(const QString &name, const QString &password, bool canLogin, QString *error) const
{
    QString sql = u"CREATE ROLE %1 %2"_s.arg(identifier(name), canLogin ? u"LOGIN"_s : u"NOLOGIN"_s);
    if (!password.isEmpty())
        sql += u" PASSWORD "_s + literal(password);
    return exec(sql, error);
}

bool PgCluster::createDatabase(const QString &name, const QString &owner, QString *error) const
{
    QString sql = u"CREATE DATABASE "_s + identifier(name);
    if (!owner.isEmpty())
        sql += u" OWNER "_s + identifier(owner);
    return exec(sql, error);
}

bool PgCluster::grantReadOnly(const QString &role, const QString &database, QString *error) const
{
    QString reason;
    const QVariant owner = value(
        u"SELECT pg_get_userbyid(datdba) FROM pg_database WHERE datname = "_s + literal(database), &reason);
    if (owner.isNull())
        return fail(error, reason.isEmpty() ? u"no database %1"_s.arg(database) : reason);
    const QString who = identifier(role);
    // Default privileges name the roles whose future tables they cover: the owner's and the superuser's.
    return exec(u"GRANT CONNECT ON DATABASE %1 TO %2"_s.arg(identifier(database), who), error)
        && runAsAdmin(*this,
            { u"GRANT USAGE ON SCHEMA public TO "_s + who,
                u"GRANT SELECT ON ALL TABLES IN SCHEMA public TO "_s + who,
                u"ALTER DEFAULT PRIVILEGES FOR ROLE %1, %2 IN SCHEMA public GRANT SELECT ON TABLES TO %3"_s
                    .arg(identifier(owner.toString()), identifier(adminUser()), who) },
            database, nullptr, error);
}

bool PgCluster::writePassFile(const QString &path, const QList<PgPassEntry> &entries, QString *error) const
{
    // libpq ignores a password file that its group or others may read.
    const QFile::Permissions ownerOnly = QFile::ReadOwner | QFile::WriteOwner;
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate, ownerOnly) || !file.setPermissions(ownerOnly))
        return fail(error, u"cannot write %1: %2"_s.arg(path, file.errorString()));
    for (const PgPassEntry &entry : entries) {
        const QString line = passField(socketDir()) + u':' + QString::number(m_port) + u':'
            + passField(entry.database) + u':' + passField(entry.user) + u':' + passField(entry.password)
            + u'\n';
        if (file.write(line.toUtf8()) < 0)
            return fail(error, u"cannot write %1: %2"_s.arg(path, file.errorString()));
    }
    return true;
}

QString PgCluster::url(const QString &user, const QString &database) const
{
    const auto encoded = [](const QString &text, const QByteArray &keep = {}) {
        return QString::fromLatin1(QUrl::toPercentEncoding(text, keep));
    };
    return u"postgresql://%1@/%2?host=%3&port=%4"_s.arg(
        encoded(user), encoded(database), encoded(socketDir(), "/"), QString::number(m_port));
}

} // namespace Toffee::Test
