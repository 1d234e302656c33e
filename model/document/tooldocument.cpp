// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/document/tooldocument.h"

#include <QFileInfo>

#include "model/document/toolcommands.h"
#include "model/toolvalidation.h"

namespace Toffee {

ToolDocument::ToolDocument(QObject *parent)
    : QObject(parent)
{
    m_model.setEditHandler([this](const Tool &before, const Tool &after) {
        m_undoStack.push(new EditToolCommand(&m_model, before, after));
    });
    connect(&m_undoStack, &QUndoStack::cleanChanged, this,
        [this](bool clean) { Q_EMIT modifiedChanged(!clean); });
}

ToolDocument::~ToolDocument()
{
    // QUndoStack says "clean changed" as it is destroyed; nobody (the document, its AutoSave, the window) may
    // hear that from a dying document.
    m_undoStack.disconnect();
}

void ToolDocument::setFile(const QString &path, TableFormat format)
{
    m_base = {}; // a file, not a library's table
    m_queued.clear();
    m_fileFormat = format;
    if (m_filePath != path) {
        m_filePath = path;
        Q_EMIT filePathChanged(path);
    }
}

void ToolDocument::newTable(Units units)
{
    m_undoStack.clear();
    m_model.resetTable(ToolTable(units));
    setFile({}, TableFormat::Json);
}

Result<void> ToolDocument::open(const QString &path, std::optional<TableFormat> format, Units tblUnits)
{
    if (!format)
        format = formatForPath(path);
    auto table = loadTableFile(path, format, tblUnits);
    if (!table)
        return table.error();
    m_undoStack.clear();
    m_model.resetTable(table.value());
    setFile(path, *format);
    return {};
}

Result<void> ToolDocument::save()
{
    if (m_filePath.isEmpty())
        return Error { tr("This table has no file yet; use Save As.") };
    return saveAs(m_filePath, m_fileFormat);
}

Result<void> ToolDocument::saveAs(const QString &path, TableFormat format)
{
    if (auto r = saveTableFile(path, table(), format); !r)
        return r;
    // A format that cannot hold everything (a LinuxCNC .tbl has no TLOs, wear or marks): the window then
    // shows what the file holds, as one undoable step, so that it never shows more than the file and Undo
    // still brings the rest back.
    if (!formatLosses(table(), format).isEmpty()) {
        auto held = readTable(writeTable(table(), format), format, table().units());
        if (held && !(held.value() == table()))
            m_undoStack.push(new ReplaceTableCommand(&m_model, table(), held.value(),
                tr("Keep only what %1 holds").arg(QFileInfo(path).fileName())));
    }
    setFile(path, format);
    m_undoStack.setClean();
    return {};
}

Result<void> ToolDocument::exportTo(const QString &path, TableFormat format) const
{
    return saveTableFile(path, table(), format);
}

Result<int> ToolDocument::importFrom(const QString &path, std::optional<TableFormat> format, Units tblUnits)
{
    auto imported = loadTableFile(path, format, tblUnits);
    if (!imported)
        return imported.error();
    if (imported.value().units() != table().units() && !imported.value().isEmpty())
        return Error { tr("%1 is in %2 but this table is in %3; Toffee does not convert units on import.")
                           .arg(path, unitsSymbol(imported.value().units()), unitsSymbol(table().units())) };
    ToolTable merged = table();
    for (const Tool &tool : imported.value().tools()) {
        auto r = merged.contains(tool.number) ? merged.replace(tool.number, tool) : merged.insert(tool);
        if (!r)
            return r.error();
    }
    const int count = int(imported.value().size());
    m_undoStack.push(new ReplaceTableCommand(&m_model, table(), merged, tr("Import %1 tools").arg(count)));
    return count;
}

bool ToolDocument::replaceTable(const ToolTable &table, const QString &undoText)
{
    if (table == this->table())
        return false;
    m_undoStack.push(new ReplaceTableCommand(&m_model, this->table(), table, undoText));
    return true;
}

QString ToolDocument::recoverEdits(
    const ToolTable &edits, const QString &originalPath, TableFormat originalFormat)
{
    QString notice;
    if (originalPath.isEmpty()) {
        newTable(edits.units());
    } else if (!QFileInfo::exists(originalPath)) {
        newTable(edits.units());
        setFile(originalPath, originalFormat); // Save writes it again
        notice = tr("%1 no longer exists; saving writes it again.").arg(originalPath);
    } else if (auto opened = open(originalPath, originalFormat, edits.units()); !opened) {
        // Never save over a file Toffee cannot read: the edits become a new table, saved with Save As.
        newTable(edits.units());
        notice = tr("%1 does not load (%2), so the recovered edits are a new table: save them with Save As.")
                     .arg(originalPath, opened.error().text());
    }
    m_undoStack.push(new ReplaceTableCommand(&m_model, table(), edits, tr("Recover unsaved edits")));
    return notice;
}

Result<void> ToolDocument::addTool(const Tool &tool)
{
    if (auto r = table().checkInsert(tool); !r)
        return r;
    m_undoStack.push(new AddToolCommand(&m_model, tool));
    return {};
}

Result<void> ToolDocument::editTool(int number, const Tool &after)
{
    if (auto r = table().checkReplace(number, after); !r)
        return r;
    const Tool before = *table().find(number);
    if (before != after)
        m_undoStack.push(new EditToolCommand(&m_model, before, after));
    return {};
}

void ToolDocument::removeTools(const QList<int> &numbers)
{
    QList<Tool> tools;
    for (int number : numbers) {
        if (const Tool *tool = table().find(number))
            tools.append(*tool);
    }
    if (!tools.isEmpty())
        m_undoStack.push(new RemoveToolsCommand(&m_model, tools));
}

Result<void> ToolDocument::recordMeasurement(
    int number, double tlo, const QDateTime &at, TloSource source, std::optional<double> referenceMz)
{
    ToolTable next = table();
    if (auto r = next.recordMeasurement(number, tlo, at, source, referenceMz); !r)
        return r;
    pushChange(*next.find(number),
        source == TloSource::Manual       ? tr("Set T%1 TLO by hand").arg(number)
            : source == TloSource::Pulled ? tr("Pull T%1's TLO from the controller").arg(number)
                                          : tr("Measure T%1").arg(number));
    return {};
}

Result<void> ToolDocument::recordBreakTest(int number, bool failed)
{
    ToolTable next = table();
    if (auto r = next.recordBreakTest(number, failed); !r)
        return r;
    if (const Tool *existing = table().find(number); existing && *existing == *next.find(number))
        return {}; // a passed test on an unmarked tool changes nothing
    pushChange(*next.find(number),
        failed ? tr("Mark T%1 failed its break test").arg(number)
               : tr("T%1 passed its break test").arg(number));
    return {};
}

Result<void> ToolDocument::record(const Recording &r)
{
    if (r.kind == RecordingKind::NewCutter) {
        // Not the machine's doing: only a tool of the table can take a new cutter, and only then is it
        // history.
        ToolTable next = table();
        if (auto changed = next.newCutter(r.tool); !changed)
            return changed;
        Q_EMIT recorded(r);
        pushChange(*next.find(r.tool), tr("New cutter in T%1").arg(r.tool));
        return {};
    }
    // The history keeps what the machine did whether or not the table could take it.
    Q_EMIT recorded(r);
    if (r.kind == RecordingKind::Restore)
        return {}; // the table already holds the TLO that was set back
    if (r.tlo)
        return recordMeasurement(r.tool, *r.tlo, r.at, r.source, r.referenceMz);
    if (r.breakTestFailed)
        return recordBreakTest(r.tool, *r.breakTestFailed);
    return {};
}

Result<void> ToolDocument::recordAll(const QList<Recording> &recordings, const QString &text)
{
    ToolTable next = table();
    if (auto recorded = next.recordAll(recordings); !recorded)
        return recorded;
    for (const Recording &r : recordings)
        Q_EMIT recorded(r);
    applyTable(next, text);
    return {};
}

void ToolDocument::pushChange(const Tool &changed, const QString &text)
{
    if (const Tool *existing = table().find(changed.number)) {
        auto *command = new EditToolCommand(&m_model, *existing, changed);
        command->setText(text);
        m_undoStack.push(command);
    } else {
        auto *command = new AddToolCommand(&m_model, changed);
        command->setText(text);
        m_undoStack.push(command);
    }
}

Tool ToolDocument::newTool() const
{
    Tool tool;
    tool.number = table().nextFreeNumber(1);
    tool.pocket = defaultPocket(tool.number);
    return tool;
}

} // namespace Toffee
