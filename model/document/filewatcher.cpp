// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/document/filewatcher.h"

#include <QCryptographicHash>
#include <QFile>
#include <QFileInfo>
#include <QTimer>

#include "model/formats/fileio.h"

namespace Toffee {

FileWatcher::FileWatcher(QObject *parent)
    : QObject(parent)
{
    // Editors save by replacing the file, which ends the watch: check a moment later and watch again.
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this,
        [this] { QTimer::singleShot(100, this, &FileWatcher::check); });
}

QByteArray FileWatcher::digestOf(const QString &path) const
{
    // Only a regular file is read: opening a FIFO put in the file's place would block the window.
    if (!isRegularFile(path))
        return QFileInfo::exists(path) ? QByteArrayLiteral("not a regular file") : QByteArray();
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QCryptographicHash hash(QCryptographicHash::Sha256);
    hash.addData(&file);
    return hash.result();
}

void FileWatcher::watch(const QString &path)
{
    if (!m_watcher.files().isEmpty())
        m_watcher.removePaths(m_watcher.files());
    m_path = path;
    m_known = path.isEmpty() ? QByteArray() : digestOf(path);
    if (!path.isEmpty() && !path.startsWith(u':'))
        m_watcher.addPath(path);
}

void FileWatcher::check()
{
    if (m_path.isEmpty())
        return;
    if (!m_watcher.files().contains(m_path) && QFile::exists(m_path))
        m_watcher.addPath(m_path);
    const QByteArray now = digestOf(m_path);
    if (now == m_known)
        return;
    m_known = now;
    Q_EMIT changedOnDisk(m_path);
}

} // namespace Toffee
