// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/spool.h"

#include <sys/stat.h>

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

Result<QString> Spool::keep(const LibraryLocation &target, const QList<HistoryEvent> &events) const
{
    if (!QDir().mkpath(m_folder))
        return Error { tr("The folder %1 cannot be made, so nothing can be kept there.").arg(m_folder) };
    // Named by the time, to the millisecond, so that a listing is oldest first; the id keeps two apart.
    const QString name
        = Clock::now().toString(u"yyyyMMdd'T'HHmmsszzz"_s) + u'-' + HistoryEvent::newId() + u".json"_s;
    const QString path = QDir(m_folder).filePath(name);
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

QStringList Spool::files() const
{
    QStringList out;
    const QDir dir(m_folder);
    for (const QString &name :
        dir.entryList({ u"*.json"_s }, QDir::Files | QDir::System | QDir::Hidden, QDir::Name))
        out << dir.filePath(name);
    return out;
}

Result<Spool::Entry> Spool::read(const QString &path) const
{
    auto data = readRegularFile(path, kMaxFileBytes);
    if (!data)
        return data.error();
    auto bad = [&path] {
        return Error { tr("%1 is not a measurement Toffee kept: it was changed or damaged.").arg(path) };
    };
    if (!hasNoDuplicateKeys(data.value()))
        return bad();
    const QJsonObject o = QJsonDocument::fromJson(data.value()).object();
    if (o.value(u"format"_s).toString() != kFormat || o.value(u"version"_s).toInt() != kVersion
        || !o.value(u"library"_s).isString() || !o.value(u"events"_s).isArray())
        return bad();
    auto events = eventsFromJson(o.value(u"events"_s).toArray());
    if (!events || events.value().isEmpty())
        return bad();
    return Entry { path, o.value(u"library"_s).toString(), events.takeValue() };
}

qsizetype Spool::count(const LibraryLocation &target) const
{
    qsizetype n = 0;
    const QString library = target.text();
    for (const QString &path : files()) {
        if (auto entry = read(path); entry && entry.value().library == library)
            n += entry.value().events.size();
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

Result<Spool::Sent> Spool::send(
    Library &library, const std::function<void(const QList<HistoryEvent> &)> &written) const
{
    Sent sent;
    const QString target = library.location().text();
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
    for (const QString &path : files()) {
        auto entry = read(path);
        if (!entry) {
            sent.quarantined << entry.error().message;
            quarantine(path);
            continue;
        }
        if (entry.value().library != target)
            continue; // another library's
        batch << path;
        events << entry.value().events;
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
