// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/document/autosave.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <sys/stat.h>

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QLockFile>
#include <QSet>
#include <QStandardPaths>
#include <QUuid>

#include "model/clock.h"
#include "model/document/tooldocument.h"
#include "model/formats/fileio.h"
#include "model/formats/jsonscanner.h"

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

// Entries of `dir` matching `pattern` whatever they are (files, links, FIFOs, devices): each is checked
// before anything reads it.
QFileInfoList entries(const QDir &dir, const QString &pattern)
{
    return dir.entryInfoList({ pattern },
        QDir::Files | QDir::Dirs | QDir::System | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

// Every file of session `id` but its lock: the copy, its .info, and any half-written temporary file QSaveFile
// left as the process died.
void removeSessionFiles(const QDir &dir, const QString &id)
{
    for (const QFileInfo &file : entries(dir, id + u".*"_s)) {
        if (file.suffix() != u"lock")
            QFile::remove(file.filePath());
    }
}

// A regular file itself, not a link to one: a recovery folder is Toffee's own, and a link in it was put
// there by something else.
bool isPlainFile(const QString &path)
{
    return isRegularFile(path, Links::NotFollowed);
}

// Where the edits belong, from the session's .info, checked like any input: a missing .info means a table
// never saved; one that is not a small regular file holding a JSON object with a sane path is broken.
bool readInfo(const QString &path, AutoSave::Session &session)
{
    struct stat info
    {
    };
    if (::lstat(QFile::encodeName(path).constData(), &info) != 0)
        return errno == ENOENT;
    if (!S_ISREG(info.st_mode))
        return false;
    const auto data = readRegularFile(path, AutoSave::kMaxInfoBytes);
    if (!data)
        return false;
    // A key twice is refused, not read as whichever of the two QJsonDocument keeps.
    JsonScanner scanner(data.value());
    Scalar whole;
    if (!scanner.value(whole) || !scanner.atEnd())
        return false;
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(data.value(), &error);
    if (error.error != QJsonParseError::NoError || !document.isObject())
        return false;
    const QJsonObject object = document.object();
    const QJsonValue original = object.value(u"original_path"_s);
    if (!original.isString() && !original.isUndefined())
        return false;
    const QString originalPath = original.toString();
    if (originalPath.size() > AutoSave::kMaxPathChars
        || (!originalPath.isEmpty()
            && (!QDir::isAbsolutePath(originalPath) || QDir::cleanPath(originalPath) != originalPath))
        || std::any_of(
            originalPath.cbegin(), originalPath.cend(), [](QChar c) { return c.unicode() < 0x20; }))
        return false;
    const auto format = formatFromName(object.value(u"original_format"_s).toString());
    if (!format && !originalPath.isEmpty())
        return false;
    session.originalPath = originalPath;
    session.originalFormat = format.value_or(TableFormat::Json);
    return true;
}

// Moves session `id`'s copy and .info (whatever they are, folders too; a link is moved, not followed), and
// its lock when `withLock`, into the quarantine folder under a name no later session reuses. Nothing is ever
// deleted here: when the quarantine folder cannot be made or a move fails, what is left stays where it is,
// and the answer is false.
bool quarantineFiles(const QDir &dir, const QString &id, bool withLock = false)
{
    const QString target = AutoSave::quarantineDirectory(dir.path());
    struct stat info
    {
    };
    if (!QDir().mkpath(target) || ::lstat(QFile::encodeName(target).constData(), &info) != 0
        || !S_ISDIR(info.st_mode))
        return false;
    const QString stamp = Clock::now().toString(u"yyyyMMdd-HHmmss"_s);
    bool moved = true;
    for (const QFileInfo &file : entries(dir, id + u".*"_s)) {
        if (file.suffix() == u"lock" && !withLock)
            continue;
        const QString to = target + u'/' + stamp + u'-' + file.fileName();
        moved = moved
            && ::rename(QFile::encodeName(file.filePath()).constData(), QFile::encodeName(to).constData())
                == 0;
    }
    return moved;
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
    const QByteArray infoText = QJsonDocument(info).toJson();
    if (auto written
        = writeFileAtomically(path(".info"), [&infoText](const FileSink &sink) { return sink(infoText); });
        !written)
        return written;
    return saveTableFile(tablePath(), m_document->table(), TableFormat::Json);
}

void AutoSave::removeCopy()
{
    if (!m_lock)
        return; // nothing was ever written
    QFile::remove(tablePath());
    QFile::remove(path(".info"));
}

QString AutoSave::quarantineDirectory(const QString &directory)
{
    return directory + u"/quarantine"_s;
}

QList<AutoSave::Session> AutoSave::findRecoverable(
    const QString &directory, QStringList *quarantined, QStringList *unmovable)
{
    QList<Session> sessions;
    const QDir dir(directory);
    QSet<QString> leftAlone; // sessions whose files could not be moved: nothing more is done to them
    const auto moveAway = [&](const QString &id, bool withLock) {
        if (quarantineFiles(dir, id, withLock)) {
            if (quarantined)
                quarantined->append(id);
            return;
        }
        leftAlone.insert(id);
        if (unmovable)
            unmovable->append(id);
    };
    // A lock that is not a plain file (a FIFO would block QLockFile's read) belongs to no Toffee.
    for (const QFileInfo &lockInfo : entries(dir, u"*.lock"_s)) {
        if (!isPlainFile(lockInfo.filePath()))
            moveAway(lockInfo.completeBaseName(), true);
    }
    // A session that died after taking its lock but before its first copy left a lock and perhaps an .info:
    // nothing to offer, so they go.
    for (const QFileInfo &lockInfo : entries(dir, u"*.lock"_s)) {
        const QString id = lockInfo.completeBaseName();
        if (leftAlone.contains(id) || QFileInfo(dir.filePath(id + u".json"_s)).isSymLink()
            || QFileInfo::exists(dir.filePath(id + u".json"_s)))
            continue;
        const auto lock = lockFile(lockInfo.filePath());
        if (lock->tryLock(0))
            removeSessionFiles(dir, id); // and the lock, as `lock` goes
    }
    QFileInfoList copies = entries(dir, u"*.json"_s);
    std::sort(copies.begin(), copies.end(), [](const QFileInfo &a, const QFileInfo &b) {
        return a.fileTime(QFileDevice::FileModificationTime) > b.fileTime(QFileDevice::FileModificationTime);
    });
    for (const QFileInfo &copy : copies) {
        const QString id = copy.completeBaseName();
        if (leftAlone.contains(id))
            continue;
        std::shared_ptr<QLockFile> lock = lockFile(withSuffix(copy.filePath(), u".lock"_s));
        if (!lock->tryLock(0))
            continue; // its Toffee is alive (this one, or another), or another has claimed it
        Session session;
        session.tablePath = copy.filePath();
        session.savedAt = copy.fileTime(QFileDevice::FileModificationTime);
        session.lock = std::move(lock);
        if (!isPlainFile(copy.filePath()) || !readInfo(withSuffix(copy.filePath(), u".info"_s), session)) {
            moveAway(id, false);
            continue; // `lock` goes with the session, and removes the lock file
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

bool AutoSave::quarantine(const Session &session)
{
    const QFileInfo copy(session.tablePath);
    const bool moved = quarantineFiles(copy.dir(), copy.completeBaseName());
    if (session.lock)
        session.lock->unlock();
    return moved;
}

} // namespace Toffee
