// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/document/toolcommands.h"

#include "model/document/tooltablemodel.h"

namespace Toffee {

AddToolCommand::AddToolCommand(ToolTableModel *model, const Tool &tool)
    : QUndoCommand(tr("Add tool T%1").arg(tool.number))
    , m_model(model)
    , m_tool(tool)
{ }

void AddToolCommand::redo()
{
    setObsolete(!m_model->insertTool(m_tool).ok());
}

void AddToolCommand::undo()
{
    m_model->removeTool(m_tool.number);
}

RemoveToolsCommand::RemoveToolsCommand(ToolTableModel *model, const QList<Tool> &tools)
    : QUndoCommand(tools.size() == 1 ? tr("Remove tool T%1").arg(tools.front().number)
                                     : tr("Remove %1 tools").arg(tools.size()))
    , m_model(model)
    , m_tools(tools)
{ }

void RemoveToolsCommand::redo()
{
    for (const Tool &tool : std::as_const(m_tools))
        m_model->removeTool(tool.number);
}

void RemoveToolsCommand::undo()
{
    for (const Tool &tool : std::as_const(m_tools))
        (void)m_model->insertTool(tool);
}

EditToolCommand::EditToolCommand(ToolTableModel *model, const Tool &before, const Tool &after)
    : QUndoCommand(tr("Edit tool T%1").arg(before.number))
    , m_model(model)
    , m_before(before)
    , m_after(after)
{ }

void EditToolCommand::redo()
{
    setObsolete(!m_model->replaceTool(m_before.number, m_after).ok());
}

void EditToolCommand::undo()
{
    (void)m_model->replaceTool(m_after.number, m_before);
}

ReplaceTableCommand::ReplaceTableCommand(
    ToolTableModel *model, const ToolTable &before, const ToolTable &after, const QString &text)
    : QUndoCommand(text)
    , m_model(model)
    , m_before(before)
    , m_after(after)
{ }

void ReplaceTableCommand::redo()
{
    m_model->resetTable(m_after);
}

void ReplaceTableCommand::undo()
{
    m_model->resetTable(m_before);
}

} // namespace Toffee
