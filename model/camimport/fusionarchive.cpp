// SPDX-License-Identifier: GPL-3.0-or-later
// A Fusion .tools file: tools.json unpacked by the zip reader module (zipreader/), then read as Fusion's
// JSON.
#include <QDir>
#include <QFileInfo>
#include <QLibrary>

#include "model/camimport/camreaders.h"
#include "model/camimport/zipreader/zipentry.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// Beside the program's bin/, in lib/…/toffee: where it is installed, and where the build tree puts it too
// (every program and test there sits one folder below the top). A build tree's module is never taken by an
// installed program.
QString modulePath()
{
    const QString programDir = QFileInfo(u"/proc/self/exe"_s).canonicalPath();
    return QDir::cleanPath(programDir + QStringLiteral("/" TOFFEE_MODULE_RELATIVE_DIR "/")
        + QLatin1StringView(kZipReaderModule));
}

Result<ReadZipEntry> loadZipReader()
{
    const QString path = modulePath();
    if (!QFileInfo::exists(path))
        return Error { tr("Toffee's zip reader %1 is missing, so .tools archives cannot be read; reinstall "
                          "Toffee.")
                           .arg(path) };
    QLibrary module(path);
    // Kept loaded: QLibrary's object going out of scope does not unload it.
    if (auto read = reinterpret_cast<ReadZipEntry>(module.resolve(kReadZipEntrySymbol)))
        return read;
    return Error {
        tr("Toffee's zip reader %1 cannot be loaded (%2); reinstall Toffee.").arg(path, module.errorString())
    };
}

} // namespace

Result<ReadZipEntry> zipReader()
{
    static const Result<ReadZipEntry> reader = loadZipReader(); // once, also when asked from two threads
    return reader;
}

Result<QList<CamTool>> readFusionArchive(QByteArrayView zip)
{
    const auto read = zipReader();
    if (!read)
        return read.error();
    Result<ZipEntry> entry = Error { QString() };
    read.value()(zip, "tools.json"_L1, kMaxCamLibraryBytes, &entry);
    if (!entry)
        return entry.error();
    auto tools = readFusionJson(entry.value().data);
    if (!tools) {
        Error error = tools.error();
        error.file = entry.value().name;
        return error;
    }
    return tools;
}

} // namespace Toffee
