// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/formats/tablereading.h"

#include <algorithm>

#include <QCoreApplication>

#include "model/toolvalidation.h"

namespace Toffee {

namespace {

// Reserving for every line of a file would size memory by the file, not the table: up to this many, then
// grow.
constexpr qsizetype kMaxReserved = 131072; // 18 MB of tools at most, reserved for a file of as many lines

QString duplicateMessage(int number, int line)
{
    return QCoreApplication::translate(
        "Toffee::TableReading", "tool %1 is already on line %2; tool numbers must be unique.")
        .arg(number)
        .arg(line);
}

} // namespace

ToolCollector::ToolCollector(QByteArrayView data)
    : m_seen(size_t(Limits::kMaxToolNumber) + 1, false)
{
    const qsizetype lines = qsizetype(std::count(data.begin(), data.end(), '\n')) + 1;
    m_tools.reserve(std::min(lines, kMaxReserved));
    m_lines.reserve(m_tools.capacity());
}

Result<void> ToolCollector::add(Tool tool, int line, Units units)
{
    if (auto valid = validateTool(tool, units); !valid)
        return Error { valid.error().message, line };
    m_unitsAgree = m_unitsAgree && (!m_checkedIn || *m_checkedIn == units);
    m_checkedIn = units;
    if (m_seen[size_t(tool.number)]) {
        const auto earlier = std::find_if(
            m_tools.cbegin(), m_tools.cend(), [&tool](const Tool &t) { return t.number == tool.number; });
        return Error { duplicateMessage(tool.number, m_lines.at(earlier - m_tools.cbegin())), line };
    }
    m_seen[size_t(tool.number)] = true;
    m_tools.append(std::move(tool));
    m_lines.append(line);
    return {};
}

Result<ToolTable> ToolCollector::build(Units units)
{
    ToolTable::Problem problem;
    // Each tool was checked as it was read; only a table whose units turned out other than those it was
    // checked in (CSV learns them from its rows) is checked again.
    const bool checked = m_unitsAgree && (!m_checkedIn || *m_checkedIn == units);
    auto table = ToolTable::fromTools(std::move(m_tools), units, &problem,
        checked ? ToolTable::Validated::Already : ToolTable::Validated::No);
    if (table)
        return table;
    const auto lineOf = [this](qsizetype i) {
        return i >= 0 && i < m_lines.size() ? m_lines.at(i) : 0;
    };
    if (problem.duplicateOf >= 0)
        return Error { duplicateMessage(problem.number, lineOf(problem.duplicateOf)), lineOf(problem.index) };
    return Error { table.error().message, lineOf(problem.index) };
}

ChunkedWriter::ChunkedWriter(const ByteSink &sink)
    : m_sink(sink)
{
    out.reserve(kChunk + 64 * 1024);
}

bool ChunkedWriter::flush()
{
    if (m_ok && !out.isEmpty())
        m_ok = m_sink(out);
    out.resize(0); // keeps the capacity
    return m_ok;
}

} // namespace Toffee
