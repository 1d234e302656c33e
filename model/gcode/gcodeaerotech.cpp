// SPDX-License-Identifier: GPL-3.0-or-later
// The interpreter's Aerotech function calls: compensation axes and offsets, Home().
#include "model/gcode/gcodeinterpreter.h"

#include <cmath>

#include "model/gcode/gcodeinterpreter_p.h"
#include "model/textparsing.h"

using namespace Qt::StringLiterals;

namespace Toffee {

Result<void> GCodeInterpreter::aerotechAxes(const QList<int> &axes, int line)
{
    if (axes.size() != 2 && axes.size() != 3)
        return error(line, tr("cutter compensation takes 2 or 3 axes."));
    if (m_compSign != 0 || m_pending != 0)
        return error(
            line, tr("the compensation axes can only change while cutter offset compensation is off."));
    m_compAxes = axes;
    m_compOffsets = QList<double>(axes.size(), 0.0);
    return {};
}

Result<void> GCodeInterpreter::callFunction(QByteArrayView call, int line)
{
    const qsizetype open = call.indexOf('(');
    if (open < 0 || !call.endsWith(')'))
        return error(line, tr("\"%1\" is not a call this simulator knows.").arg(QString::fromUtf8(call)));
    const QByteArrayView name = call.first(open).trimmed();
    QByteArrayView args = call.sliced(open + 1, call.size() - open - 2).trimmed();
    if (args.startsWith('[') && args.endsWith(']'))
        args = args.sliced(1, args.size() - 2);
    QList<QByteArrayView> items;
    for (QByteArrayView item : splitView(args, ',')) {
        if (!item.trimmed().isEmpty())
            items.append(item.trimmed());
    }
    auto axesOf = [&](QList<int> &axes) -> bool {
        for (QByteArrayView item : items) {
            const int index = item.size() == 1 ? axisIndex(QChar::toUpper(char16_t(item.front()))) : -1;
            if (index < 0)
                return false;
            axes.append(index);
        }
        return true;
    };
    if (name == "CutterCompensationSetAxes") {
        QList<int> axes;
        if (!axesOf(axes))
            return error(line, tr("CutterCompensationSetAxes takes axes such as [X, Y, Z]."));
        return aerotechAxes(axes, line);
    }
    if (name == "CutterCompensationSetOffsets") {
        if (m_compSign != 0 || m_pending != 0)
            return error(
                line, tr("CutterCompensationSetOffsets works only while cutter offset compensation is off."));
        if (items.size() != m_compAxes.size())
            return error(line,
                tr("CutterCompensationSetOffsets needs %1 offsets, one for each compensation axis.")
                    .arg(m_compAxes.size()));
        QList<double> offsets;
        for (QByteArrayView item : items) {
            const auto v = parseDecimal(item);
            if (!v)
                return error(line, tr("\"%1\" is not a number.").arg(QString::fromUtf8(item)));
            if (std::fabs(*v) > kMaxWordValue)
                return error(line, GCodeLexer::tooLarge(item));
            offsets.append(*v);
        }
        m_compOffsets = offsets;
        return {};
    }
    if (name == "Home") {
        QList<int> axes;
        if (!axesOf(axes) || axes.isEmpty())
            return error(line, tr("Home takes axes such as X or [X, Y]."));
        home(axes, line);
        return {};
    }
    return error(line, tr("\"%1\" is not a call this simulator knows.").arg(QString::fromUtf8(name)));
}

// Aerotech's Home(): the axes go to 0 and compensation ends at once, with no lead-off.
void GCodeInterpreter::home(const QList<int> &axes, int line)
{
    m_compSign = 0;
    m_compFraction = 0.0;
    m_pending = 0;
    const Position start = m_machine;
    for (int a : axes) {
        m_machine[size_t(a)] = 0.0;
        m_program[size_t(a)] = 0.0;
    }
    recordStraight(line, start);
}

} // namespace Toffee
