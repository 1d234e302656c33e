// SPDX-License-Identifier: GPL-3.0-or-later
// The job check's end: each tool the program loads against what the table and the library know of it.
#include "model/job/jobchecker.h"

#include <algorithm>
#include <cmath>

#include "model/clock.h"
#include "model/numberformat.h"
#include "model/timetext.h"

using namespace Qt::StringLiterals;

namespace Toffee {

JobReport JobChecker::finish(const QString &program, bool cancelled)
{
    JobReport report;
    report.program = program;
    report.dialect = m_setup.dialect;
    report.lines = m_lines;
    report.cancelled = cancelled;
    report.tools.reserve(m_tools.size());
    for (JobTool tool : std::as_const(m_tools)) {
        const ToolFacts facts = m_setup.facts.value(tool.number);
        tool.inTable = facts.inTable;
        tool.tlo = measuresTlos(m_setup.dialect) ? facts.measuredTlo
            : facts.inTable                      ? std::optional(facts.length)
                                                 : std::nullopt;
        tool.measuredAt = facts.measuredAt;
        tool.setByHand = facts.measuredTlo && facts.source == TloSource::Manual;
        report.tools.append(tool);
        toolFindings(tool);
    }
    report.moreTools = m_moreTools;
    report.moreLoads = m_moreLoads;
    report.moreFromLine = m_moreFromLine;
    for (Finding &f : m_findings) {
        if (f.moreTools > 0 && f.message.isEmpty()) {
            f.message = moreMessage(f);
            f.tool = -1; // it stands for many
        }
    }
    report.cuttingSeconds = m_cuttingSeconds;
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

template<typename Found> void JobChecker::judgeTool(int n, const ToolFacts &facts, Found found) const
{
    const bool carvera = m_setup.dialect == Dialect::Carvera;
    // T0 is no tool on the other controllers (LinuxCNC's empty spindle), the wireless probe on the Carvera.
    if (n == 0 || (carvera && isCarveraNonCutter(n)))
        return;
    if (m_setup.rack && !inRack(n))
        found(FindingKind::ManualChange, [n] {
            return tr(
                "The machine's rack does not hold T%1: it is a manual change, and the machine waits for "
                "the operator.")
                .arg(n);
        });
    if (m_setup.hasTable && !facts.inTable) {
        found(FindingKind::MissingTool,
            [n] { return tr("T%1 is not in the tool table: nothing is known of its length.").arg(n); });
        return;
    }
    if (facts.broken)
        found(FindingKind::BrokenTool, [n] {
            return tr("T%1 failed its last break test and has not been measured since: check the tool and "
                      "probe it.")
                .arg(n);
        });
    // The Carvera and grblHAL take the TLO Toffee measured; the other controllers the table's length.
    const bool tlos = measuresTlos(m_setup.dialect);
    const bool measured = tlos ? facts.measuredTlo.has_value() : (facts.measuredTlo || facts.length != 0.0);
    if (!measured) {
        found(FindingKind::NotMeasured, [n, tlos] {
            return tlos ? tr("T%1 has no measured TLO.").arg(n)
                        : tr("T%1 has no length in the table: G43 would apply 0.").arg(n);
        });
    } else if (tlos && facts.source == TloSource::Manual) {
        found(FindingKind::NotMeasured, [n] {
            return tr("T%1's TLO was set by hand, not measured on the tool setter: probe it before the job.")
                .arg(n);
        });
    } else if (tlos && facts.source == TloSource::Pulled) {
        found(FindingKind::NotMeasured, [n] {
            return tr(
                "T%1's TLO was read from the controller's table, not measured on the tool setter: probe "
                "it before the job.")
                .arg(n);
        });
    } else if (Clock::isInFuture(facts.measuredAt, m_setup.now)) {
        found(FindingKind::StaleTlo, [n, &facts] {
            return tr("T%1's TLO is dated %2, in the future: a clock was wrong, and when it was measured is "
                      "not known.")
                .arg(n)
                .arg(facts.measuredAt.toString(Qt::ISODate));
        });
    } else if (facts.measuredAt.isValid() && !facts.isFresh(m_setup.now, m_setup.staleDays)) {
        found(FindingKind::StaleTlo, [this, n, &facts] {
            return tr("T%1's TLO was measured %2, before the stale limit (%3 d).")
                .arg(n)
                .arg(ageText(facts.measuredAt, m_setup.now))
                .arg(m_setup.staleDays);
        });
    }
    if (m_setup.controllerTlos && facts.measuredTlo) {
        const auto entry = m_setup.controllerTlos->constFind(n);
        const double tlo = *facts.measuredTlo;
        if (entry == m_setup.controllerTlos->cend())
            found(FindingKind::ControllerTableDiffers, [n] {
                return tr("The controller's own table has no T%1: G43 H%1 is refused. Renumber the tool, or "
                          "apply its TLO with G43.1.")
                    .arg(n);
            });
        else if (std::fabs(*entry - tlo) > facts.sameWithin)
            found(FindingKind::ControllerTableDiffers, [n, tlo, value = *entry] {
                return tr("The controller's own table holds %1 for T%2, the table file %3: G43 H%2 would "
                          "apply the controller's. Push the offsets (Machine ▸ Push Offsets…, toffee-cli "
                          "push-offsets) or probe T%2 before the job.")
                    .arg(millimetres(value))
                    .arg(n)
                    .arg(millimetres(tlo));
            });
    }
    if (facts.newCutterAt.isValid())
        found(FindingKind::StaleTlo, [this, n, &facts] {
            return tr(
                "The history says T%1 got a new cutter %2, after the table's TLO was measured: that TLO is "
                "the old cutter's. Probe T%1 before the job.")
                .arg(n)
                .arg(ageText(facts.newCutterAt, m_setup.now));
        });
    if (facts.libraryTlo)
        found(FindingKind::StaleTlo, [this, n, &facts] {
            return tr("The history has a newer measurement of T%1 (%2, %3) than the table's: the table was "
                      "not saved "
                      "after it.")
                .arg(n)
                .arg(millimetres(*facts.libraryTlo), ageText(facts.libraryMeasuredAt, m_setup.now));
        });
}

void JobChecker::toolFindings(const JobTool &tool)
{
    const ToolFacts facts = m_setup.facts.value(tool.number);
    judgeTool(tool.number, facts,
        [this, &tool](FindingKind kind, const auto &message) { noteForTool(kind, tool, message()); });
    lifeFinding(tool, facts);
    if (facts.spreadLimit && facts.lastSpread && *facts.lastSpread > *facts.spreadLimit + 1e-9)
        noteForTool(FindingKind::SpreadExceeded, tool,
            tr("T%1's edges differed by %2 when it was last measured, more than its limit %3: runout or a "
               "chipped edge. Look at the cutter and how it sits in its holder before it cuts.")
                .arg(tool.number)
                .arg(millimetres(*facts.lastSpread), millimetres(*facts.spreadLimit)));
}

// As FANUC's tool-life management counts: the minutes of cutting and the programs since the cutter went in,
// with this program's added, against the tool's limits.
void JobChecker::lifeFinding(const JobTool &tool, const ToolFacts &facts)
{
    if (!facts.inTable || (!facts.lifeLimitMinutes && !facts.lifeLimitUses))
        return;
    const int n = tool.number;
    const double after = facts.used.seconds + tool.cuttingSeconds;
    if (facts.lifeLimitMinutes && facts.used.seconds > *facts.lifeLimitMinutes * 60.0 + 1e-6) {
        noteForTool(FindingKind::LifeExceeded, tool,
            tr("T%1 is past its life limit of %2 min already: its cutter has cut %3 since it went in, and "
               "the "
               "program cuts %4 more. Put in a new cutter (Edit ▸ New Cutter…, toffee-cli new-cutter %1) or "
               "raise "
               "the limit.")
                .arg(n)
                .arg(formatNumber(*facts.lifeLimitMinutes, NumberFormat::upTo(3)))
                .arg(durationText(facts.used.seconds), durationText(tool.cuttingSeconds)));
        return;
    }
    if (facts.lifeLimitMinutes && after > *facts.lifeLimitMinutes * 60.0 + 1e-6) {
        noteForTool(FindingKind::LifeExceeded, tool,
            tr("T%1 would pass its life limit of %2 min in this program: its cutter has cut %3 since it went "
               "in, and the program cuts %4 more. Put in a new cutter (Edit ▸ New Cutter…, toffee-cli "
               "new-cutter %1) or raise the limit.")
                .arg(n)
                .arg(formatNumber(*facts.lifeLimitMinutes, NumberFormat::upTo(3)))
                .arg(durationText(facts.used.seconds), durationText(tool.cuttingSeconds)));
        return;
    }
    if (facts.lifeLimitUses && facts.used.uses + 1 > *facts.lifeLimitUses)
        noteForTool(FindingKind::LifeExceeded, tool,
            tr("T%1 would pass its life limit of %2 uses: its cutter has cut in %3 programs since it went "
               "in, "
               "and this is one more. Put in a new cutter (Edit ▸ New Cutter…, toffee-cli new-cutter %1) or "
               "raise the limit.")
                .arg(n)
                .arg(*facts.lifeLimitUses)
                .arg(facts.used.uses));
}

void JobChecker::countMoreTool(int number, int line, bool first)
{
    static const ToolFacts unknown;
    const auto found = m_setup.facts.constFind(number);
    const ToolFacts &facts = found != m_setup.facts.cend() ? *found : unknown;
    quint32 counted = 0; // a kind once a load (a stale TLO can be found twice)
    judgeTool(number, facts, [&](FindingKind kind, const auto &) {
        const quint32 bit = quint32(1) << int(kind);
        if (!(counted & bit))
            noteMore(kind, number, line, first);
        counted |= bit;
    });
}

QString JobChecker::moreMessage(const Finding &summary) const
{
    const qint64 n = summary.moreTools;
    QString what;
    switch (summary.kind) {
    case FindingKind::MissingTool:
        what = tr("%1 more tools the table lacks").arg(n);
        break;
    case FindingKind::ManualChange:
        what = tr("%1 more tools the machine's rack does not hold (manual changes)").arg(n);
        break;
    case FindingKind::NotMeasured:
        what = tr("%1 more tools with no TLO measured on the tool setter").arg(n);
        break;
    case FindingKind::StaleTlo:
        what = tr("%1 more tools whose TLO is older than the stale limit (%2 d) or dated in the future")
                   .arg(n)
                   .arg(m_setup.staleDays);
        break;
    case FindingKind::BrokenTool:
        what = tr("%1 more tools that failed their last break test").arg(n);
        break;
    case FindingKind::BelowFloor:
        what = tr("%1 more tools feed below the floor of %2")
                   .arg(n)
                   .arg(millimetres(m_setup.zFloor.value_or(0.0), false));
        break;
    case FindingKind::NoLengthCompensation:
        what = tr("%1 more tools cut with no length compensation").arg(n);
        break;
    case FindingKind::LengthOffsetMismatch:
        what = tr("%1 more tools cut with another tool's length offset").arg(n);
        break;
    case FindingKind::ProgramSetsTlo:
        what = tr("%1 more tools have their TLO set by the program to another value than the table's").arg(n);
        break;
    case FindingKind::ControllerTableDiffers:
        what = tr("%1 more tools whose TLO in the controller's own table is not the file's").arg(n);
        break;
    default: // not a tool's finding: never summed up
        what = u"%1 more tools: %2"_s.arg(n).arg(findingKey(summary.kind));
        break;
    }
    // What the history knows could change these three; it is read for the listed tools only.
    const bool fromTable = summary.kind == FindingKind::NotMeasured || summary.kind == FindingKind::StaleTlo
        || summary.kind == FindingKind::BrokenTool;
    return (fromTable
            ? tr("%1, beyond the first %2 tools the program loads; the first of them is T%3. Counted, "
                 "not listed, and judged by the table alone: the history library is read for the "
                 "listed tools only.")
            : tr("%1, beyond the first %2 tools the program loads; the first of them is T%3. Counted, "
                 "not listed."))
        .arg(what)
        .arg(kMaxListedTools)
        .arg(summary.tool);
}

} // namespace Toffee
