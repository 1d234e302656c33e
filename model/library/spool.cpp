// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/spool.h"

#include <sys/stat.h>

#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "model/clock.h"
#include "model/formats/fileio.h"
#include "model/library/library.h"
#include "model/library/outboxpayload.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr auto kFormat = "toffee-outbox"_L1;
constexpr int kVersion = 1;

} // namespace

Spool::Spool(QString folder)
    : m_folder(std::move(folder))
{ }

QString Spool::defaultFolder()
{
    return QFileInfo(LibraryLocation::standard().path).absoluteDir().filePath(u"outbox"_s);
}

QString Spool::folderFor(const LibraryLocation &target) const
{
    const QByteArray hash
        = QCryptographicHash::hash(target.identity().toUtf8(), QCryptographicHash::Sha256).toHex().left(16);
    return QDir(m_folder).filePath(u"library-"_s + QString::fromLatin1(hash));
}

Result<QString> Spool::keep(const LibraryLocation &target, const QList<HistoryEvent> &events) const
{
    if (events.isEmpty())
        return Error { tr("There is nothing to keep.") };
    const QString folder = folderFor(target);
    if (!QDir().mkpath(folder))
        return Error { tr("The folder %1 cannot be made, so nothing can be kept there.").arg(folder) };
    // Named by the time, to the millisecond, so that a listing is oldest first; the id keeps two apart.
    const QString name
        = Clock::now().toString(u"yyyyMMdd'T'HHmmsszzz"_s) + u'-' + HistoryEvent::newId() + u".json"_s;
    const QString path = QDir(folder).filePath(name);
    const QByteArray head = QJsonDocument(QJsonObject { { u"format"_s, QString(kFormat) },
                                              { u"version"_s, kVersion }, { u"library"_s, target.text() } })
                                .toJson(QJsonDocument::Compact);
    // {"format":…,"library":…,"version":1} with the events added as the last member.
    const QByteArray text = head.left(head.size() - 1) + ",\"events\":" + eventsPayload(events) + "}\n";
    if (auto written = writeFileAtomically(path, [&text](const FileSink &sink) { return sink(text); });
        !written)
        return written.error();
    return path;
}

Result<void> Spool::remove(const QString &path) const
{
    if (!QFile::remove(path) && QFileInfo::exists(path))
        return Error { tr("%1 was written to the library but cannot be removed from this computer; it will "
                          "be sent again, and the library will find it already there.")
                           .arg(path) };
    return {};
}

QStringList Spool::files(const LibraryLocation &target) const
{
    QStringList out;
    for (const QString &folder : { folderFor(target), m_folder }) {
        const QDir dir(folder);
        for (const QString &name :
            dir.entryList({ u"*.json"_s }, QDir::Files | QDir::System | QDir::Hidden, QDir::Name))
            out << dir.filePath(name);
    }
    return out;
}

Result<std::optional<Spool::Entry>> Spool::read(const QString &path) const
{
    auto data = readRegularFile(path, kMaxFileBytes);
    if (!data) {
        if (!QFileInfo::exists(path))
            return std::optional<Entry>(); // another sender took it meanwhile
        return data.error();
    }
    auto bad = [&path] {
        return Error { tr("%1 is not a measurement Toffee kept: it was changed or damaged.").arg(path) };
    };
    if (!hasNoDuplicateKeys(data.value()))
        return bad();
    const QJsonObject o = QJsonDocument::fromJson(data.value()).object();
    if (o.value(u"format"_s).toString() != kFormat || o.value(u"version"_s).toInt() != kVersion
        || !o.value(u"library"_s).isString() || !o.value(u"events"_s).isArray())
        return bad();
    // Each event alone: one the history cannot take goes to the quarantine, the others are sent.
    Entry entry { path, o.value(u"library"_s).toString(), {}, {}, {} };
    for (const QJsonValue &v : o.value(u"events"_s).toArray()) {
        if (auto e = eventFromJson(v)) {
            entry.events.append(e.takeValue());
        } else {
            entry.rejected.append(v);
            if (entry.why.isEmpty())
                entry.why = e.error().message;
        }
    }
    if (entry.events.isEmpty() && entry.rejected.isEmpty())
        return bad();
    return std::optional(entry);
}

qsizetype Spool::count(const LibraryLocation &target) const
{
    qsizetype n = 0;
    const QString identity = target.identity();
    for (const QString &path : files(target)) {
        auto entry = read(path);
        if (!entry || !entry.value())
            continue;
        const auto library = LibraryLocation::parse(entry.value()->library);
        if (library && library.value().identity() == identity)
            n += entry.value()->events.size();
    }
    return n;
}

void Spool::quarantine(const QString &path) const
{
    const QString folder = QDir(m_folder).filePath(u"quarantine"_s);
    if (!QDir().mkpath(folder))
        return; // left where it is: never deleted
    const QString to
        = QDir(folder).filePath(Clock::now().toString(u"yyyyMMdd-HHmmss-"_s) + QFileInfo(path).fileName());
    (void)::rename(QFile::encodeName(path).constData(), QFile::encodeName(to).constData());
}

bool Spool::quarantineRejected(const Entry &entry) const
{
    const QString folder = QDir(m_folder).filePath(u"quarantine"_s);
    if (!QDir().mkpath(folder))
        return false;
    const QString to = QDir(folder).filePath(QFileInfo(entry.path).completeBaseName() + u".rejected.json"_s);
    const QByteArray text = QJsonDocument(
        QJsonObject { { u"format"_s, QString(kFormat) }, { u"version"_s, kVersion },
            { u"library"_s, entry.library }, { u"why"_s, entry.why }, { u"events"_s, entry.rejected } })
                                .toJson(QJsonDocument::Compact);
    return bool(writeFileAtomically(to, [&text](const FileSink &sink) { return sink(text); }));
}

Result<Spool::Sent> Spool::send(
    Library &library, const std::function<void(const QList<HistoryEvent> &)> &written) const
{
    Sent sent;
    const LibraryLocation target = library.location();
    const QString identity = target.identity();
    // In batches of one transaction each, oldest first: a hundred files are one write, not a hundred.
    QStringList batch;
    QList<HistoryEvent> events;
    auto write = [&]() -> Result<void> {
        if (batch.isEmpty())
            return {};
        if (auto appended = library.append(events); !appended)
            return appended.error();
        for (const QString &path : std::as_const(batch)) {
            if (auto removed = remove(path); !removed)
                return removed;
        }
        sent.events += int(events.size());
        if (written)
            written(events);
        batch.clear();
        events.clear();
        return {};
    };
    for (const QString &path : files(target)) {
        auto entry = read(path);
        if (!entry) {
            sent.quarantined << entry.error().message + u' '
                    + tr("It was moved to %1.").arg(QDir(m_folder).filePath(u"quarantine"_s));
            quarantine(path);
            continue;
        }
        if (!entry.value())
            continue; // sent by another meanwhile
        const Entry &e = *entry.value();
        const auto library = LibraryLocation::parse(e.library);
        if (!library || library.value().identity() != identity)
            continue; // another library's, written at the top by an older Toffee
        if (!e.rejected.isEmpty()) {
            if (!quarantineRejected(e))
                continue; // kept whole where it is: never lost
            sent.quarantined << tr("%1 event(s) of %2 cannot go into the history (%3). They were moved to "
                                   "%4 apart; the file's other events are sent.")
                                    .arg(e.rejected.size())
                                    .arg(path, e.why, QDir(m_folder).filePath(u"quarantine"_s));
            if (e.events.isEmpty()) {
                (void)remove(path);
                continue;
            }
        }
        batch << path;
        events << e.events;
        if (events.size() >= kBatchEvents) {
            if (auto done = write(); !done)
                return done.error();
        }
    }
    if (auto done = write(); !done)
        return done.error();
    return sent;
}

} // namespace Toffee
