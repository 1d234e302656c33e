// SPDX-License-Identifier: GPL-3.0-or-later
// A Fusion .tools file: a zip archive holding the JSON library as tools.json. It is read from memory with
// libzip; what it unpacks to is capped as it is unpacked, whatever the archive claims, so that a small
// archive cannot fill memory.
#include <memory>

#include <zip.h>

#include "model/camimport/camreaders.h"
#include "model/numberformat.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr char kEntry[] = "tools.json";

struct ArchiveCloser
{
    void operator()(zip_t *archive) const { zip_discard(archive); }
};
struct EntryCloser
{
    void operator()(zip_file_t *file) const { zip_fclose(file); }
};
using Archive = std::unique_ptr<zip_t, ArchiveCloser>;
using Entry = std::unique_ptr<zip_file_t, EntryCloser>;

QString megabytes(qint64 bytes)
{
    return formatNumber(double(bytes) / (1024.0 * 1024.0), NumberFormat::upTo(1));
}

Error tooLarge(const QString &entry)
{
    return Error { tr("it unpacks to more than %1 MB; Toffee reads libraries of at most %1 MB.")
                       .arg(megabytes(kMaxCamLibraryBytes)),
        0, entry };
}

Result<Archive> open(QByteArrayView zip)
{
    zip_error_t error;
    zip_error_init(&error);
    // The buffer is not copied: `zip` outlives the archive, which is discarded before the reader returns.
    zip_source_t *source = zip_source_buffer_create(zip.data(), zip_uint64_t(zip.size()), 0, &error);
    zip_t *archive = source ? zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error) : nullptr;
    if (!archive) {
        const QString reason = QString::fromLocal8Bit(zip_error_strerror(&error));
        zip_error_fini(&error);
        if (source)
            zip_source_free(source);
        return Error {
            tr("this is not a .tools archive: a zip archive could not be read from it (%1).").arg(reason)
        };
    }
    zip_error_fini(&error);
    return Archive(archive);
}

// The entry's bytes, at most kMaxCamLibraryBytes of them; libzip checks the CRC at the end.
Result<QByteArray> unpack(zip_t *archive, zip_int64_t index, const QString &name)
{
    zip_stat_t stat;
    zip_stat_init(&stat);
    if (zip_stat_index(archive, zip_uint64_t(index), 0, &stat) == 0 && (stat.valid & ZIP_STAT_SIZE)
        && stat.size > zip_uint64_t(kMaxCamLibraryBytes))
        return tooLarge(name);
    Entry file(zip_fopen_index(archive, zip_uint64_t(index), 0));
    if (!file)
        return Error { tr("it cannot be unpacked: %1.").arg(QString::fromLocal8Bit(zip_strerror(archive))), 0,
            name };
    QByteArray data;
    char buffer[64 * 1024];
    while (true) {
        const zip_int64_t n = zip_fread(file.get(), buffer, sizeof buffer);
        if (n < 0)
            return Error { tr("it cannot be unpacked: %1; the archive is damaged or truncated.")
                               .arg(QString::fromLocal8Bit(zip_file_strerror(file.get()))),
                0, name };
        if (n == 0)
            break;
        if (data.size() + n > kMaxCamLibraryBytes)
            return tooLarge(name);
        data.append(buffer, qsizetype(n));
    }
    return data;
}

} // namespace

Result<QList<CamTool>> readFusionArchive(QByteArrayView zip)
{
    // libzip takes no bytes at all for an archive with nothing in it.
    if (zip.isEmpty())
        return Error { tr("this is not a .tools archive: the file is empty.") };
    auto archive = open(zip);
    if (!archive)
        return archive.error();
    const zip_int64_t index = zip_name_locate(archive.value().get(), kEntry, ZIP_FL_NOCASE | ZIP_FL_NODIR);
    if (index < 0)
        return Error { tr(
            "the archive holds no %1; a Fusion .tools file is a zip archive with the library in "
            "%1.")
                           .arg(QLatin1StringView(kEntry)) };
    const char *entryName = zip_get_name(archive.value().get(), zip_uint64_t(index), ZIP_FL_ENC_GUESS);
    const QString name = entryName ? QString::fromUtf8(entryName) : QString::fromLatin1(kEntry);
    auto json = unpack(archive.value().get(), index, name);
    if (!json)
        return json.error();
    auto tools = readFusionJson(json.value());
    if (!tools) {
        Error error = tools.error();
        error.file = name;
        return error;
    }
    return tools;
}

} // namespace Toffee
