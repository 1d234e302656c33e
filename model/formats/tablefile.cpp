// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/formats/tablefile.h"

#include <new>
#include <optional>

#include <QCoreApplication>
#include <QFileInfo>

#include "model/formats/fileio.h"
#include "model/textparsing.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace { } // namespace

std::optional<TableFormat> formatForPath(const QString &path)
{
    return formatFromName(QFileInfo(path).suffix());
}

std::optional<TableFormat> formatFromName(QStringView name)
{
    const QString n = name.toString().toLower();
    if (n == u"json")
        return TableFormat::Json;
    if (n == u"tbl" || n == u"linuxcnc")
        return TableFormat::LinuxCnc;
    if (n == u"csv")
        return TableFormat::Csv;
    return std::nullopt;
}

QString formatName(TableFormat format)
{
    switch (format) {
    case TableFormat::Json:
        return tr("Toffee tool table (JSON)");
    case TableFormat::LinuxCnc:
        return tr("LinuxCNC tool table");
    case TableFormat::Csv:
        return tr("CSV spreadsheet");
    }
    return {};
}

QString formatSuffix(TableFormat format)
{
    switch (format) {
    case TableFormat::Json:
        return u"json"_s;
    case TableFormat::LinuxCnc:
        return u"tbl"_s;
    case TableFormat::Csv:
        return u"csv"_s;
    }
    return {};
}

Result<ToolTable> readTable(const QByteArray &data, TableFormat format, Units tblUnits)
{
    switch (format) {
    case TableFormat::Json:
        return readJsonTable(data);
    case TableFormat::LinuxCnc:
        return readLinuxCncTable(data, tblUnits);
    case TableFormat::Csv:
        return readCsvTable(data);
    }
    return Error { tr("unknown table format.") };
}

QByteArray writeTable(const ToolTable &table, TableFormat format)
{
    switch (format) {
    case TableFormat::Json:
        return writeJsonTable(table);
    case TableFormat::LinuxCnc:
        return writeLinuxCncTable(table);
    case TableFormat::Csv:
        return writeCsvTable(table);
    }
    return {};
}

bool writeTable(const ToolTable &table, TableFormat format, const ByteSink &sink)
{
    switch (format) {
    case TableFormat::Json:
        return writeJsonTable(table, sink);
    case TableFormat::LinuxCnc:
        return writeLinuxCncTable(table, sink);
    case TableFormat::Csv:
        return writeCsvTable(table, sink);
    }
    return false;
}

QStringList formatLosses(const ToolTable &table, TableFormat format)
{
    if (format != TableFormat::LinuxCnc)
        return {};
    bool wear = false;
    bool tlo = false;
    bool notes = false;
    bool life = false;
    bool cutter = false;
    bool probing = false;
    QStringList broken;
    for (const Tool &tool : table.tools()) {
        if (tool.breakTestFailed)
            broken << u"T"_s + QString::number(tool.number);
        wear = wear || tool.lengthWear != 0.0 || tool.radiusWear != 0.0;
        tlo = tlo || tool.measuredTlo.has_value();
        notes = notes || !tool.notes.isEmpty();
        life = life || tool.lifeLimitMinutes || tool.lifeLimitUses;
        cutter = cutter || !tool.cutterType.isEmpty() || tool.overallLength;
        probing = probing || tool.flutes || !tool.probing.isDefault();
    }
    QStringList losses;
    if (!broken.isEmpty())
        losses << tr("A LinuxCNC table cannot mark a tool that failed its break test: %1 would no longer be "
                     "marked.")
                      .arg(broken.join(u", "_s));
    if (wear)
        losses << tr("A LinuxCNC table has no wear columns: wear is added into the length and diameter.");
    if (tlo)
        losses << tr("A LinuxCNC table has no place for measured TLOs: they are not saved.");
    if (notes)
        losses << tr("A LinuxCNC table has no place for notes: they are not saved.");
    if (life)
        losses << tr("A LinuxCNC table has no place for tool life limits: they are not saved.");
    if (cutter)
        losses << tr("A LinuxCNC table has no place for the cutter's type and overall length: they are not "
                     "saved, and an import can then tell a new cutter only by its diameter.");
    if (probing)
        losses << tr("A LinuxCNC table has no place for how a tool is probed (its edges, touches, touch-off "
                     "point, latch feed and spread limit): they are not saved, and each tool is then probed "
                     "once at the setter's centre.");
    if (table.units() == Units::Inch)
        losses << tr("A LinuxCNC table does not record its units: the numbers are written in inches.");
    return losses;
}

Result<ToolTable> loadTableFile(const QString &path, std::optional<TableFormat> format, Units tblUnits)
{
    if (!format)
        format = formatForPath(path);
    if (!format)
        return Error { tr("%1: unknown file type; use a .json, .tbl or .csv file.").arg(excerpt(path, 200)) };
    const auto data = readRegularFile(path, kMaxTableFileBytes);
    if (!data)
        return data.error();
    // A table within every limit may still not fit in the memory this process is allowed (ulimit -v):
    // that is a refusal like any other, not a crash.
    std::optional<Result<ToolTable>> read;
    try {
        read.emplace(readTable(data.value(), *format, tblUnits));
    } catch (const std::bad_alloc &) {
        return Error { tr("%1: there is not enough memory to read this table (the file is %2 MB).")
                           .arg(path)
                           .arg(data.value().size() >> 20) };
    }
    auto &result = *read;
    if (!result)
        return Error { result.error().message, result.error().line, path };
    return std::move(result);
}

Result<void> saveTableFile(const QString &path, const ToolTable &table, TableFormat format)
{
    // What Toffee would refuse to read back, it refuses to write: the limit holds for both.
    qint64 total = 0;
    const QString tooLarge = tr("the table would take more than %1 MB, more than Toffee reads back; shorten "
                                "the notes or split the table.")
                                 .arg(kMaxTableFileBytes >> 20);
    return writeFileAtomically(
        path,
        [&](const FileSink &sink) {
            return writeTable(table, format, [&](QByteArrayView piece) {
                total += piece.size();
                if (total > kMaxTableFileBytes)
                    return false;
                return sink(piece);
            });
        },
        &tooLarge);
}

} // namespace Toffee
