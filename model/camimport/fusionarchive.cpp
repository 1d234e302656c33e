// SPDX-License-Identifier: GPL-3.0-or-later
// A Fusion .tools file: tools.json unpacked by the zip reader module (zipreader/), then read as Fusion's
// JSON.
#include "model/camimport/camreaders.h"
#include "model/camimport/zipreader/zipentry.h"
#include "model/modules.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// The module's function; resolved at each read, which costs microseconds against the archive's unpacking, so
// a module put back is found without a restart.
Result<ReadZipEntry> zipReader()
{
    const auto function = resolveInModule(QLatin1StringView(kZipReaderModule), kReadZipEntrySymbol);
    if (function)
        return reinterpret_cast<ReadZipEntry>(function.value());
    if (function.error().code == kModuleMissing)
        return Error { tr("Toffee's zip reader %1 is missing, so .tools archives cannot be read; reinstall "
                          "Toffee.")
                           .arg(function.error().file) };
    return Error { tr("Toffee's zip reader %1 cannot be loaded (%2); reinstall Toffee.")
                       .arg(function.error().file, function.error().message) };
}

} // namespace

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
