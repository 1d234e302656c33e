// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/library/programuse.h"

#include <QFileInfo>

#include "model/clock.h"
#include "model/formats/linereader.h"
#include "model/gcode/gcodeinterpreter.h"

namespace Toffee {

Result<ProgramUse> ProgramUse::read(const QString &path, Dialect dialect, const QString &machine)
{
    // A line at a time: memory does not grow with the program.
    LineReader reader;
    if (auto opened = reader.open(path); !opened)
        return opened.error();
    GCodeInterpreter interpreter(dialect);
    interpreter.setRecordMoves(false);
    QByteArrayView line;
    while (!interpreter.ended() && reader.next(line)) {
        if (auto ran = interpreter.runLine(line, reader.lineNumber()); !ran)
            return Error { tr("%1 Nothing was recorded.").arg(ran.error().message), ran.error().line, path };
    }
    if (reader.error())
        return *reader.error();
    ProgramUse out;
    out.rapidMm = interpreter.rapidDistance();
    const QDateTime now = Clock::now();
    for (const auto &[tool, usage] : interpreter.toolUsage()) {
        if (tool >= 0)
            out.uses.append({ HistoryEvent::newId(), machine, tool, now, QFileInfo(path).fileName(),
                usage.cuttingSeconds, usage.feedPathMm });
    }
    return out;
}

} // namespace Toffee
