// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the three table readers; not part of the model's interface.
#pragma once

#include "tablefile.h"
#include "tooltable.h"

namespace Toffee {

// The table from a reader's tools, or the first problem with the line of the tool it is on:
// lines[i] is the line tools[i] was read from.
[[nodiscard]] Result<ToolTable> buildTable(QList<Tool> tools, const QList<int> &lines, Units units);

// How many lines `data` has: a reader reserves that many tools up front rather than growing its list.
[[nodiscard]] qsizetype countLines(QByteArrayView data);

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
