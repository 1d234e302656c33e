// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/tooltable.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include <QCoreApplication>

#include "model/toolvalidation.h"
#include "model/translate.h"

namespace Toffee {

namespace {

Error duplicateError(int number)
{
    return Error { tr("tool number %1 is already in the table; tool numbers must be unique.").arg(number) };
}

} // namespace

Result<ToolTable> ToolTable::fromTools(QList<Tool> tools, Units units, Problem *problem, Validated validated)
{
    for (qsizetype i = 0; validated == Validated::No && i < tools.size(); ++i) {
        if (auto r = validateTool(tools.at(i), units); !r) {
            if (problem)
                *problem = { i, -1, tools.at(i).number };
            return r.error();
        }
    }
    // Files Toffee writes are in tool order: then the list is the table, with no copy.
    const auto ascending = std::adjacent_find(
        tools.cbegin(), tools.cend(), [](const Tool &a, const Tool &b) { return a.number >= b.number; });
    if (ascending == tools.cend()) {
        ToolTable table(units);
        table.m_tools = std::move(tools);
        return table;
    }
    // Sort a permutation, not the tools, so a duplicate can be reported at its place in the input.
    std::vector<qsizetype> order(tools.size());
    std::iota(order.begin(), order.end(), qsizetype(0));
    std::stable_sort(order.begin(), order.end(),
        [&tools](qsizetype a, qsizetype b) { return tools.at(a).number < tools.at(b).number; });
    for (size_t k = 1; k < order.size(); ++k) {
        if (tools.at(order[k]).number == tools.at(order[k - 1]).number) {
            if (problem)
                *problem = { order[k], order[k - 1], tools.at(order[k]).number };
            return duplicateError(tools.at(order[k]).number);
        }
    }
    ToolTable table(units);
    table.m_tools.reserve(tools.size());
    for (qsizetype i : order)
        table.m_tools.append(std::move(tools[i]));
    return table;
}

qsizetype ToolTable::insertionIndex(int number) const
{
    const auto it = std::lower_bound(
        m_tools.cbegin(), m_tools.cend(), number, [](const Tool &t, int n) { return t.number < n; });
    return it - m_tools.cbegin();
}

qsizetype ToolTable::indexOf(int number) const
{
    const qsizetype i = insertionIndex(number);
    return i < m_tools.size() && m_tools.at(i).number == number ? i : -1;
}

const Tool *ToolTable::find(int number) const
{
    const qsizetype i = indexOf(number);
    return i < 0 ? nullptr : &m_tools.at(i);
}

int ToolTable::nextFreeNumber(int from) const
{
    int candidate = std::max(from, 0);
    for (qsizetype i = insertionIndex(candidate); i < m_tools.size() && m_tools.at(i).number == candidate;
         ++i)
        ++candidate;
    return candidate <= Limits::kMaxToolNumber ? candidate : -1;
}

Result<void> ToolTable::checkInsert(const Tool &tool) const
{
    if (auto r = validateTool(tool, m_units); !r)
        return r;
    if (contains(tool.number))
        return duplicateError(tool.number);
    return {};
}

Result<void> ToolTable::checkReplace(int number, const Tool &tool) const
{
    if (!contains(number))
        return Error { tr("there is no tool %1 in the table.").arg(number) };
    if (auto r = validateTool(tool, m_units); !r)
        return r;
    if (tool.number != number && contains(tool.number))
        return duplicateError(tool.number);
    return {};
}

Result<void> ToolTable::insert(const Tool &tool)
{
    if (auto r = checkInsert(tool); !r)
        return r;
    m_tools.insert(insertionIndex(tool.number), tool);
    return {};
}

Result<void> ToolTable::replace(int number, const Tool &tool)
{
    if (auto r = checkReplace(number, tool); !r)
        return r;
    const qsizetype i = indexOf(number);
    if (tool.number == number) {
        m_tools[i] = tool;
        return {};
    }
    m_tools.removeAt(i);
    m_tools.insert(insertionIndex(tool.number), tool);
    return {};
}

Tool ToolTable::toolOrNew(int number) const
{
    if (const Tool *existing = find(number))
        return *existing;
    Tool tool;
    tool.number = number;
    tool.pocket = defaultPocket(number);
    return tool;
}

Result<void> ToolTable::recordMeasurement(
    int number, double tloMm, const QDateTime &at, TloSource source, std::optional<double> referenceMzMm)
{
    // A measured value is stored in the table's units at the machine's resolution (0.001 mm, 0.0001 in),
    // never with the noise of the arithmetic that produced it.
    const double steps = std::pow(10.0, resolutionDecimals(m_units));
    double tlo = fromMillimetres(tloMm, m_units);
    if (std::isfinite(tlo))
        tlo = std::round(tlo * steps) / steps;
    std::optional<double> referenceMz;
    if (referenceMzMm && std::isfinite(*referenceMzMm))
        referenceMz = std::round(fromMillimetres(*referenceMzMm, m_units) * steps) / steps;
    Tool tool = toolOrNew(number);
    tool.measuredTlo = tlo;
    tool.measuredAt = at.toUTC();
    tool.tloSource = source;
    tool.referenceMz = referenceMz;
    if (source == TloSource::Probe)
        tool.breakTestFailed = false;
    return contains(number) ? replace(number, tool) : insert(tool);
}

ProbePlan ToolTable::probePlan(int number) const
{
    const Tool *tool = find(number);
    return tool ? ProbePlan::of(tool->probing, tool->flutes, m_units) : ProbePlan {};
}

std::optional<StoredTlo> ToolTable::storedTlo(int number) const
{
    const Tool *tool = find(number);
    if (!tool || !tool->measuredTlo)
        return std::nullopt;
    // At the machine's 0.001 mm, so that what is sent is what the machine then reports.
    const auto machine = [this](double length) {
        return std::round(toMillimetres(length, m_units) * 1000.0) / 1000.0;
    };
    StoredTlo stored;
    stored.tlo = machine(*tool->measuredTlo);
    if (tool->referenceMz)
        stored.referenceMz = machine(*tool->referenceMz);
    stored.sameWithin = sameLengthWithin(m_units);
    stored.source = tool->tloSource;
    stored.measuredAt = tool->measuredAt;
    stored.breakTestFailed = tool->breakTestFailed;
    return stored;
}

Result<void> ToolTable::recordBreakTest(int number, bool failed)
{
    Tool tool = toolOrNew(number);
    tool.breakTestFailed = failed;
    return contains(number) ? replace(number, tool) : insert(tool);
}

Result<void> ToolTable::newCutter(int number)
{
    const Tool *found = find(number);
    if (!found)
        return Error { tr("T%1 is not in the table.").arg(number) };
    Tool tool = *found;
    tool.endCutter();
    return replace(number, tool);
}

Result<void> ToolTable::record(const Recording &r)
{
    if (r.kind == RecordingKind::Restore)
        return {}; // the table already holds the TLO that was set back: history only
    if (r.kind == RecordingKind::NewCutter)
        return newCutter(r.tool);
    if (r.tlo)
        return recordMeasurement(r.tool, *r.tlo, r.at, r.source, r.referenceMz);
    if (r.breakTestFailed)
        return recordBreakTest(r.tool, *r.breakTestFailed);
    return {};
}

Recording ToolTable::newCutterRecording(int number) const
{
    const auto stored = storedTlo(number);
    return Recording::newCutter(number, stored ? std::optional(stored->tlo) : std::nullopt,
        stored ? stored->referenceMz : std::nullopt);
}

Result<void> ToolTable::recordAll(const QList<Recording> &recordings)
{
    ToolTable next = *this;
    for (const Recording &r : recordings) {
        if (auto recorded = next.record(r); !recorded)
            return Error { tr("T%1: %2 Nothing was recorded.").arg(r.tool).arg(recorded.error().message) };
    }
    *this = std::move(next);
    return {};
}

bool ToolTable::remove(int number)
{
    const qsizetype i = indexOf(number);
    if (i < 0)
        return false;
    m_tools.removeAt(i);
    return true;
}

} // namespace Toffee
