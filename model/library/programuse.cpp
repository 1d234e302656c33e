// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/programuse.h"

#include <QFileInfo>

#include "model/formats/fileio.h"
#include "model/gcode/gcodeinterpreter.h"

namespace Toffee {

Result<ProgramUse> ProgramUse::read(const QString &path, Dialect dialect, const QString &machine)
{
    constexpr qint64 kMaxProgramBytes = 512LL * 1024 * 1024;
    const auto program = readRegularFile(path, kMaxProgramBytes);
    if (!program)
        return program.error();
    GCodeInterpreter interpreter(dialect);
    interpreter.setRecordMoves(false);
    if (auto ran = interpreter.run(program.value()); !ran)
        return Error { tr("%1 Nothing was recorded.").arg(ran.error().message), ran.error().line, path };
    ProgramUse out;
    out.rapidMm = interpreter.rapidDistance();
    const QDateTime now = QDateTime::currentDateTimeUtc();
    for (const auto &[tool, usage] : interpreter.toolUsage()) {
        if (tool >= 0)
            out.uses.append({ HistoryEvent::newId(), machine, tool, now, QFileInfo(path).fileName(),
                usage.cuttingSeconds, usage.feedPathMm });
    }
    return out;
}

} // namespace Toffee
