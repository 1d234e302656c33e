// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QList>
#include <QStringList>

#include "model/tooltable.h"
#include "serial/machine/machinereplies.h"

namespace Toffee {

// What pull-offsets does with one entry of a controller's own table (grblHAL's), against the table file: the
// one rule toffee-cli and the window's preview follow. Lengths are the machine's millimetres.
struct PulledEntry
{
    enum class Action {
        Unchanged, // the file holds the same TLO
        Take, // the file's TLO differs: taken, as set on the controller
        NewTool, // the file has no such tool: added, as set on the controller
        Empty, // 0.000 where the file holds another (or nothing): an entry never set, left alone
    };
    int tool = 0;
    std::optional<double> inFile; // the file's TLO, in millimetres
    double inController = 0.0; // millimetres
    Action action = Action::Unchanged;

    [[nodiscard]] bool changes() const { return action == Action::Take || action == Action::NewTool; }
};

// Each entry of `entries` (millimetres, as the controller reports them) against `table`, in the controller's
// order.
[[nodiscard]] QList<PulledEntry> planPull(const ToolTable &table, const QList<ControllerTool> &entries);

// What push-offsets does with each tool of the table that has a TLO, against what the controller holds: the
// one rule toffee-cli and the window's preview follow. Lengths are the machine's millimetres.
struct PushedEntry
{
    enum class Action {
        Unchanged, // the controller holds the same TLO
        Write, // written (G10 L1) and read back
        Beyond, // a number beyond the controller's table: the whole push is refused
    };
    int tool = 0;
    double inFile = 0.0; // millimetres
    std::optional<double> inController; // millimetres; nothing when the controller has no such entry
    double radius = 0.0; // millimetres
    Action action = Action::Unchanged;
};

struct PushPlan
{
    QList<PushedEntry> entries; // in the table's order
    [[nodiscard]] QList<ControllerTool> writes() const;
    [[nodiscard]] QStringList beyond() const; // "T17", …
};

// `held`: what the controller holds now (millimetres); `tableSize`: its table's last tool number, or 0 for a
// table that lists its tools (LinuxCNC's tool.tbl): a tool not held is beyond it.
[[nodiscard]] PushPlan planPush(const ToolTable &table, const QList<ControllerTool> &held, int tableSize);

} // namespace Toffee
