// SPDX-License-Identifier: GPL-3.0-or-later
// The preparation's steps: the lines it writes, the Carvera's restores and break tests, the check of each
// cutting move against the original, and the side-by-side preview.
#include "model/job/jobpreparer.h"

#include <cmath>

#include "model/breaktestrule.h"
#include "model/gcode/gcodewords.h"
#include "model/job/jobchecker.h"
#include "model/numberformat.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

bool near(const Position &a, const Position &b)
{
    for (size_t i = 0; i < 3; ++i) {
        if (std::fabs(a[i] - b[i]) > 1e-6)
            return false;
    }
    return true;
}

// Where a line's comment starts (';', '(' or "//"), or its end.
qsizetype commentStart(QByteArrayView line)
{
    qsizetype at = line.size();
    for (const char *mark : { ";", "(", "//" }) {
        const qsizetype found = line.indexOf(QByteArrayView(mark));
        if (found >= 0 && found < at)
            at = found;
    }
    return at;
}

} // namespace

Result<void> JobPreparer::insertLine(const QString &line, const LineSink &sink, bool inserted)
{
    const QByteArray bytes = line.toUtf8();
    const int number = int(++m_summary.preparedLines);
    if (auto ran = m_prepared.runLine(bytes, number); !ran)
        return Error { tr("the line Toffee would insert here, \"%1\", is refused: %2 Nothing was written.")
                           .arg(line, ran.error().message),
            int(m_summary.originalLines) };
    if (m_prepared.lastBlock().motion != BlockEffect::Motion::None)
        return Error { tr("the line Toffee would insert here, \"%1\", would move the machine. Nothing was "
                          "written.")
                           .arg(line),
            int(m_summary.originalLines) };
    if (!sink(bytes))
        return Error { tr("the prepared program could not be written.") };
    if (inserted)
        ++m_summary.inserted;
    addRow({ 0, number, {}, line }, true);
    return {};
}

Result<void> JobPreparer::writeOriginal(
    QByteArrayView original, QByteArrayView prepared, int lineNumber, const LineSink &sink)
{
    const int number = int(++m_summary.preparedLines);
    if (!m_afterEnd) {
        if (auto ran = m_prepared.runLine(prepared, number); !ran)
            return Error { tr("the prepared line \"%1\" is refused: %2 Nothing was written.")
                               .arg(QString::fromUtf8(prepared), ran.error().message),
                lineNumber };
    }
    if (!sink(prepared))
        return Error { tr("the prepared program could not be written.") };
    if (m_changedLine)
        ++m_summary.changed;
    addRow({ lineNumber, number, QString::fromUtf8(original), QString::fromUtf8(prepared) }, m_changedLine);
    return {};
}

// M491.1 on the tool in the spindle, after its cutting before the next change (not its "last" cut: the
// program may load it again later, and it is tested again then): the spindle stopped first.
Result<void> JobPreparer::breakTest(const LineSink &sink)
{
    const int tool = m_tool;
    const int lastCut = m_lastCutLine;
    m_lastCutLine = 0;
    if (tool < 0 || isCarveraNonCutter(tool)) {
        noteOnce(tool,
            tr("The program cuts before any tool change (original line %1): there is no tool to "
               "break-test.")
                .arg(lastCut));
        return {};
    }
    // The firmware's own rules, as Check Rack and the Break Test panel follow them (breakTestExclusion): the
    // preview's note and a comment where the test would have gone say which tool was skipped, and why.
    if (const auto why = breakTestExclusion(tool)) {
        if (m_untested.insert(tool))
            ++m_summary.untestedTools;
        noteOnce(tool, breakTestExclusionText(*why, tool));
        return insertLine(comment(breakTestExclusionText(*why, tool, false)), sink, true);
    }
    if (m_prepared.spindleOn()) {
        if (auto r = insertLine(
                u"M5 "_s + comment(u"the spindle stops for T%1's break test"_s.arg(tool)), sink, true);
            !r)
            return r;
    }
    // The stored TLO of 0.000 (the reference tool's), which the firmware takes for none, is compared as
    // 0.001 (comparableTlo): set in force first.
    if (const auto stored = m_facts.value(tool).measuredTlo; stored && isZeroTlo(*stored)) {
        if (auto r = insertLine(u"M493.3 Z"_s + commandNumber(kZeroTloCompared) + u' '
                    + comment(
                        u"T%1's TLO 0.000 as 0.001 mm, which the firmware's break test compares with"_s.arg(
                            tool)),
                sink, true);
            !r)
            return r;
    }
    return insertLine(u"M491.1 H"_s + commandNumber(m_options.tolerance) + u' '
            + comment(u"break test of T%1 after its cuts up to original line %2, tolerance %3 mm"_s.arg(tool)
                          .arg(lastCut)
                          .arg(commandNumber(m_options.tolerance))),
        sink, true);
}

std::optional<double> JobPreparer::restorable(int tool)
{
    if (isCarveraNonCutter(tool))
        return std::nullopt;
    if (m_rack.contains(tool)) {
        noteOnce(tool, tr("T%1 is in the rack: the Carvera measures a rack tool at every change.").arg(tool));
        return std::nullopt;
    }
    const auto tlo = restorableTlo(
        tool, m_facts.value(tool), m_options.now, m_options.staleDays, m_options.machineReferenceMz);
    if (!tlo) {
        noteOnce(tool, tlo.error().message);
        return std::nullopt;
    }
    return tlo.value();
}

QString JobPreparer::carveraChange(QByteArrayView line, int tool)
{
    const auto block = GCodeBlock::read(line);
    if (!block || block.value().find('H'))
        return {}; // the program sets the TLO itself
    const auto tlo = restorable(tool);
    if (!tlo)
        return {};
    const qsizetype cut = commentStart(line);
    const QString before = QString::fromUtf8(line.first(cut)).trimmed();
    const QString own = QString::fromUtf8(line.sliced(cut)).trimmed(); // the program's own comment stays
    return before + u" H"_s + commandNumber(*tlo) + u' '
        + comment(u"was \"%1\": T%2 takes its stored TLO instead of a probe"_s.arg(before).arg(tool))
        + (own.isEmpty() ? QString() : u' ' + own);
}

// The seed's restore (M493.2 T, M493.3 Z) after a change that did not probe: the stock firmware ignores
// M6's H, the community firmware takes either.
Result<void> JobPreparer::restoreAfterChange(int tool, const LineSink &sink)
{
    const ToolFacts facts = m_facts.value(tool);
    const double tlo = *facts.measuredTlo;
    if (auto same = sameReference(tool, facts); !same)
        return same;
    // A date, not an age: the program is kept and run later.
    const QString when = facts.measuredAt.toUTC().toString(u"yyyy-MM-dd HH:mm"_s) + u" UTC"_s;
    QString measured = facts.source == TloSource::Manual ? u"set by hand %1"_s.arg(when)
        : facts.source == TloSource::Pulled              ? u"read from the controller %1"_s.arg(when)
                                                         : u"measured %1"_s.arg(when);
    if (facts.referenceMz)
        measured += u" against reference MCS Z %1"_s.arg(commandNumber(*facts.referenceMz));
    if (auto r = insertLine(u"M493.2 T"_s + QString::number(tool) + u' '
                + comment(u"T%1 is the tool in the spindle"_s.arg(tool)),
            sink, true);
        !r)
        return r;
    return insertLine(u"M493.3 Z"_s + commandNumber(tlo) + u' '
            + comment(u"T%1's stored TLO, %2"_s.arg(tool).arg(measured)),
        sink, true);
}

// After each move of the original: the prepared program is at the same work position on every axis the block
// named, at the same machine position across the length axis, and its length axis carries the offset it
// should: the original's, or the tool's own where a G43 was inserted for it. A move in machine coordinates
// (G53, G28) ends at the same machine position. Where a G43 was inserted, the positions along the length axis
// differ by design, until the next tool's own offset is in force.
Result<void> JobPreparer::compare(int lineNumber)
{
    const BlockEffect &effect = m_original.lastBlock();
    if (effect.motion == BlockEffect::Motion::None)
        return {};
    const bool feed = effect.motion == BlockEffect::Motion::Feed;
    if (feed)
        ++m_summary.cuttingMoves;
    const Position &a = m_original.position();
    const Position &b = m_prepared.position();
    const size_t axis = size_t(m_original.lengthAxis());
    const Error elsewhere {
        tr("the prepared program would put the machine elsewhere than the original with the "
           "table's offsets. Nothing was written."),
        lineNumber
    };
    if (effect.machineCoordinates)
        return near(a, b) ? Result<void>() : Result<void>(elsewhere);
    for (size_t i = 0; i < 3; ++i) {
        if (i == axis && !effect.lengthAxisWord)
            continue;
        if (std::fabs(m_original.workPosition()[i] - m_prepared.workPosition()[i]) > 1e-6)
            return Error { tr("the prepared program would cut at another work position than the original. "
                              "Nothing was written."),
                lineNumber };
        if (i != axis && std::fabs(a[i] - b[i]) > 1e-6)
            return elsewhere;
    }
    if (!effect.lengthAxisWord && !feed)
        return {};
    const LengthCompensation original = m_original.lengthCompensation();
    const LengthCompensation prepared = m_prepared.lengthCompensation();
    const bool calledSince = m_original.lengthCalls() != m_callsAtInsertion;
    const int tool = m_original.loadedTool();
    const auto offset = m_offsets.find(tool);
    // The offset the prepared program must carry: the tool's own, where a G43 was inserted for it and the
    // program called none since; the one the program called since where the original has none in force; the
    // original's otherwise.
    double expected = original.value;
    if (m_compensated && !calledSince)
        expected = offset != m_offsets.end() ? offset->second.length() : 0.0;
    else if (m_compensated && !original.active && prepared.active)
        expected = original.latched;
    if (std::fabs(prepared.value - expected) < 1e-6)
        return {};
    return m_compensated
        ? Error { tr("the prepared program would cut without T%1's length offset. Nothing was "
                     "written.")
                      .arg(tool),
              lineNumber }
        : elsewhere;
}

// The machine has one reference: stored TLOs measured against two cannot both be right.
Result<void> JobPreparer::sameReference(int tool, const ToolFacts &facts)
{
    if (!facts.referenceMz) {
        noteOnce(-2 - tool,
            tr("T%1's stored TLO does not say which reference it was measured against: check that "
               "it still holds.")
                .arg(tool));
        return {};
    }
    if (m_restoredReference && std::fabs(*m_restoredReference - *facts.referenceMz) > 0.0005)
        return Error { tr(
            "T%1's stored TLO was measured against reference MCS Z %2 and T%3's against %4: the machine "
            "has one reference, so at most one is right. Probe one of them again, or prepare without "
            "stored TLOs. Nothing was written.")
                           .arg(tool)
                           .arg(commandNumber(*facts.referenceMz))
                           .arg(m_restoredTool)
                           .arg(commandNumber(*m_restoredReference)) };
    if (!m_restoredReference) {
        m_restoredReference = facts.referenceMz;
        m_restoredTool = tool;
        m_summary.notes.append(
            tr("The stored TLOs hold only while the machine's reference MCS Z is %1 (its calibration): "
               "check it before running the program.")
                .arg(commandNumber(*facts.referenceMz)));
    }
    return {};
}

// `tool`, or -2 - tool for its reference's note.
void JobPreparer::noteOnce(int tool, const QString &note)
{
    const bool reference = tool < Limits::kEmptySpindle;
    const int number = reference ? -2 - tool : tool;
    if (!(reference ? m_notedReference : m_noted).insert(number))
        return;
    if (m_summary.notes.size() < kMaxNotes) {
        m_summary.notes.append(note);
        return;
    }
    if (m_moreNotes++ == 0)
        m_firstMoreNoted = number;
}

void JobPreparer::addRow(const PrepareRow &row, bool changed)
{
    if (changed) {
        if (m_hunk.isEmpty())
            m_hunk = m_context;
        m_context.clear();
        m_hunk.append(row);
        m_trailing = 0;
        if (m_hunk.size() >= kMaxHunkRows)
            closeHunk();
        return;
    }
    if (!m_hunk.isEmpty()) {
        m_hunk.append(row);
        if (++m_trailing == kContextLines)
            closeHunk();
        return;
    }
    m_context.append(row);
    if (m_context.size() > kContextLines)
        m_context.removeFirst();
}

void JobPreparer::closeHunk()
{
    if (m_summary.hunks.size() < kMaxHunks)
        m_summary.hunks.append(m_hunk);
    else
        ++m_summary.moreHunks;
    m_hunk.clear();
    m_trailing = 0;
}

} // namespace Toffee
