// SPDX-License-Identifier: GPL-3.0-or-later
// A tool document whose table is a machine's table in a library: what Save writes, and another station's
// changes taken in without losing this one's.
#include <QSet>

#include "model/document/toolcommands.h"
#include "model/document/tooldocument.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

std::optional<Tool> toolIn(const ToolTable &table, int number)
{
    const Tool *tool = table.find(number);
    return tool ? std::optional(*tool) : std::nullopt;
}

// `table` with tool `number` replaced, added or removed.
void put(ToolTable &table, int number, const std::optional<Tool> &tool)
{
    if (!tool)
        table.remove(number);
    else if (table.contains(number))
        (void)table.replace(number, *tool);
    else
        (void)table.insert(*tool);
}

} // namespace

void ToolDocument::openLibraryTable(const StoredTable &stored)
{
    m_undoStack.clear();
    m_model.resetTable(stored.table());
    setFile({}, TableFormat::Json);
    m_base = stored;
}

void ToolDocument::setBaseRow(int number, const std::optional<Tool> &tool, qint64 version)
{
    for (StoredTool &row : m_base.rows) {
        if (row.number == number) {
            row.tool = tool;
            row.version = version;
            return;
        }
    }
    m_base.rows.append({ number, tool, version, {}, {} });
}

ToolWrites ToolDocument::libraryWrites() const
{
    ToolWrites out { m_base.machine, m_base.units, {} };
    QSet<int> numbers;
    for (const StoredTool &row : m_base.rows)
        numbers.insert(row.number);
    for (const Tool &tool : table().tools())
        numbers.insert(tool.number);
    QList<int> sorted(numbers.begin(), numbers.end());
    std::sort(sorted.begin(), sorted.end());
    for (int number : sorted) {
        const StoredTool *row = m_base.row(number);
        const std::optional<Tool> mine = toolIn(table(), number);
        const std::optional<Tool> base = row ? row->tool : std::nullopt;
        if (mine != base)
            out.writes.append({ number, mine, row ? row->version : 0, base });
    }
    return out;
}

void ToolDocument::cleanWhenWritten()
{
    if (libraryWrites().writes.isEmpty())
        m_undoStack.setClean();
}

void ToolDocument::markWritten(const ToolWrites &writes, const WriteOutcome &outcome)
{
    ToolTable next = table();
    for (const ToolWrite &write : writes.writes) {
        if (outcome.queued) {
            setBaseRow(write.number, write.tool, write.baseVersion); // checked against the library when sent
        } else if (outcome.merged.contains(write.number)) {
            // Another station's change to other fields was merged in: the table shows what was written.
            const std::optional<Tool> merged = outcome.merged.value(write.number);
            setBaseRow(write.number, merged, outcome.written.value(write.number));
            if (toolIn(next, write.number) == write.tool)
                put(next, write.number, merged);
        } else if (outcome.written.contains(write.number)) {
            setBaseRow(write.number, write.tool, outcome.written.value(write.number));
        }
    }
    if (!(next == table()))
        m_undoStack.push(new ReplaceTableCommand(&m_model, table(), next, tr("Update from the library")));
    cleanWhenWritten();
}

QList<ToolConflict> ToolDocument::takeRemote(const StoredTable &latest)
{
    if (latest.machine != m_base.machine)
        return {};
    const bool wasClean = m_undoStack.isClean();
    ToolTable next = table();
    QList<ToolConflict> conflicts;
    for (const StoredTool &theirs : latest.rows) {
        const StoredTool *row = m_base.row(theirs.number);
        if (row && row->version == theirs.version)
            continue; // nothing new
        const std::optional<Tool> base = row ? row->tool : std::nullopt;
        const std::optional<Tool> mine = toolIn(table(), theirs.number);
        const auto merged = mine == base ? std::optional(theirs.tool) : mergeTool(base, theirs.tool, mine);
        if (!merged) {
            conflicts.append({ theirs.number, theirs.tool, mine, theirs.version, theirs.updatedBy });
            continue;
        }
        put(next, theirs.number, *merged);
        setBaseRow(theirs.number, theirs.tool, theirs.version);
    }
    if (!(next == table()))
        m_undoStack.push(new ReplaceTableCommand(&m_model, table(), next, tr("Update from the library")));
    if (wasClean)
        cleanWhenWritten();
    return conflicts;
}

void ToolDocument::resolveConflict(const ToolConflict &conflict, bool keepMine)
{
    setBaseRow(conflict.number, conflict.theirs, conflict.theirVersion);
    if (!keepMine && toolIn(table(), conflict.number) != conflict.theirs) {
        ToolTable next = table();
        put(next, conflict.number, conflict.theirs);
        m_undoStack.push(new ReplaceTableCommand(
            &m_model, table(), next, tr("Take T%1 from %2").arg(conflict.number).arg(conflict.theirStation)));
    }
    cleanWhenWritten();
}

} // namespace Toffee
