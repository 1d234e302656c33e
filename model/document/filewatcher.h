// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QFileSystemWatcher>
#include <QObject>

namespace Toffee {

// Notices when the open table's file is changed by someone else. Toffee's own saves are told to it, so only
// content that differs from what Toffee last read or wrote counts.
class FileWatcher final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(FileWatcher)

public:
    explicit FileWatcher(QObject *parent = nullptr);

    // Watches `path` (none when empty), taking its current content as the known one.
    void watch(const QString &path);

Q_SIGNALS:
    void changedOnDisk(const QString &path);

private:
    void check();
    [[nodiscard]] QByteArray digestOf(const QString &path) const;

    QFileSystemWatcher m_watcher;
    QString m_path;
    QByteArray m_known;
};

} // namespace Toffee
