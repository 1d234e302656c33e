// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/job/jobpreparer.h"

#include <cmath>

#include "model/numberformat.h"
#include "model/tooltable.h"

using namespace Qt::StringLiterals;

namespace Toffee {

JobPreparer::JobPreparer(const ToolTable &table, PrepareOptions options)
    : m_options(std::move(options))
    , m_offsets(offsetTableFor(table, m_options.dialect))
    , m_facts(factsFromTable(table))
    , m_original(m_options.dialect, m_offsets)
    , m_prepared(m_options.dialect, m_offsets)
{
    m_original.setRecordMoves(false);
    m_prepared.setRecordMoves(false);
    m_original.setKeepToolUsage(false);
    m_prepared.setKeepToolUsage(false);
    for (int tool : std::as_const(m_options.rack))
        m_rack.insert(tool);
}

Result<void> JobPreparer::check(const PrepareOptions &options)
{
    const QString name = dialectInfo(options.dialect).name;
    if (options.dialect != Dialect::Carvera && (options.useStoredTlo || options.breakTest))
        return Error { tr("%1 has no stored-offset or break-test commands: --use-stored-tlo and --break-test "
                          "are for the Carvera. For %1, prepare inserts only the missing G43.")
                           .arg(name) };
    if (options.dialect == Dialect::Aerotech)
        return Error { tr("Preparing a program is for the Carvera and the controllers with G43; Automation1 "
                          "compensates with G143 / G144, which Toffee does not insert.") };
    if (options.dialect == Dialect::Carvera && !options.useStoredTlo && !options.breakTest)
        return Error { tr("Say what to prepare: --use-stored-tlo, --break-test, or both.") };
    if (options.breakTest
        && (!std::isfinite(options.tolerance) || options.tolerance < Limits::kMinBreakTolerance
            || options.tolerance > kMaxPrepareTolerance))
        return Error {
            tr("The break-test tolerance must be from %1 mm (the Carvera halts below it) to %2 mm (a "
               "looser test would miss a broken tool).")
                .arg(commandNumber(Limits::kMinBreakTolerance), commandNumber(kMaxPrepareTolerance))
        };
    return {};
}

QString JobPreparer::commandNumber(double value)
{
    return formatNumber(value, NumberFormat::command());
}

// A comment in the program for the controller: in English and ASCII whatever the window's language, since
// controllers take little else in a program (FANUC, for one, refuses most other characters).
QString JobPreparer::comment(const QString &why) const
{
    if (m_options.dialect == Dialect::Aerotech)
        return u"// Toffee: "_s + why;
    QString text = why;
    text.replace(u'(', u'[').replace(u')', u']');
    return u"(Toffee: "_s + text + u')';
}

Result<void> JobPreparer::feed(QByteArrayView line, int lineNumber, const LineSink &sink)
{
    m_afterEnd = m_original.ended();
    if (m_afterEnd) {
        // The controller runs nothing after the end: copied as it is.
        ++m_summary.originalLines;
        m_changedLine = false;
        return writeOriginal(line, line, lineNumber, sink);
    }
    ++m_summary.originalLines;
    if (auto ran = m_original.runLine(line, lineNumber); !ran)
        return Error { tr("%1 Toffee prepares only a program the controller runs: check the job first.")
                           .arg(ran.error().message),
            lineNumber };
    const BlockEffect effect = m_original.lastBlock();
    if (m_options.breakTest && (effect.toolChange || m_original.ended()) && m_lastCutLine > 0) {
        if (auto r = breakTest(sink); !r)
            return r;
    }
    const bool moves = effect.motion != BlockEffect::Motion::None && !effect.machineCoordinates
        && (effect.lengthAxisWord || effect.motion == BlockEffect::Motion::Feed);
    if (m_compensationDue && moves) {
        m_compensationDue = false;
        if (m_original.lengthCalls() == m_callsAtChange && m_tool > 0) {
            m_compensated = true;
            m_callsAtInsertion = m_original.lengthCalls();
            const QString letter = m_options.dialect == Dialect::Fagor8055M ? u"D"_s : u"H"_s;
            const QString call = u"G43 "_s + letter + QString::number(m_tool);
            if (auto r = insertLine(call + u' '
                        + comment(u"no G43 for T%1 after its change at original line %2"_s.arg(m_tool).arg(
                            m_toolLine)),
                    sink, true);
                !r)
                return r;
        }
    }
    const int loaded = m_original.loadedTool();
    QString rewritten;
    if (effect.toolChange && m_options.dialect == Dialect::Carvera && m_options.useStoredTlo)
        rewritten = carveraChange(line, loaded);
    m_changedLine = !rewritten.isEmpty();
    const QByteArray prepared = m_changedLine ? rewritten.toUtf8() : QByteArray();
    if (auto r = writeOriginal(line, m_changedLine ? QByteArrayView(prepared) : line, lineNumber, sink); !r)
        return r;
    if (auto r = compare(lineNumber); !r)
        return r;
    if (effect.toolChange) {
        m_tool = loaded;
        m_toolLine = lineNumber;
        m_lastCutLine = 0;
        m_compensationDue = usesG43(m_options.dialect);
        m_compensated = false;
        m_callsAtChange = m_original.lengthCalls();
        if (m_changedLine) {
            if (auto r = restoreAfterChange(loaded, sink); !r)
                return r;
        }
    }
    if (effect.motion == BlockEffect::Motion::Feed)
        m_lastCutLine = lineNumber;
    return {};
}

Result<PrepareSummary> JobPreparer::finish(const LineSink &sink)
{
    if (m_options.breakTest && m_lastCutLine > 0 && !m_original.ended()) {
        if (auto r = breakTest(sink); !r)
            return r.error();
    }
    if (!m_hunk.isEmpty())
        closeHunk();
    if (m_moreNotes > 0)
        m_summary.notes.append(tr("%1 more notes like these, one for each further tool (the first of them "
                                  "T%2): counted, not listed.")
                                   .arg(m_moreNotes)
                                   .arg(m_firstMoreNoted));
    return m_summary;
}

} // namespace Toffee
