// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

#include "model/document/tooldocument.h"
#include "serial/machineconnection.h"

namespace Toffee {

// What a question about the tool in the spindle adds when the table marks that tool broken (it failed its
// break test), so that no operation on it is one click that says nothing of the mark; nothing otherwise.
enum class BrokenToolAction { Probe, SetByHand, BreakTest };

inline QString brokenToolWarning(
    const ToolDocument *document, const MachineConnection *connection, BrokenToolAction action)
{
    const auto number = connection->activeTool();
    const Tool *tool = number ? document->table().find(*number) : nullptr;
    if (!tool || !tool->breakTestFailed)
        return {};
    const char *text = action == BrokenToolAction::Probe
        ? QT_TRANSLATE_NOOP("BrokenTool",
            "T%1 is marked broken: it failed its break test. Probing measures it as it is now, records that "
            "TLO and clears the mark: replace the tool first if it is broken.")
        : action == BrokenToolAction::SetByHand
        ? QT_TRANSLATE_NOOP("BrokenTool",
            "T%1 is marked broken: it failed its break test. A TLO set by hand does not clear the mark; "
            "measure the tool (Probe) once it is checked or replaced.")
        : QT_TRANSLATE_NOOP("BrokenTool",
            "T%1 is marked broken: it failed its last break test. Testing it again compares it with its "
            "stored TLO; a pass clears the mark.");
    return QCoreApplication::translate("BrokenTool", text).arg(tool->number);
}

// `warning` as a paragraph of its own after a question's text, or nothing.
inline QString brokenParagraph(const QString &warning)
{
    return warning.isEmpty() ? QString() : QStringLiteral("\n\n") + warning;
}

} // namespace Toffee
