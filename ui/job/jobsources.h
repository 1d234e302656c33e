// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QHash>

#include <QString>

#include "model/gcode/dialect.h"
#include "model/job/jobcheck.h"
#include "model/library/librarylocation.h"
#include "model/tooltable.h"

namespace Toffee {

// What a job check and a preparation in the window read besides the program: the table as it is now (a copy)
// and its file, the history library (when it exists), this machine's name in it, the stale limit, and the
// machine's reference MCS Z when the window is connected and knows it.
struct JobSources
{
    ToolTable table;
    QString tablePath;
    std::optional<LibraryLocation> library;
    QString machine;
    int staleDays = 7;
    std::optional<double> machineReferenceMz;
    // What the connected controller's own table holds (grblHAL's), by tool: the check compares.
    std::optional<QHash<int, double>> controllerTlos;
    // The connected machine's dialect when it says it (grblHAL's), over the remembered choice.
    std::optional<Dialect> machineDialect;
};

// The library's facts for a job's tools, read on the thread that calls it (a library connection belongs to
// one thread); nothing when there is no library. Opened only when it exists: a check creates no library.
[[nodiscard]] Result<void> addHistoryFacts(
    const JobSources &sources, QHash<int, ToolFacts> &facts, const QList<int> &tools);

} // namespace Toffee
