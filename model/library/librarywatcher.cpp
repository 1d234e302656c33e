// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/librarywatcher.h"

#include <QSqlDriver>
#include <QSqlQuery>
#include <QVariant>

#include "model/library/library.h"

using namespace Qt::StringLiterals;

namespace Toffee {

LibraryWatcher::LibraryWatcher(Library *library, QObject *parent)
    : QObject(parent)
    , m_library(library)
{
    QSqlDriver *driver = library->driver();
    if (library->location().isShared() && driver->hasFeature(QSqlDriver::EventNotifications)) {
        connect(driver, &QSqlDriver::notification, this,
            [this](const QString &name, QSqlDriver::NotificationSource, const QVariant &payload) {
                if (name != QString(Library::kChannel))
                    return;
                const QStringList parts = payload.toString().split(u'\t');
                Q_EMIT changed(parts.value(0));
                Q_EMIT announced(parts.value(0), parts.value(1), parts.value(2).toLongLong());
            });
        driver->subscribeToNotification(QString(Library::kChannel));
        return;
    }
    m_poll.setInterval(kPollMs);
    connect(&m_poll, &QTimer::timeout, this, &LibraryWatcher::poll);
    m_poll.start();
    poll();
}

LibraryWatcher::~LibraryWatcher()
{
    if (m_library->location().isShared() && m_library->driver()->isOpen())
        m_library->driver()->unsubscribeFromNotification(QString(Library::kChannel));
}

// data_version changes when another connection commits to the file; this connection's own writes leave it.
void LibraryWatcher::poll()
{
    QSqlQuery query(m_library->driver()->createResult());
    if (!query.exec(u"PRAGMA data_version"_s) || !query.next())
        return;
    const qint64 version = query.value(0).toLongLong();
    if (m_dataVersion >= 0 && version != m_dataVersion)
        Q_EMIT changed({});
    m_dataVersion = version;
}

} // namespace Toffee
