// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>

#include <QUndoCommand>

#include "model/tooltable.h"

namespace Toffee {

class ToolTableModel;

// Each command stores tool numbers and values, never model indexes, and changes the table only through
// ToolTableModel's public API. A command whose change no longer applies marks itself obsolete.

class AddToolCommand final : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::AddToolCommand)

public:
    AddToolCommand(ToolTableModel *model, const Tool &tool);
    void redo() override;
    void undo() override;

private:
    ToolTableModel *m_model;
    Tool m_tool;
};

class RemoveToolsCommand final : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::RemoveToolsCommand)

public:
    RemoveToolsCommand(ToolTableModel *model, const QList<Tool> &tools);
    void redo() override;
    void undo() override;

private:
    ToolTableModel *m_model;
    QList<Tool> m_tools;
};

class EditToolCommand final : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::EditToolCommand)

public:
    EditToolCommand(ToolTableModel *model, const Tool &before, const Tool &after);
    void redo() override;
    void undo() override;

private:
    ToolTableModel *m_model;
    Tool m_before;
    Tool m_after;
};

// Import and other whole-table changes: one step, whatever their size.
class ReplaceTableCommand final : public QUndoCommand
{
public:
    ReplaceTableCommand(
        ToolTableModel *model, const ToolTable &before, const ToolTable &after, const QString &text);
    void redo() override;
    void undo() override;

private:
    ToolTableModel *m_model;
    ToolTable m_before;
    ToolTable m_after;
};

} // namespace Toffee
