// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include "model/job/jobcheck.h"
#include "model/job/jobpreparer.h"

namespace Toffee {

// Prepares the program at `path` for the machine (JobPreparer) a line at a time, into `output` whole or not
// at all (writeFileAtomically): a program that cannot be prepared leaves no file and an old one unchanged.
// With no `output`, only the summary and its preview.
[[nodiscard]] Result<PrepareSummary> prepareJobFile(const QString &path, const ToolTable &table,
    const PrepareOptions &options, const QString &output = {}, const JobProgress &progress = {});

} // namespace Toffee
