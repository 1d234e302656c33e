// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>

#include "model/gcode/dialect.h"
#include "model/library/historyevent.h"
#include "model/result.h"

namespace Toffee {

// What a program made each tool do, ready to record: the tools' cutting time and feed path, and the rapids.
struct ProgramUse
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::ProgramUse)

public:
    QList<ToolUse> uses; // one per tool that cut, for `machine`, now
    double rapidMm = 0.0;

    // Reads the program at `path` and runs it as a `dialect` controller would. Refused, with the line, when
    // the interpreter refuses it; nothing is to be recorded then.
    [[nodiscard]] static Result<ProgramUse> read(
        const QString &path, Dialect dialect, const QString &machine);
};

} // namespace Toffee
