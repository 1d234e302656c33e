// SPDX-License-Identifier: GPL-3.0-or-later
// toffee_zipreader, the module that reads a Fusion .tools file: a zip archive holding the JSON library as
// tools.json. It is read from memory with libzip; what it unpacks to is capped as it is unpacked, whatever
// the archive claims, so that a small archive cannot fill memory. Loaded when a .tools file is first read
// (zipentry.h says why).
#include <memory>

#include <zip.h>

#include "model/camimport/zipreader/zipentry.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

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

Error tooLarge(const QString &entry, qint64 limit)
{
    return Error {
        tr("it unpacks to more than %1 MB; Toffee reads libraries of at most %1 MB.").arg(megabytes(limit)),
        0, entry
    };
}

// What libzip's error means for a .tools file: its own words describe libzip's state, not the file ("File
// already exists" for two entries of one name, "Zip archive inconsistent" for a damaged directory).
QString problem(zip_error_t *error)
{
    switch (zip_error_code_zip(error)) {
    case ZIP_ER_NOZIP:
        return tr("it is not a zip archive, or one cut short (there is no zip directory at its end)");
    case ZIP_ER_EXISTS:
        return tr("two of its entries have the same name, so it cannot be told which one is meant");
    case ZIP_ER_INCONS:
        return tr("the archive is damaged (its directory and its entries disagree)");
    case ZIP_ER_MULTIDISK:
        return tr("it is one part of an archive split over several files");
    case ZIP_ER_CRC:
        return tr("the archive is damaged (what it unpacks to fails its checksum)");
    case ZIP_ER_COMPNOTSUPP:
        return tr("it is compressed in a way Toffee cannot unpack (Fusion's own archives use deflate)");
    case ZIP_ER_ENCRNOTSUPP:
    case ZIP_ER_NOPASSWD:
    case ZIP_ER_WRONGPASSWD:
        return tr("it is encrypted; Toffee reads archives without a password");
    case ZIP_ER_ZLIB:
    case ZIP_ER_COMPRESSED_DATA:
        return tr("its compressed data is damaged");
    case ZIP_ER_EOF:
    case ZIP_ER_READ:
        return tr("the archive is truncated (it ends early)");
    case ZIP_ER_MEMORY:
        return tr("there is not enough memory to unpack it");
    default:
        return tr("libzip says: %1").arg(QString::fromLocal8Bit(zip_error_strerror(error)));
    }
}

Result<Archive> open(QByteArrayView zip)
{
    zip_error_t error;
    zip_error_init(&error);
    // The buffer is not copied: `zip` outlives the archive, which is discarded before the reader returns.
    zip_source_t *source = zip_source_buffer_create(zip.data(), zip_uint64_t(zip.size()), 0, &error);
    zip_t *archive = source ? zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error) : nullptr;
    if (!archive) {
        const QString reason = problem(&error);
        zip_error_fini(&error);
        if (source)
            zip_source_free(source);
        return Error { tr("this is not a .tools archive Toffee can read: %1.").arg(reason) };
    }
    zip_error_fini(&error);
    return Archive(archive);
}

// The entry's bytes, at most `limit` of them; libzip checks the CRC at the end.
Result<QByteArray> unpack(zip_t *archive, zip_int64_t index, const QString &name, qint64 limit)
{
    zip_stat_t stat;
    zip_stat_init(&stat);
    if (zip_stat_index(archive, zip_uint64_t(index), 0, &stat) == 0 && (stat.valid & ZIP_STAT_SIZE)
        && stat.size > zip_uint64_t(limit))
        return tooLarge(name, limit);
    Entry file(zip_fopen_index(archive, zip_uint64_t(index), 0));
    if (!file)
        return Error { tr("it cannot be unpacked: %1.").arg(problem(zip_get_error(archive))), 0, name };
    QByteArray data;
    char buffer[64 * 1024];
    while (true) {
        const zip_int64_t n = zip_fread(file.get(), buffer, sizeof buffer);
        if (n < 0)
            return Error { tr("it cannot be unpacked: %1.").arg(problem(zip_file_get_error(file.get()))), 0,
                name };
        if (n == 0)
            break;
        if (data.size() + n > limit)
            return tooLarge(name, limit);
        data.append(buffer, qsizetype(n));
    }
    return data;
}

// The entry that is `wanted` (tools.json) in any case and folder, or -1. Two of them are refused: which one
// Fusion would read cannot be told, and taking either silently could import the wrong library.
Result<zip_int64_t> entryIndex(zip_t *archive, QLatin1StringView wanted)
{
    zip_int64_t found = -1;
    const zip_int64_t count = zip_get_num_entries(archive, 0);
    for (zip_int64_t i = 0; i < count; ++i) {
        const char *raw = zip_get_name(archive, zip_uint64_t(i), ZIP_FL_ENC_GUESS);
        const QString name = raw ? QString::fromUtf8(raw) : QString();
        if (name.section(u'/', -1).compare(wanted, Qt::CaseInsensitive) != 0)
            continue;
        if (found >= 0)
            return Error { tr("the archive holds %1 twice (%2 and %3); Toffee will not guess which one is "
                              "the library.")
                               .arg(wanted,
                                   excerpt(QString::fromUtf8(
                                       zip_get_name(archive, zip_uint64_t(found), ZIP_FL_ENC_GUESS))),
                                   excerpt(name)) };
        found = i;
    }
    return found;
}

Result<ZipEntry> readEntry(QByteArrayView zip, QLatin1StringView wanted, qint64 limit)
{
    // libzip takes no bytes at all for an archive with nothing in it.
    if (zip.isEmpty())
        return Error { tr("this is not a .tools archive: the file is empty.") };
    auto archive = open(zip);
    if (!archive)
        return archive.error();
    const auto index = entryIndex(archive.value().get(), wanted);
    if (!index)
        return index.error();
    if (index.value() < 0)
        return Error { tr(
            "the archive holds no %1; a Fusion .tools file is a zip archive with the library in "
            "%1.")
                           .arg(wanted) };
    const char *entryName
        = zip_get_name(archive.value().get(), zip_uint64_t(index.value()), ZIP_FL_ENC_GUESS);
    const QString name = entryName ? QString::fromUtf8(entryName) : QString(wanted);
    auto data = unpack(archive.value().get(), index.value(), name, limit);
    if (!data)
        return data.error();
    return ZipEntry { name, data.value() };
}

} // namespace

} // namespace Toffee

// The module's one export (zipentry.h: ReadZipEntry).
extern "C" Q_DECL_EXPORT void toffee_read_zip_entry(
    QByteArrayView zip, QLatin1StringView wanted, qint64 limit, Toffee::Result<Toffee::ZipEntry> *out)
{
    *out = Toffee::readEntry(zip, wanted, limit);
}
