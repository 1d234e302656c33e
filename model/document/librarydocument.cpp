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
        if (mine == base || (m_queued.contains(number) && m_queued.value(number) == mine))
            continue; // as read, or waiting in the outbox
        out.writes.append({ number, mine, row ? row->version : 0, base });
    }
    return out;
}

// Saved when the library holds (or the outbox will send) every tool as shown; otherwise modified, even when
// the undo stack is at its clean index (a conflict resolved as mine, after a save).
void ToolDocument::cleanWhenWritten()
{
    if (libraryWrites().writes.isEmpty())
        m_undoStack.setClean();
    else if (m_undoStack.isClean())
        m_undoStack.resetClean();
}

// The table becomes `next` as one undoable step, tool by tool: the rows that did not change keep their
// selection, the cell being looked at and the column widths (a reset would lose them).
void ToolDocument::applyTable(const ToolTable &next, const QString &text)
{
    QList<QUndoCommand *> steps;
    QList<Tool> removed;
    for (const Tool &before : table().tools()) {
        const Tool *after = next.find(before.number);
        if (!after)
            removed.append(before);
        else if (!(*after == before))
            steps.append(new EditToolCommand(&m_model, before, *after));
    }
    for (const Tool &after : next.tools()) {
        if (!table().contains(after.number))
            steps.append(new AddToolCommand(&m_model, after));
    }
    if (!removed.isEmpty())
        steps.append(new RemoveToolsCommand(&m_model, removed));
    if (steps.isEmpty())
        return;
    m_undoStack.beginMacro(text);
    for (QUndoCommand *step : steps)
        m_undoStack.push(step);
    m_undoStack.endMacro();
}

void ToolDocument::markWritten(const ToolWrites &writes, const WriteOutcome &outcome)
{
    ToolTable next = table();
    for (const ToolWrite &write : writes.writes) {
        if (outcome.queued) {
            // Sent when the library is back, and checked then against what it holds: until then the tool is
            // neither written (its row stays as read) nor to be written again.
            m_queued.insert(write.number, write.tool);
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
    forgetUndoPast(next);
    cleanWhenWritten();
}

// Another station's change is shown, and Undo stops there: undoing it, or an older edit of the same tool,
// would put their old values back, and the next Save would write them over theirs without a question.
void ToolDocument::forgetUndoPast(const ToolTable &next)
{
    if (next == table())
        return;
    applyTable(next, tr("Update from the library"));
    m_undoStack.clear();
}

QList<ToolConflict> ToolDocument::takeRemote(const StoredTable &latest)
{
    if (latest.machine != m_base.machine)
        return {};
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
        // A queued write is in `merged` now, or was what the library took: either way written from here.
        m_queued.remove(theirs.number);
    }
    forgetUndoPast(next);
    cleanWhenWritten();
    return conflicts;
}

void ToolDocument::resolveConflict(const ToolConflict &conflict, bool keepMine)
{
    setBaseRow(conflict.number, conflict.theirs, conflict.theirVersion);
    m_queued.remove(conflict.number); // mine is written at the next Save, over theirs
    if (!keepMine && toolIn(table(), conflict.number) != conflict.theirs) {
        ToolTable next = table();
        put(next, conflict.number, conflict.theirs);
        applyTable(next, tr("Take T%1 from %2").arg(conflict.number).arg(conflict.theirStation));
    }
    cleanWhenWritten();
}

} // namespace Toffee
