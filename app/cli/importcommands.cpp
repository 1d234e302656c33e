// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli import: tools from a CAM library into a table, showing first what is new and what changes.
#include <optional>

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include "app/cli/cli.h"
#include "app/cli/machineoptions.h"
#include "model/camimport/camlibrary.h"
#include "model/camimport/camreaders.h"
#include "model/camimport/importpreview.h"
#include "model/formats/fileio.h"
#include "model/formats/jsonscanner.h"
#include "model/formats/tablefile.h"
#include "model/library/historyevent.h"
#include "model/library/library.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

const QString kUsage = u"usage: toffee-cli import SOURCE --into TABLE [--dry-run] [--units mm|in]"_s;

QString word(ImportChange change)
{
    switch (change) {
    case ImportChange::New:
        return u"new"_s;
    case ImportChange::Changed:
        return u"changed"_s;
    case ImportChange::Unchanged:
        return u"unchanged"_s;
    }
    return {};
}

void printPreview(Invocation &call, const CamLibrary &library, const ImportPreview &preview)
{
    call.out << library.path << " (" << camFormatName(library.format) << "): " << preview.tools().size()
             << (preview.tools().size() == 1 ? " tool\n" : " tools\n");
    for (const ImportedTool &tool : preview.tools()) {
        call.out << u"  %1 %2  %3\n"_s.arg(word(tool.change), -10)
                        .arg(u"T"_s + QString::number(tool.number), -7)
                        .arg(tool.description);
        for (const QString &field : tool.fields)
            call.out << "                      " << field << '\n';
        for (const QString &note : tool.notes)
            call.out << "                      note: " << note << '\n';
    }
}

QJsonObject previewJson(const CamLibrary &library, const QString &table, const ImportPreview &preview)
{
    QJsonArray added;
    QJsonArray changed;
    QJsonArray unchanged;
    QJsonArray notes;
    QJsonArray newCutters;
    for (const ImportedTool &tool : preview.tools()) {
        if (tool.newCutter)
            newCutters.append(tool.number);
        if (!tool.notes.isEmpty())
            notes.append(QJsonObject {
                { u"number"_s, tool.number }, { u"notes"_s, QJsonArray::fromStringList(tool.notes) } });
        if (tool.change == ImportChange::New)
            added.append(tool.number);
        else if (tool.change == ImportChange::Unchanged)
            unchanged.append(tool.number);
        else
            changed.append(QJsonObject {
                { u"number"_s, tool.number }, { u"fields"_s, QJsonArray::fromStringList(tool.fields) } });
    }
    return QJsonObject { { u"source"_s, library.path }, { u"format"_s, camFormatName(library.format) },
        { u"table"_s, table }, { u"new"_s, added }, { u"changed"_s, changed }, { u"unchanged"_s, unchanged },
        { u"notes"_s, notes }, { u"new_cutters"_s, newCutters } };
}

// Why `path`, given as --into, is no tool table though it exists: a CAM library or program, or JSON that is
// not Toffee's. Nothing when it may be a table: the table's reader then says what is wrong with it, if
// anything.
std::optional<QString> notATable(const QString &path)
{
    const auto cam = camFormatForPath(path);
    if (!cam || !QFileInfo(path).isFile())
        return std::nullopt;
    if (*cam == CamFormat::MakeraProgram)
        return u"a G-code program, not a tool table"_s;
    if (*cam == CamFormat::FusionArchive)
        return u"a Fusion tool library (.tools), not a tool table"_s;
    if (*cam == CamFormat::HsmLibrary)
        return u"an HSM tool library (.hsmlib), not a tool table"_s;
    const auto data = readRegularFile(path, kMaxCamLibraryBytes);
    if (!data || isToffeeTable(data.value()))
        return std::nullopt;
    // Read as it streams, never as a whole document (a library may be 32 MB): valid JSON, and whether its
    // top level has a "data" list, as a Fusion library has.
    JsonScanner json(data.value());
    bool dataList = false;
    if (json.consume('{') && !json.consume('}')) {
        do {
            QByteArrayView key;
            QString decoded;
            Scalar value;
            if (!json.key(key, decoded) || !json.expect(':', "':'"))
                return std::nullopt;
            dataList = dataList || (key == "data" && json.peek() == '[');
            if (!json.value(value))
                return std::nullopt; // the table's reader shows where the JSON breaks
        } while (json.consume(','));
    }
    if (json.failed())
        return std::nullopt;
    if (dataList || readFusionJson(data.value()))
        return u"a Fusion tool library, not a tool table"_s;
    return u"JSON but not a tool table (it has no \"format\": \"toffee-tool-table\")"_s;
}

} // namespace

int importTools(Invocation &call)
{
    const QString tablePath = call.option(u"into"_s);
    if (call.arguments.size() != 1 || tablePath.isEmpty())
        return fail(call, kUsage, BadInput);
    const auto units = call.has(u"units"_s) ? unitsFromSymbol(call.option(u"units"_s)) : Units::Millimetre;
    if (!units)
        return fail(call, u"--units must be mm or in."_s, BadInput);
    // Refused before anything is read or written: a library given as --into would be read as a table of a
    // "newer Toffee", or, named .tools or .nc, not be told apart from a misspelt table.
    if (const auto what = notATable(tablePath))
        return fail(call,
            u"%1 is %2: give a .json, .tbl or .csv tool table as --into."_s.arg(tablePath, *what), BadInput);
    const auto format = formatForPath(tablePath);
    if (!format)
        return fail(call,
            u"%1: cannot tell the table's format from its name (.json, .tbl or .csv)."_s.arg(tablePath),
            BadInput);
    const QString source = call.arguments.front();
    if (camFormatForPath(source) == CamFormat::FusionJson) {
        if (auto data = readRegularFile(source, kMaxCamLibraryBytes); data && isToffeeTable(data.value()))
            return fail(call,
                u"%1 is a Toffee tool table, not a CAM library; open it, or use convert."_s.arg(source),
                BadInput);
    }
    auto library = loadCamLibrary(source);
    if (!library)
        return fail(call, library.error().text(), BadInput);
    // No TABLE yet: a new one, as a CAM library is often the start of a table.
    const bool isNew = !QFileInfo::exists(tablePath) && !QFileInfo(tablePath).isSymLink();
    auto table = isNew ? Result<ToolTable>(ToolTable(*units)) : loadTableFile(tablePath, {}, *units);
    if (!table)
        return fail(call, table.error().text(), BadInput);
    std::optional<Units> assumed;
    if (call.has(u"cam-units"_s)) {
        assumed = unitsFromSymbol(call.option(u"cam-units"_s));
        if (!assumed)
            return fail(call, u"--cam-units must be mm or in."_s, BadInput);
    }
    auto preview = ImportPreview::build(table.value(), library.value(), assumed);
    if (!preview)
        return fail(call, preview.error().text(), BadInput);

    const ImportPreview &p = preview.value();
    const bool write = !call.has(u"dry-run"_s) && (isNew || p.changesAnything());
    const QStringList losses = write ? formatLosses(p.merged(), *format) : QStringList();
    // The history first: a library that cannot be opened is said before the table changes.
    auto history = write && !p.newCutters().isEmpty() ? openLibraryOption(call)
                                                      : Result<std::unique_ptr<Library>>(nullptr);
    if (!history)
        return fail(call, history.error().message, BadInput);
    if (write) {
        if (auto saved = saveTableFile(tablePath, p.merged(), *format); !saved)
            return fail(call, saved.error().text(), BadInput);
    }
    if (history.value()) {
        // Each tool the library gave a new cutter: the old cutter ends in the history, on --machine.
        const QString machine
            = call.has(u"machine"_s) ? call.option(u"machine"_s).trimmed() : kDefaultMachineName;
        QList<HistoryEvent> ended;
        for (const ImportedTool &tool : p.newCutters())
            ended << historyEvent(
                Recording::newCutter(tool.number, tool.endedTlo, tool.endedReferenceMz), machine);
        if (auto written = history.value()->append(ended); !written)
            call.err << "toffee-cli: warning: the table is written, but the history could not take the new "
                        "cutters: "
                     << written.error().message << Qt::endl;
    }
    for (const QString &loss : losses)
        call.err << "toffee-cli: warning: " << loss << Qt::endl;
    if (call.json) {
        QJsonObject object = previewJson(library.value(), tablePath, p);
        object.insert(u"written"_s, write);
        printJson(call, object);
        return Success;
    }
    printPreview(call, library.value(), p);
    call.out << tablePath << ": " << p.summary() << "; "
             << (write                           ? u"written"_s
                        : call.has(u"dry-run"_s) ? u"nothing written (--dry-run)"_s
                                                 : u"nothing to change, left as it was"_s)
             << Qt::endl;
    return Success;
}

} // namespace Toffee::Cli
