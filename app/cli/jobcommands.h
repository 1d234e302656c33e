// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include "app/cli/cli.h"
#include "model/job/jobchecker.h"
#include "model/library/library.h"

namespace Toffee::Cli {

// The options job check and job prepare share: the dialect (--dialect, else the machine's in the library),
// --table, --z-floor, --stale-days and --rack; and the history library when there is one.
[[nodiscard]] Result<JobCheckSetup> readJobSetup(
    Invocation &call, std::unique_ptr<Library> &library, QString &machine);
int prepareJob(Invocation &call);

} // namespace Toffee::Cli
