// SPDX-License-Identifier: GPL-3.0-or-later
#include "autosave.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QSaveFile>
#include <QStandardPaths>
#include <QUuid>

#include "tooldocument.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// A lock counts as stale only when the process that took it is gone, never for its age: a Toffee left open
// for a week still owns its copy.
std::unique_ptr<QLockFile> lockFile(const QString &path)
{
    auto lock = std::make_unique<QLockFile>(path);
    lock->setStaleLockTime(0);
    return lock;
}

QString withSuffix(QString path, const QString &suffix)
{
    path.chop(QStringLiteral(".json").size());
    return path + suffix;
}

// Every file of session `id` but its lock: the copy, its .info, and any half-written temporary file QSaveFile
// left as the process died.
void removeSessionFiles(const QDir &dir, const QString &id)
{
    for (const QFileInfo &file : dir.entryInfoList({ id + u".*"_s }, QDir::Files)) {
        if (file.suffix() != u"lock")
            QFile::remove(file.filePath());
    }
}

} // namespace

AutoSave::AutoSave(ToolDocument *document, const QString &directory, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_directory(directory)
    , m_id(QString::number(QCoreApplication::applicationPid()) + u'-'
          + QUuid::createUuid().toString(QUuid::WithoutBraces).left(8))
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(kDefaultDelayMs);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        if (auto saved = saveNow(); !saved)
            Q_EMIT failed(saved.error().text());
    });
    connect(m_document->undoStack(), &QUndoStack::indexChanged, this, &AutoSave::documentChanged);
    connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, &AutoSave::documentChanged);
    connect(m_document, &ToolDocument::filePathChanged, this, &AutoSave::documentChanged);
}

AutoSave::~AutoSave()
{
    removeCopy(); // a normal exit: whatever was unsaved, the operator chose to leave it
}

QString AutoSave::defaultDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + u"/recovery"_s;
}

QString AutoSave::path(const char *suffix) const
{
    return m_directory + u'/' + m_id + QLatin1StringView(suffix);
}

QString AutoSave::tablePath() const
{
    return path(".json");
}

void AutoSave::documentChanged()
{
    if (!m_document->isModified()) {
        m_timer.stop();
        removeCopy();
    } else if (!m_timer.isActive()) {
        m_timer.start();
    }
}

Result<void> AutoSave::saveNow()
{
    m_timer.stop();
    if (!m_document->isModified()) {
        removeCopy();
        return {};
    }
    if (!QDir().mkpath(m_directory))
        return Error { tr("Cannot create the folder for unsaved edits, %1.").arg(m_directory) };
    if (!m_lock) {
        auto lock = lockFile(path(".lock"));
        if (!lock->tryLock(0))
            return Error { tr("Cannot write in the folder for unsaved edits, %1.").arg(m_directory) };
        m_lock = std::move(lock);
    }
    // Where the edits belong is written first: a copy is never on disk without it.
    const QJsonObject info { { u"original_path"_s, m_document->filePath() },
        { u"original_format"_s, formatSuffix(m_document->fileFormat()) } };
    QSaveFile infoFile(path(".info"));
    if (!infoFile.open(QIODevice::WriteOnly) || infoFile.write(QJsonDocument(info).toJson()) < 0
        || !infoFile.commit())
        return Error { infoFile.errorString(), 0, infoFile.fileName() };
    return saveTableFile(tablePath(), m_document->table(), TableFormat::Json);
}

void AutoSave::removeCopy()
{
    if (!m_lock)
        return; // nothing was ever written
    QFile::remove(tablePath());
    QFile::remove(path(".info"));
}

QList<AutoSave::Session> AutoSave::findRecoverable(const QString &directory)
{
    QList<Session> sessions;
    const QDir dir(directory);
    // A session that died after taking its lock but before its first copy left a lock and perhaps an .info:
    // nothing to offer, so they go.
    for (const QFileInfo &lockInfo : dir.entryInfoList({ u"*.lock"_s }, QDir::Files)) {
        const QString id = lockInfo.completeBaseName();
        if (QFileInfo::exists(dir.filePath(id + u".json"_s)))
            continue;
        const auto lock = lockFile(lockInfo.filePath());
        if (lock->tryLock(0))
            removeSessionFiles(dir, id); // and the lock, as `lock` goes
    }
    const QFileInfoList copies = dir.entryInfoList({ u"*.json"_s }, QDir::Files, QDir::Time);
    for (const QFileInfo &copy : copies) {
        std::shared_ptr<QLockFile> lock = lockFile(withSuffix(copy.filePath(), u".lock"_s));
        if (!lock->tryLock(0))
            continue; // its Toffee is alive (this one, or another), or another has claimed it
        Session session;
        session.tablePath = copy.filePath();
        session.savedAt = copy.lastModified();
        session.lock = std::move(lock);
        QFile infoFile(withSuffix(copy.filePath(), u".info"_s));
        if (infoFile.open(QIODevice::ReadOnly)) {
            const QJsonObject info = QJsonDocument::fromJson(infoFile.readAll()).object();
            session.originalPath = info.value(u"original_path"_s).toString();
            session.originalFormat
                = formatFromName(info.value(u"original_format"_s).toString()).value_or(TableFormat::Json);
        }
        sessions.append(session);
    }
    return sessions;
}

Result<ToolTable> AutoSave::load(const Session &session)
{
    return loadTableFile(session.tablePath, TableFormat::Json);
}

void AutoSave::discard(const Session &session)
{
    const QFileInfo copy(session.tablePath);
    removeSessionFiles(copy.dir(), copy.completeBaseName());
    if (session.lock)
        session.lock->unlock(); // removes the lock file
}

} // namespace Toffee
