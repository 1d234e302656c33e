// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

#include "model/job/jobcheck.h"
#include "model/job/jobpreparer.h"

namespace Toffee {

// What a preparation must not do or must also know.
struct PrepareGuards
{
    bool preview = false; // only the summary and its preview: nothing is written
    QStringList protectedFiles; // besides the program: files the output may not replace (the tool table)
    JobFactSource moreFacts; // the history library's facts for the job check run beside it
};

// Prepares the program at `path` for the machine (JobPreparer) a line at a time, into `output` whole or not
// at all (writeFileAtomically): a program that cannot be prepared leaves no file and an old one unchanged.
// The job check runs beside it: a program it finds errors in is not prepared. The output may not be the
// program itself or a protected file, by any name (links are followed).
[[nodiscard]] Result<PrepareSummary> prepareJobFile(const QString &path, const ToolTable &table,
    const PrepareOptions &options, const QString &output, const JobProgress &progress = {},
    const PrepareGuards &guards = {});

} // namespace Toffee
