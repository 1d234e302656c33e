// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>

#include <QString>

#include "model/job/jobchecker.h"
#include "model/result.h"

namespace Toffee {

// Told now and then how far the check is (bytes of the file read, of its size); returning false cancels it.
using JobProgress = std::function<bool(qint64 done, qint64 total)>;

// Checks the program at `path` a line at a time (LineReader): its memory does not grow with the program.
// A file that cannot be read, or a line too long for any program, is an error; what the program does wrong is
// in the report. A cancelled check returns what it found so far, marked cancelled.
[[nodiscard]] Result<JobReport> checkJobFile(const QString &path, JobCheckSetup setup,
    const JobFactSource &moreFacts = {}, const JobProgress &progress = {});

} // namespace Toffee
