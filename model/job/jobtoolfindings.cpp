// SPDX-License-Identifier: GPL-3.0-or-later
// The job check's end: each tool the program loads against what the table and the library know of it.
#include "model/job/jobchecker.h"

#include <algorithm>

#include "model/numberformat.h"
#include "model/timetext.h"

namespace Toffee {

JobReport JobChecker::finish(const QString &program, bool cancelled)
{
    JobReport report;
    report.program = program;
    report.dialect = m_setup.dialect;
    report.lines = m_lines;
    report.cancelled = cancelled;
    const auto &usage = m_interpreter.toolUsage();
    for (JobTool tool : std::as_const(m_tools)) {
        if (const auto used = usage.find(tool.number); used != usage.end()) {
            tool.cuttingSeconds = used->second.cuttingSeconds;
            tool.feedPathMm = used->second.feedPathMm;
        }
        const ToolFacts facts = m_setup.facts.value(tool.number);
        tool.inTable = facts.inTable;
        tool.tlo = m_setup.dialect == Dialect::Carvera ? facts.measuredTlo
            : facts.inTable                            ? std::optional(facts.length)
                                                       : std::nullopt;
        tool.measuredAt = facts.measuredAt;
        tool.setByHand = facts.measuredTlo && facts.source == TloSource::Manual;
        report.tools.append(tool);
        toolFindings(tool);
    }
    for (const auto &[tool, used] : usage)
        report.cuttingSeconds += used.cuttingSeconds;
    report.rapidMm = m_interpreter.rapidDistance();
    if (m_moreProgramErrors > 0)
        m_findings.append({ FindingKind::ProgramError, m_firstUncountedError, -1,
            tr("More lines the controller would refuse, from this one on: %1 in all.")
                .arg(m_moreProgramErrors),
            { m_firstUncountedError }, m_moreProgramErrors });
    report.findings = m_findings;
    // By line, and on one line the errors first.
    std::stable_sort(report.findings.begin(), report.findings.end(), [](const Finding &a, const Finding &b) {
        return a.line != b.line ? a.line < b.line
                                : a.severity() == Severity::Error && b.severity() != Severity::Error;
    });
    return report;
}

void JobChecker::noteForTool(FindingKind kind, const JobTool &tool, const QString &message)
{
    m_findings.append({ kind, tool.loadLines.value(0), tool.number, message, tool.loadLines, tool.loads });
}

void JobChecker::toolFindings(const JobTool &tool)
{
    const int n = tool.number;
    const bool carvera = m_setup.dialect == Dialect::Carvera;
    // T0 is no tool on the other controllers (LinuxCNC's empty spindle), the wireless probe on the Carvera.
    if (n == 0 || (carvera && isCarveraNonCutter(n)))
        return;
    if (m_setup.rack && !m_setup.rack->contains(n))
        noteForTool(FindingKind::ManualChange, tool,
            tr("The machine's rack does not hold T%1: it is a manual change, and the machine waits for the "
               "operator.")
                .arg(n));
    const ToolFacts facts = m_setup.facts.value(n);
    if (m_setup.hasTable && !facts.inTable) {
        noteForTool(FindingKind::MissingTool, tool,
            tr("T%1 is not in the tool table: nothing is known of its length.").arg(n));
        return;
    }
    if (facts.broken)
        noteForTool(FindingKind::BrokenTool, tool,
            tr("T%1 failed its last break test and has not been measured since: check the tool and probe "
               "it.")
                .arg(n));
    const bool measured
        = carvera ? facts.measuredTlo.has_value() : (facts.measuredTlo || facts.length != 0.0);
    if (!measured) {
        noteForTool(FindingKind::NotMeasured, tool,
            carvera ? tr("T%1 has no measured TLO.").arg(n)
                    : tr("T%1 has no length in the table: G43 would apply 0.").arg(n));
    } else if (carvera && facts.source == TloSource::Manual) {
        noteForTool(FindingKind::NotMeasured, tool,
            tr("T%1's TLO was set by hand, not measured on the tool setter: probe it before the job.")
                .arg(n));
    } else if (facts.measuredAt.isValid()
        && facts.measuredAt.secsTo(m_setup.now) < -ToolFacts::kClockSkewSeconds) {
        noteForTool(FindingKind::StaleTlo, tool,
            tr("T%1's TLO is dated %2, in the future: a clock was wrong, and when it was measured is not "
               "known.")
                .arg(n)
                .arg(facts.measuredAt.toString(Qt::ISODate)));
    } else if (facts.measuredAt.isValid() && !facts.isFresh(m_setup.now, m_setup.staleDays)) {
        noteForTool(FindingKind::StaleTlo, tool,
            tr("T%1's TLO was measured %2, before the stale limit (%3 d).")
                .arg(n)
                .arg(ageText(facts.measuredAt, m_setup.now))
                .arg(m_setup.staleDays));
    }
    if (facts.libraryTlo)
        noteForTool(FindingKind::StaleTlo, tool,
            tr("The history has a newer measurement of T%1 (%2, %3) than the table's: the table was not "
               "saved "
               "after it.")
                .arg(n)
                .arg(displayNumber(*facts.libraryTlo, m_setup.tableUnits) + u' '
                        + unitsSymbol(m_setup.tableUnits),
                    ageText(facts.libraryMeasuredAt, m_setup.now)));
}

} // namespace Toffee
