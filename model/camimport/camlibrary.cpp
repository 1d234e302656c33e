// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/camimport/camlibrary.h"

#include <unordered_map>

#include <QFile>
#include <QFileInfo>

#include "model/camimport/camreaders.h"
#include "model/formats/fileio.h"
#include "model/numberformat.h"
#include "model/toolvalidation.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// "tool 3 in "data" (T5)", "T5": how a message names a tool; its line, when it has one, is the Error's.
QString who(const CamTool &tool)
{
    const QString number = u"T"_s + QString::number(tool.number);
    return tool.place.isEmpty() ? number : tool.place + u" ("_s + number + u')';
}

Error refused(const CamTool &tool, const QString &reason)
{
    return Error { who(tool) + u": "_s + reason, tool.line };
}

// A value a library may leave out, but never give as negative.
Result<void> checkLength(const QString &what, const std::optional<double> &value, Units units)
{
    if (value && *value < 0)
        return Error {
            tr("%1 is %2 %3; it cannot be negative.").arg(what, quotedNumber(*value), unitsSymbol(units))
        };
    if (value)
        return validateLength(what, *value, kMaxMachineMillimetres, units);
    return {};
}

Result<void> checkValues(const CamTool &tool)
{
    if (auto r = validateToolNumber(tool.number); !r)
        return r;
    if (auto r = checkLength(tr("the diameter"), tool.diameter, tool.units); !r)
        return r;
    if (auto r = checkLength(tr("the flute length"), tool.fluteLength, tool.units); !r)
        return r;
    if (auto r = checkLength(tr("the length below the holder"), tool.stickOut, tool.units); !r)
        return r;
    return checkLength(tr("the overall length"), tool.overallLength, tool.units);
}

// A program may be gigabytes: only its beginning, where the header is, is read.
Result<QByteArray> readProgramHead(const QString &path, bool *complete)
{
    if (!isRegularFile(path)) {
        // Refused before a byte is read, with the reason readRegularFile gives (a FIFO, a folder, no file).
        auto refusal = readRegularFile(path, 0);
        return refusal.ok() ? Error { tr("%1: cannot open it.").arg(path) } : refusal.error();
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return Error { tr("%1: cannot open: %2").arg(path, file.errorString()) };
    QByteArray head = file.read(kMaxProgramHeaderBytes);
    *complete = file.atEnd();
    return head;
}

} // namespace

QString camFormatName(CamFormat format)
{
    switch (format) {
    case CamFormat::FusionJson:
        return tr("Fusion tool library (JSON)");
    case CamFormat::FusionArchive:
        return tr("Fusion tool library (.tools)");
    case CamFormat::HsmLibrary:
        return tr("HSM tool library (.hsmlib)");
    case CamFormat::MakeraProgram:
        return tr("Makera CAM program's tool header");
    }
    return {};
}

Result<QList<CamTool>> checkCamTools(QList<CamTool> tools)
{
    if (tools.isEmpty())
        return Error { tr("the library holds no tools; nothing to import.") };
    std::unordered_map<int, qsizetype> seen;
    for (qsizetype i = 0; i < tools.size(); ++i) {
        CamTool &tool = tools[i];
        if (auto r = checkValues(tool); !r)
            return refused(tool, r.error().message);
        if (const auto [at, added] = seen.emplace(tool.number, i); !added) {
            const CamTool &first = tools.at(at->second);
            return refused(tool,
                tr("number %1 is taken already (%2); each tool needs a number of its own.")
                    .arg(tool.number)
                    .arg(first.place.isEmpty() ? tr("line %1").arg(first.line) : first.place));
        }
        tool.description = tool.description.simplified();
    }
    return tools;
}

std::optional<CamFormat> camFormatForPath(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == u"json")
        return CamFormat::FusionJson;
    if (suffix == u"tools")
        return CamFormat::FusionArchive;
    if (suffix == u"hsmlib")
        return CamFormat::HsmLibrary;
    static const QStringList kPrograms
        = { u"nc"_s, u"gcode"_s, u"cnc"_s, u"ngc"_s, u"tap"_s, u"txt"_s, u"gc"_s, u"g"_s };
    if (kPrograms.contains(suffix))
        return CamFormat::MakeraProgram;
    return std::nullopt;
}

bool isToffeeTable(QByteArrayView json)
{
    // A Toffee table names its format at the top level; a CAM library never has that member. Quotes inside
    // a JSON string are escaped, so a description mentioning it does not match.
    static constexpr QByteArrayView kKey = "\"format\"";
    static constexpr QByteArrayView kValue = "\"toffee-tool-table\"";
    auto skipBlanks = [&json](qsizetype at) {
        while (at < json.size()
            && (json.at(at) == ' ' || json.at(at) == '\t' || json.at(at) == '\r' || json.at(at) == '\n'))
            ++at;
        return at;
    };
    for (qsizetype at = json.indexOf(kKey); at >= 0; at = json.indexOf(kKey, at + 1)) {
        qsizetype next = skipBlanks(at + kKey.size());
        if (next >= json.size() || json.at(next) != ':')
            continue;
        next = skipBlanks(next + 1);
        if (json.sliced(next).startsWith(kValue))
            return true;
    }
    return false;
}

bool isCamLibraryFile(const QString &path)
{
    const auto format = camFormatForPath(path);
    if (format != CamFormat::FusionJson)
        return format.has_value();
    // A .json too large or unreadable for a CAM library goes to the table reader, which says why.
    const auto data = readRegularFile(path, kMaxCamLibraryBytes);
    return data.ok() && !isToffeeTable(data.value());
}

Result<CamLibrary> loadCamLibrary(const QString &path)
{
    const auto format = camFormatForPath(path);
    if (!format)
        return Error { tr("%1: not a CAM tool library Toffee reads (.json, .tools, .hsmlib, or a G-code "
                          "program with Makera CAM's tool header).")
                           .arg(path) };
    bool complete = true;
    auto data = *format == CamFormat::MakeraProgram ? readProgramHead(path, &complete)
                                                    : readRegularFile(path, kMaxCamLibraryBytes);
    if (!data)
        return data.error();
    Result<QList<CamTool>> tools = Error {};
    switch (*format) {
    case CamFormat::FusionJson:
        tools = readFusionJson(data.value());
        break;
    case CamFormat::FusionArchive:
        tools = readFusionArchive(data.value());
        break;
    case CamFormat::HsmLibrary:
        tools = readHsmLibrary(data.value());
        break;
    case CamFormat::MakeraProgram:
        tools = readMakeraHeader(data.value(), complete);
        break;
    }
    if (!tools) {
        Error error = tools.error();
        // An archive's reader names the entry at fault; the file goes before it.
        error.file = error.file.isEmpty() ? path : path + u": "_s + error.file;
        return error;
    }
    return CamLibrary { path, *format, tools.takeValue() };
}

} // namespace Toffee
