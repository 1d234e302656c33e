// SPDX-License-Identifier: GPL-3.0-or-later
#include "tablereading.h"

#include <algorithm>

#include <QCoreApplication>

namespace Toffee {

Result<ToolTable> buildTable(QList<Tool> tools, const QList<int> &lines, Units units)
{
    ToolTable::Problem problem;
    auto table = ToolTable::fromTools(std::move(tools), units, &problem);
    if (table)
        return table;
    const auto lineOf = [&lines](qsizetype i) {
        return i >= 0 && i < lines.size() ? lines.at(i) : 0;
    };
    if (problem.duplicateOf >= 0)
        return Error { QCoreApplication::translate("Toffee::TableReading",
                           "tool %1 is already on line %2; tool numbers must be unique.")
                           .arg(problem.number)
                           .arg(lineOf(problem.duplicateOf)),
            lineOf(problem.index) };
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

qsizetype countLines(QByteArrayView data)
{
    return qsizetype(std::count(data.begin(), data.end(), '\n')) + 1;
}

} // namespace Toffee
