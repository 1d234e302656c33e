// SPDX-License-Identifier: GPL-3.0-or-later
// What tst_library.cpp and tst_librarywriters.cpp share: events, their digests and a connection of the test's
// own.
#pragma once

#include "model/library/historyrecorder.h"
#include "model/library/library.h"
#include "model/library/spool.h"
#include "model/toolsetter.h"
#include "tests/support/fulldisk.h"
#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <csignal>

namespace Toffee::Test {

using namespace Qt::StringLiterals;

inline QDateTime at(int minutes)
{
    return QDateTime(QDate(2026, 11, 23), QTime(8, 0), Qt::UTC).addSecs(minutes * 60).addMSecs(125);
}

inline HistoryEvent makeEvent(int tool, EventKind kind, int minutes, double tlo)
{
    HistoryEvent e;
    e.id = HistoryEvent::newId();
    e.machine = u"Carvera"_s;
    e.tool = tool;
    e.at = at(minutes);
    e.kind = kind;
    e.tlo = tlo;
    return e;
}

inline QByteArray digest(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QCryptographicHash::hash(file.readAll(), QCryptographicHash::Sha256);
}

// A second connection of the test's own, straight through Qt SQL.
struct RawConnection
{
    QString name;
    explicit RawConnection(const QString &path, const QString &id)
        : name(id)
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(u"QSQLITE"_s, name);
        db.setDatabaseName(path);
        db.open();
    }
    ~RawConnection()
    {
        QSqlDatabase::database(name, false).close();
        QSqlDatabase::removeDatabase(name);
    }
    bool exec(const QString &sql) const
    {
        QSqlQuery query(QSqlDatabase::database(name));
        return query.exec(sql);
    }
    QVariant value(const QString &sql) const
    {
        QSqlQuery query(QSqlDatabase::database(name));
        return query.exec(sql) && query.next() ? query.value(0) : QVariant();
    }
};

} // namespace Toffee::Test
