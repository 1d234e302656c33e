// SPDX-License-Identifier: GPL-3.0-or-later
// What the zip reader module (toffee_zipreader, on libzip) hands back, and the one function it exports. The
// module is loaded the first time a .tools archive is read, so that the window and toffee-cli do not load
// libzip and what it links (libcrypto among them) at every start: issue 16's start-up.
#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include "model/result.h"

namespace Toffee {

// The entry that was asked for: its name in the archive and its bytes.
struct ZipEntry
{
    QString name;
    QByteArray data;
};

// toffee_read_zip_entry(zip, wanted, limit, out): the entry whose name, in any folder and any case, is
// `wanted`, unpacked to at most `limit` bytes; or why not, in words for an operator.
using ReadZipEntry
    = void (*)(QByteArrayView zip, QLatin1StringView wanted, qint64 limit, Result<ZipEntry> *out);
inline constexpr char kReadZipEntrySymbol[] = "toffee_read_zip_entry";

// The module's file name; model/modules.h says where it is looked for.
inline constexpr char kZipReaderModule[] = "toffee_zipreader.so";

} // namespace Toffee
