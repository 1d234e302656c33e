// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/formats/fileio.h"
#include "model/numberformat.h"
#include "model/translate.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

namespace Toffee {

namespace {

QString systemError(int error)
{
    return QString::fromLocal8Bit(std::strerror(error));
}

// Why `mode` is not a file Toffee reads or writes, or nothing when it is a regular file.
QString notAFile(mode_t mode)
{
    if (S_ISREG(mode))
        return {};
    if (S_ISFIFO(mode))
        return tr("it is a named pipe (FIFO), not a file; Toffee opens only regular files.");
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return tr("it is a device, not a file; Toffee opens only regular files.");
    if (S_ISDIR(mode))
        return tr("it is a folder, not a file.");
    if (S_ISSOCK(mode))
        return tr("it is a socket, not a file; Toffee opens only regular files.");
    return tr("it is not a regular file; Toffee opens only regular files.");
}

Error readError(const QString &path, const QString &reason)
{
    return Error { tr("%1: cannot open: %2").arg(path, reason) };
}

QString megabytes(qint64 bytes)
{
    const int decimals = bytes < 10 * 1024 * 1024 ? 1 : 0;
    return formatNumber(double(bytes) / (1024.0 * 1024.0), NumberFormat::fixed(decimals));
}

Error tooLarge(const QString &path, qint64 size, qint64 maxBytes)
{
    return Error { tr("%1: the file is %2 MB; Toffee reads files of at most %3 MB.")
                       .arg(path, megabytes(size), megabytes(maxBytes)) };
}

// A file built into the application (Qt's resource system): Toffee's own, never special.
Result<QByteArray> readResource(const QString &path, qint64 maxBytes)
{
    QFile resource(path);
    if (!resource.open(QIODevice::ReadOnly))
        return readError(path, resource.errorString());
    if (resource.size() > maxBytes)
        return tooLarge(path, resource.size(), maxBytes);
    return resource.readAll();
}

// Reads `fd` to the end, never past maxBytes: the file may grow while it is read. `size`: its size before.
Result<QByteArray> readToEnd(int fd, qint64 size, const QString &path, qint64 maxBytes)
{
    QByteArray data;
    data.resize(qsizetype(size));
    qsizetype used = 0;
    while (true) {
        if (used == data.size()) {
            if (data.size() > maxBytes)
                return tooLarge(path, data.size(), maxBytes);
            data.resize(std::min<qsizetype>(std::max<qsizetype>(data.size() * 2, 4096), maxBytes + 1));
        }
        const ssize_t n = ::read(fd, data.data() + used, size_t(data.size() - used));
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return Error { tr("%1: cannot read: %2").arg(path, systemError(errno)) };
        }
        if (n == 0)
            break;
        used += n;
    }
    if (used > maxBytes)
        return tooLarge(path, used, maxBytes);
    data.resize(used);
    return data;
}

QString sentence(QString reason)
{
    if (!reason.isEmpty() && !reason.endsWith(u'.'))
        reason += u'.';
    return reason;
}

// A save that failed says what became of the file: an old one is unchanged, else nothing was written.
Error saveFailure(const QString &path, bool existed, const QString &reason)
{
    return Error { existed ? tr("%1: cannot save: %2 The old file is unchanged.").arg(path, reason)
                           : tr("%1: cannot save: %2 Nothing was written.").arg(path, reason) };
}

// Why QSaveFile could not open `path`: the system's reason (a read-only file system, no permission) says more
// than QSaveFile's.
QString openFailure(const QSaveFile &file, const QString &path, const QString &folder, bool existed)
{
    if (existed && ::access(QFile::encodeName(path).constData(), W_OK) != 0)
        return sentence(systemError(errno));
    if (::access(QFile::encodeName(folder).constData(), W_OK) != 0)
        return sentence(tr("%1: %2").arg(folder, systemError(errno)));
    return sentence(file.errorString());
}

bool writeWhole(QSaveFile &file, QByteArrayView piece, QString &writeError)
{
    qsizetype done = 0;
    while (done < piece.size()) {
        // A short write is retried: the retry reports why (ENOSPC, EDQUOT, EFBIG).
        const qint64 n = file.write(piece.data() + done, piece.size() - done);
        if (n <= 0) {
            writeError = file.errorString();
            return false;
        }
        done += n;
    }
    return true;
}

// The producer's pieces into `file`; false, with why in `reason`, when one could not be written or the
// producer gave up.
bool produceInto(QSaveFile &file, const FileProducer &produce, const QString *producerError, QString &reason)
{
    QString writeError;
    if (produce([&file, &writeError](QByteArrayView piece) { return writeWhole(file, piece, writeError); }))
        return true;
    if (!writeError.isEmpty())
        reason = sentence(writeError);
    else
        reason = sentence(producerError ? *producerError : tr("the file could not be written"));
    return false;
}

// Puts the written file in place of the old one; false, with why in `reason`, when that failed.
bool syncAndCommit(QSaveFile &file, QString &reason)
{
    // QSaveFile::commit() syncs but does not say whether the sync worked; a disk that fills as delayed
    // allocation meets it (or a network file system) reports it only here.
    if (::fsync(file.handle()) != 0) {
        const int error = errno;
        file.cancelWriting();
        reason = sentence(systemError(error));
        return false;
    }
    if (!file.commit()) {
        reason = sentence(file.errorString());
        return false;
    }
    return true;
}

} // namespace

bool isRegularFile(const QString &path, Links links)
{
    struct stat info
    {
    };
    const QByteArray native = QFile::encodeName(path);
    const int found
        = links == Links::Followed ? ::stat(native.constData(), &info) : ::lstat(native.constData(), &info);
    return found == 0 && S_ISREG(info.st_mode);
}

Result<OpenFile> openRegularFile(const QString &path)
{
    if (path.isEmpty())
        return Error { tr("no file name was given.") };
    const QByteArray native = QFile::encodeName(path);
    // stat() first: opening a FIFO for reading would block until a writer came, and a device would never end.
    struct stat before
    {
    };
    if (::stat(native.constData(), &before) != 0)
        return readError(path, systemError(errno));
    if (const QString why = notAFile(before.st_mode); !why.isEmpty())
        return readError(path, why);
    // O_NONBLOCK: should the name be swapped for a FIFO between stat() and open(), open() still returns at
    // once, and fstat() below refuses it.
    OpenFile file;
    file.fd = ::open(native.constData(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (file.fd < 0)
        return readError(path, systemError(errno));
    struct stat info
    {
    };
    if (::fstat(file.fd, &info) != 0)
        return readError(path, systemError(errno));
    if (const QString why = notAFile(info.st_mode); !why.isEmpty())
        return readError(path, why);
    file.size = info.st_size;
    return file;
}

OpenFile::~OpenFile()
{
    if (fd >= 0)
        ::close(fd);
}

OpenFile::OpenFile(OpenFile &&other) noexcept
    : fd(std::exchange(other.fd, -1))
    , size(other.size)
{ }

Result<qint64> readSome(const OpenFile &file, char *into, qint64 bytes, const QString &path)
{
    while (true) {
        const ssize_t n = ::read(file.fd, into, size_t(bytes));
        if (n >= 0)
            return qint64(n);
        if (errno != EINTR)
            return Error { tr("%1: cannot read: %2").arg(path, systemError(errno)) };
    }
}

Result<QByteArray> readRegularFile(const QString &path, qint64 maxBytes)
{
    if (path.startsWith(u':'))
        return readResource(path, maxBytes);
    auto file = openRegularFile(path);
    if (!file)
        return file.error();
    if (file.value().size > maxBytes)
        return tooLarge(path, file.value().size, maxBytes);
    return readToEnd(file.value().fd, file.value().size, path, maxBytes);
}

Result<void> writeFileAtomically(
    const QString &path, const FileProducer &produce, const QString *producerError)
{
    struct stat existing
    {
    };
    const bool existed = ::stat(QFile::encodeName(path).constData(), &existing) == 0;
    if (existed) {
        // Nothing is written over what is not a file, and there is no "old file" to speak of.
        if (const QString why = notAFile(existing.st_mode); !why.isEmpty())
            return Error { tr("%1: cannot save: %2").arg(path, why) };
    }
    const QString folder = QFileInfo(path).absolutePath();
    if (!QFileInfo(folder).isDir())
        return saveFailure(path, existed, tr("the folder %1 does not exist.").arg(folder));

    QSaveFile file(path);
    file.setDirectWriteFallback(false);
    // Unbuffered: each write reaches the system at once and its failure is seen here, not lost in a flush.
    if (!file.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return saveFailure(path, existed, openFailure(file, path, folder, existed));
    QString reason;
    if (!produceInto(file, produce, producerError, reason)) {
        file.cancelWriting();
        return saveFailure(path, existed, reason);
    }
    if (!syncAndCommit(file, reason))
        return saveFailure(path, existed, reason);
    return {};
}

} // namespace Toffee
