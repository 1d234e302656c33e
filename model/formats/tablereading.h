// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the three table readers; not part of the model's interface.
#pragma once

#include <optional>
#include <vector>

#include "model/formats/tablefile.h"
#include "model/tooltable.h"

namespace Toffee {

// Gathers a reader's tools as it reads them and checks each at once: the first tool that is not valid, or
// whose number came before, stops the reader at its line. Memory grows with the table, never with the file:
// a giant file of one repeated row fails at its second row.
class ToolCollector
{
public:
    // `data`: the file, to reserve room for about as many tools as it has lines, within reason.
    explicit ToolCollector(QByteArrayView data);

    // `units`: the table's, when the reader knows them yet; a CSV table learns its units from its rows, so
    // until then the larger (millimetre) limits apply, and build() checks again with the table's own.
    [[nodiscard]] Result<void> add(Tool tool, int line, Units units = Units::Millimetre);
    [[nodiscard]] Result<ToolTable> build(Units units);

private:
    QList<Tool> m_tools;
    QList<int> m_lines; // m_lines[i] is the line m_tools[i] was read from
    std::optional<Units> m_checkedIn; // the units every tool so far was validated in, while they agree
    bool m_unitsAgree = true;
    std::vector<bool> m_seen; // by tool number
};

// Collects a writer's output and hands it to the sink a megabyte at a time.
class ChunkedWriter
{
public:
    explicit ChunkedWriter(const ByteSink &sink);
    QByteArray out;
    // After each tool: passes the piece on once it is big enough.
    bool next() { return out.size() < kChunk || flush(); }
    bool finish() { return flush(); }

private:
    bool flush();
    static constexpr qsizetype kChunk = 1 << 20;
    const ByteSink &m_sink;
    bool m_ok = true;
};

// A writer's whole output as one array, for the QByteArray overloads.
template<typename Writer> QByteArray collect(const ToolTable &table, Writer write)
{
    QByteArray all;
    write(table, [&all](QByteArrayView piece) {
        all += piece;
        return true;
    });
    return all;
}

} // namespace Toffee
