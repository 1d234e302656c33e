// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/machine/offsetsync.h"

#include <algorithm>
#include <cmath>

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr double kSame = 0.0005; // the controller prints 0.001 mm

std::optional<double> heldFor(const QList<ControllerTool> &held, int tool)
{
    const auto it = std::find_if(
        held.cbegin(), held.cend(), [tool](const ControllerTool &t) { return t.tool == tool; });
    return it == held.cend() ? std::nullopt : std::optional(it->tlo);
}

} // namespace

QList<PulledEntry> planPull(const ToolTable &table, const QList<ControllerTool> &entries)
{
    QList<PulledEntry> plan;
    plan.reserve(entries.size());
    for (const ControllerTool &entry : entries) {
        const auto stored = table.storedTlo(entry.tool);
        PulledEntry row { entry.tool, stored ? std::optional(stored->tlo) : std::nullopt, entry.tlo,
            PulledEntry::Action::Unchanged };
        if (row.inFile && std::fabs(*row.inFile - row.inController) <= stored->sameWithin)
            row.action = PulledEntry::Action::Unchanged;
        else if (std::fabs(entry.tlo) < kSame)
            row.action = PulledEntry::Action::Empty;
        else
            row.action
                = table.contains(entry.tool) ? PulledEntry::Action::Take : PulledEntry::Action::NewTool;
        plan.append(row);
    }
    return plan;
}

PushPlan planPush(const ToolTable &table, const QList<ControllerTool> &held, int tableSize)
{
    PushPlan plan;
    for (const Tool &tool : table.tools()) {
        const auto stored = table.storedTlo(tool.number);
        if (!stored)
            continue;
        PushedEntry row { tool.number, stored->tlo, heldFor(held, tool.number),
            std::max(0.0, toMillimetres(tool.totalRadius(), table.units())), PushedEntry::Action::Write };
        // A table of a size holds T1 to its size; one that lists its tools (LinuxCNC's) holds those alone.
        if (tableSize > 0 ? tool.number < 1 || tool.number > tableSize : !row.inController)
            row.action = PushedEntry::Action::Beyond;
        else if (row.inController && std::fabs(*row.inController - row.inFile) <= stored->sameWithin)
            row.action = PushedEntry::Action::Unchanged;
        plan.entries.append(row);
    }
    return plan;
}

QList<ControllerTool> PushPlan::writes() const
{
    QList<ControllerTool> out;
    for (const PushedEntry &e : entries) {
        if (e.action == PushedEntry::Action::Write)
            out.append({ e.tool, e.inFile, e.radius });
    }
    return out;
}

QStringList PushPlan::beyond() const
{
    QStringList out;
    for (const PushedEntry &e : entries) {
        if (e.action == PushedEntry::Action::Beyond)
            out << u"T%1"_s.arg(e.tool);
    }
    return out;
}

} // namespace Toffee
