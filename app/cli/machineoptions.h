// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include "app/cli/cli.h"
#include "model/result.h"
#include "model/tooltable.h"
#include "serial/machineconnection.h"

namespace Toffee::Cli {

// A machine command's options, each checked before the port is even opened: what can be refused is refused
// without touching the machine.
struct MachineOptions
{
    ConnectionTarget target;
    int tool = 0; // select-tool and change-tool
    double tolerance = 0.0; // break-test
    std::optional<double> z; // set-tlo --z
    std::optional<double> aboveZ0; // set-tlo --above-z0
    int count = 1000; // link-test
    std::optional<ToolTable> table; // --table, loaded, and writable
    QString tablePath;
};

[[nodiscard]] Result<MachineOptions> readMachineOptions(const Invocation &call);

} // namespace Toffee::Cli
