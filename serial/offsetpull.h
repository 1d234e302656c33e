// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QList>

#include "model/tooltable.h"
#include "serial/machine/machinereplies.h"

namespace Toffee {

// What pull-offsets does with one entry of a controller's own table (grblHAL's), against the table file: the
// one rule toffee-cli and the window's preview follow.
struct PulledEntry
{
    enum class Action {
        Unchanged, // the file holds the same TLO
        Take, // the file's TLO differs: taken, as set on the controller
        NewTool, // the file has no such tool: added, as set on the controller
        Empty, // 0.000 where the file holds another (or nothing): an entry never set, left alone
    };
    int tool = 0;
    std::optional<double> inFile; // the file's TLO, in its units
    double inController = 0.0; // in the file's units
    Action action = Action::Unchanged;

    [[nodiscard]] bool changes() const { return action == Action::Take || action == Action::NewTool; }
};

// Each entry of `entries` (millimetres, as the controller reports them) against `table`, in the controller's
// order.
[[nodiscard]] QList<PulledEntry> planPull(const ToolTable &table, const QList<ControllerTool> &entries);

} // namespace Toffee
