// SPDX-License-Identifier: GPL-3.0-or-later
// Every file Toffee reads or writes goes through these two: a file is input like any other, and a save that
// cannot complete must never look as if it had.
#pragma once

#include <functional>

#include <QByteArray>
#include <QString>

#include "model/result.h"

namespace Toffee {

// The whole of `path`, which must be a regular file (or a link to one) of at most `maxBytes`. Anything else
// (a FIFO, a device such as /dev/zero, a folder, a socket, a link that loops) is refused by name before a
// byte is read, so that it can neither block nor fill memory. Error messages begin with the path. A path
// beginning with ':' is one of the application's own resources.
[[nodiscard]] Result<QByteArray> readRegularFile(const QString &path, qint64 maxBytes);

// A regular file open for reading, closed when it goes: its descriptor and its size when it was opened.
struct OpenFile
{
    OpenFile() = default;
    OpenFile(OpenFile &&other) noexcept;
    OpenFile &operator=(OpenFile &&) = delete;
    ~OpenFile();
    int fd = -1;
    qint64 size = 0;
};

// Opens `path` for reading on the same terms as readRegularFile (a regular file, refused by name otherwise),
// for a reader that streams it (LineReader).
[[nodiscard]] Result<OpenFile> openRegularFile(const QString &path);
// Up to `bytes` of `file` into `into`: how many, 0 at its end.
[[nodiscard]] Result<qint64> readSome(const OpenFile &file, char *into, qint64 bytes, const QString &path);

// Whether `path` is a regular file: through a link to one, or (`Links::NotFollowed`) only the name itself.
enum class Links { Followed, NotFollowed };
[[nodiscard]] bool isRegularFile(const QString &path, Links links = Links::Followed);

// Hands the file's contents to a sink in pieces; the producer stops (returning false) when the sink does.
using FileSink = std::function<bool(QByteArrayView piece)>;
using FileProducer = std::function<bool(const FileSink &sink)>;

// Writes `path` whole or not at all: through a temporary file that replaces it only once every byte is
// written and flushed to the disk. A save that cannot complete (a full disk, a quota, a file-size limit, a
// read-only folder) fails with the system's own reason and leaves the old file byte for byte as it was.
// A producer that gives up of its own accord passes its reason in `*producerError`.
[[nodiscard]] Result<void> writeFileAtomically(
    const QString &path, const FileProducer &produce, const QString *producerError = nullptr);

} // namespace Toffee
