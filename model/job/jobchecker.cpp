// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/job/jobchecker.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/limits.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/timetext.h"
#include "model/tooltable.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

quint64 aggregateKey(FindingKind kind, int tool)
{
    return (quint64(kind) << 32) | quint32(tool);
}

// The key of a kind's summary of the tools beyond the list: no tool has this number.
constexpr int kMoreToolsKey = std::numeric_limits<int>::min();

} // namespace

void JobCheckSetup::useTable(const ToolTable &table)
{
    hasTable = true;
    tableUnits = table.units();
    offsets = offsetTableFor(table, dialect);
    facts = factsFromTable(table);
}

QList<int> carveraRack()
{
    return { 1, 2, 3, 4, 5, 6 };
}

Result<QList<int>> parseRack(const QString &text)
{
    if (text.trimmed() == u"none"_s)
        return QList<int> {};
    const Error refused { tr("a rack is \"none\", or tool numbers and ranges such as 1-6 or 1,2,5-8.") };
    QList<int> tools;
    for (const QString &item : text.split(u',')) {
        const QStringList ends = item.trimmed().split(u'-');
        const auto first = parseInteger(ends.value(0).trimmed().toUtf8());
        const auto last = ends.size() == 2 ? parseInteger(ends.value(1).trimmed().toUtf8()) : first;
        if (ends.size() > 2 || !first || !last || *first < 0 || *last < *first
            || *last > Limits::kMaxToolNumber || *last - *first > 9999)
            return refused;
        for (qint64 n = *first; n <= *last; ++n)
            tools.append(int(n));
    }
    return tools;
}

QString rackText(const QList<int> &rack)
{
    if (rack.isEmpty())
        return u"none"_s;
    QStringList parts;
    for (qsizetype i = 0; i < rack.size();) {
        qsizetype j = i;
        while (j + 1 < rack.size() && rack.at(j + 1) == rack.at(j) + 1)
            ++j;
        parts << (j > i ? u"%1-%2"_s.arg(rack.at(i)).arg(rack.at(j)) : QString::number(rack.at(i)));
        i = j + 1;
    }
    return parts.join(u',');
}

bool isCarveraNonCutter(int tool)
{
    return tool == Limits::kEmptySpindle || tool == 0 || tool >= 999990;
}

JobChecker::JobChecker(JobCheckSetup setup)
    : m_setup(std::move(setup))
    , m_interpreter(m_setup.dialect, m_setup.offsets)
{
    static_assert(int(FindingKind::ProgramSetsTlo) < std::tuple_size_v<decltype(m_moreCounted)>);
    m_interpreter.setRecordMoves(false);
    // Each block's feed goes to the listed tool it cut with (feed()): the interpreter keeps none per tool.
    m_interpreter.setKeepToolUsage(false);
    for (int tool : m_setup.rack.value_or(QList<int> {}))
        m_rack.insert(tool);
}

void JobChecker::feed(QByteArrayView line, int lineNumber)
{
    if (m_interpreter.ended())
        return;
    ++m_lines;
    if (auto r = m_interpreter.runLine(line, lineNumber); !r) {
        programError(r.error());
        return;
    }
    const BlockEffect &effect = m_interpreter.lastBlock();
    if (effect.unitsWord)
        unitsChanged(lineNumber);
    if (effect.toolChange)
        toolChanged(lineNumber);
    if (effect.setsTlo)
        tloSet(lineNumber);
    if (effect.motion == BlockEffect::Motion::Feed)
        feedMove(lineNumber, effect);
    if (effect.feedPathMm != 0.0 || effect.cuttingSeconds != 0.0) {
        m_cuttingSeconds += effect.cuttingSeconds;
        if (m_current >= 0) {
            JobTool &tool = m_tools[m_current];
            tool.cuttingSeconds += effect.cuttingSeconds;
            tool.feedPathMm += effect.feedPathMm;
        }
    }
}

void JobChecker::toolChanged(int line)
{
    m_compensationDue = true;
    m_callsAtChange = m_interpreter.lengthCalls();
    const int number = m_interpreter.loadedTool();
    auto found = m_toolIndex.constFind(number);
    if (found == m_toolIndex.cend() && m_tools.size() >= kMaxListedTools) {
        m_current = kBeyondList;
        const bool first = m_moreSeen.insert(number);
        if (first && m_moreTools++ == 0)
            m_moreFromLine = line;
        ++m_moreLoads;
        countMoreTool(number, line, first);
        return;
    }
    if (found == m_toolIndex.cend()) {
        JobTool tool;
        tool.number = number;
        m_tools.append(tool);
        found = m_toolIndex.insert(number, m_tools.size() - 1);
    }
    m_current = *found;
    JobTool &tool = m_tools[m_current];
    if (tool.loadLines.size() < kMaxLinesPerFinding)
        tool.loadLines.append(line);
    ++tool.loads;
}

void JobChecker::feedMove(int line, const BlockEffect &effect)
{
    if (m_current == -1) {
        note(FindingKind::NoToolLoaded, -1, line, [] {
            return tr("A feed move before any tool change: the program does not say which tool is in the "
                      "spindle.");
        });
    } else if (!effect.machineCoordinates && m_current >= 0) {
        JobTool &tool = m_tools[m_current];
        if (!tool.lowestZ || effect.lowestZ < *tool.lowestZ)
            tool.lowestZ = effect.lowestZ;
    }
    if (m_setup.zFloor && effect.lowestZ < *m_setup.zFloor - 1e-9 && !effect.machineCoordinates) {
        const int tool = m_interpreter.loadedTool();
        const double z = effect.lowestZ;
        note(FindingKind::BelowFloor, tool, line, [this, tool, z] {
            return tool >= 0 ? tr("T%1 feeds to work Z %2, below the floor of %3.")
                                   .arg(tool)
                                   .arg(millimetres(z, false), millimetres(*m_setup.zFloor, false))
                             : tr("A feed move to work Z %1, below the floor of %2.")
                                   .arg(millimetres(z, false), millimetres(*m_setup.zFloor, false));
        });
    }
    if (usesG43(m_setup.dialect) && m_current != -1)
        checkCompensation(line);
}

// After a tool change, and whenever the offset in force changes: is it this tool's?
void JobChecker::checkCompensation(int line)
{
    const LengthCompensation comp = m_interpreter.lengthCompensation();
    if (!m_compensationDue && comp.active == m_checkedActive && comp.reg == m_checkedRegister)
        return;
    m_compensationDue = false;
    m_checkedActive = comp.active;
    m_checkedRegister = comp.reg;
    const int tool = m_interpreter.loadedTool();
    if (!comp.active) {
        note(FindingKind::NoLengthCompensation, tool, line, [tool] {
            return tr("T%1 cuts with no length compensation: no G43 since it was loaded.").arg(tool);
        });
    } else if (comp.reg > 0 && comp.reg != tool) {
        const QString letter = m_setup.dialect == Dialect::Fagor8055M ? u"D"_s : u"H"_s;
        const bool stale = m_interpreter.lengthCalls() == m_callsAtChange;
        note(FindingKind::LengthOffsetMismatch, tool, line, [tool, comp, letter, stale] {
            const QString n = QString::number(tool);
            const QString reg = QString::number(comp.reg);
            return stale
                ? tr("T%1 cuts with %2%3 still in force from the tool before: no G43 %2%1 since its "
                     "change.")
                      .arg(n, letter, reg)
                : tr("T%1 cuts with the length offset %2%3, which is another tool's.").arg(n, letter, reg);
        });
    }
}

// The program sets the TLO itself: a break test then compares against it, and every cut follows it.
void JobChecker::tloSet(int line)
{
    const int tool = m_interpreter.loadedTool();
    const double set = m_interpreter.lengthCompensation().latched;
    const ToolFacts facts = m_setup.facts.value(tool);
    if (!facts.measuredTlo || std::fabs(*facts.measuredTlo - set) < 0.0005)
        return;
    note(FindingKind::ProgramSetsTlo, tool, line, [tool, set, &facts] {
        return tr("The program sets T%1's TLO to %2 itself; the table holds %3 for it.")
            .arg(tool)
            .arg(millimetres(set, false), millimetres(*facts.measuredTlo, false));
    });
}

void JobChecker::unitsChanged(int line)
{
    const Units units = *m_interpreter.programUnits();
    if (m_setup.dialect == Dialect::Carvera && units == Units::Inch) {
        note(FindingKind::InchOnCarvera, -1, line, [] {
            return tr("G20: the Carvera refuses inch programs (ALARM: Imperial Units are unsupported). Post "
                      "the program in millimetres.");
        });
    } else if (m_setup.hasTable && units != m_setup.tableUnits && !measuresTlos(m_setup.dialect)) {
        // Where the controller measures its TLOs (the Carvera, grblHAL), they are its millimetres whatever
        // the table's units: only a table whose lengths are the controller's offsets must share the
        // program's.
        note(FindingKind::UnitsMismatch, -1, line, [units] {
            return units == Units::Inch
                ? tr("The program is in inches (G20) but the tool table is in millimetres.")
                : tr("The program is in millimetres (G21) but the tool table is in inches.");
        });
    }
}

void JobChecker::programError(const Error &error)
{
    if (m_programErrors < kMaxProgramErrors) {
        ++m_programErrors;
        m_findings.append({ FindingKind::ProgramError, error.line, m_interpreter.loadedTool(), error.message,
            { error.line }, 1 });
        return;
    }
    if (m_moreProgramErrors++ == 0)
        m_firstUncountedError = error.line;
}

template<typename Message> void JobChecker::note(FindingKind kind, int tool, int line, Message message)
{
    // A finding of a tool is the loaded one's; units and a feed before any change are no tool's.
    const bool ofTool = kind != FindingKind::NoToolLoaded && kind != FindingKind::UnitsMismatch
        && kind != FindingKind::InchOnCarvera;
    if (m_current == kBeyondList && ofTool) {
        noteMore(kind, tool, line, m_moreCounted[size_t(kind)].insert(tool));
        return;
    }
    const quint64 key = aggregateKey(kind, tool);
    if (const auto found = m_findingIndex.constFind(key); found != m_findingIndex.cend()) {
        Finding &f = m_findings[*found];
        if (f.lines.size() < kMaxLinesPerFinding)
            f.lines.append(line);
        ++f.count;
        return;
    }
    m_findingIndex.insert(key, m_findings.size());
    m_findings.append({ kind, line, tool, message(), { line }, 1 });
}

void JobChecker::noteMore(FindingKind kind, int tool, int line, bool newTool)
{
    const quint64 key = aggregateKey(kind, kMoreToolsKey);
    auto found = m_findingIndex.constFind(key);
    if (found == m_findingIndex.cend()) {
        // Its message is made at the end, when the count is known; until then `tool` is the first one's.
        found = m_findingIndex.insert(key, m_findings.size());
        m_findings.append({ kind, line, tool, QString(), {}, 0, 0 });
    }
    Finding &f = m_findings[*found];
    if (f.lines.size() < kMaxLinesPerFinding)
        f.lines.append(line);
    ++f.count;
    if (newTool)
        ++f.moreTools;
}

QList<int> JobChecker::toolNumbers() const
{
    QList<int> numbers;
    for (const JobTool &t : m_tools)
        numbers.append(t.number);
    return numbers;
}

Result<void> JobChecker::addFacts(const JobFactSource &source)
{
    if (!source)
        return {};
    QHash<int, ToolFacts> facts = m_setup.facts;
    if (auto added = source(facts, toolNumbers()); !added)
        return added;
    m_setup.facts = std::move(facts);
    return {};
}

} // namespace Toffee
