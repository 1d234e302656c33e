// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/offsetpull.h"

#include <cmath>

namespace Toffee {

namespace {
constexpr double kSame = 0.0005; // the controller prints 0.001 mm
} // namespace

QList<PulledEntry> planPull(const ToolTable &table, const QList<ControllerTool> &entries)
{
    const double fromMm = table.units() == Units::Inch ? 1.0 / 25.4 : 1.0;
    QList<PulledEntry> plan;
    plan.reserve(entries.size());
    for (const ControllerTool &entry : entries) {
        const Tool *tool = table.find(entry.tool);
        PulledEntry row { entry.tool, tool ? tool->measuredTlo : std::nullopt, entry.tlo * fromMm,
            PulledEntry::Action::Unchanged };
        if (row.inFile && std::fabs(*row.inFile - row.inController) < kSame)
            row.action = PulledEntry::Action::Unchanged;
        else if (std::fabs(entry.tlo) < kSame)
            row.action = PulledEntry::Action::Empty;
        else
            row.action = tool ? PulledEntry::Action::Take : PulledEntry::Action::NewTool;
        plan.append(row);
    }
    return plan;
}

} // namespace Toffee
