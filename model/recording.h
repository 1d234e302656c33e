// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QDateTime>

#include "model/tool.h"

namespace Toffee {

// What an operation on the machine means for the tool table, carried by its result so that the window and the
// CLI record it with one call (ToolTable::record, ToolDocument::record): a tool's new TLO (probed or set by
// hand) with the reference it is measured against, or a break test's verdict.
struct Recording
{
    int tool = -1;
    std::optional<double> tlo; // a TLO to store, with where it came from and its reference
    TloSource source = TloSource::Probe;
    std::optional<double> referenceMz;
    std::optional<bool> breakTestFailed; // a break test's verdict (no TLO)
    QDateTime at; // UTC
};

} // namespace Toffee
