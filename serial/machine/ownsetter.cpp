// SPDX-License-Identifier: GPL-3.0-or-later
// What a probe of Toffee's own setter cycle says, the same on every controller that runs it (grblHAL,
// LinuxCNC).
#include <QStringList>

#include "model/numberformat.h"
#include "serial/machine/machinecontroller.h"

using namespace Qt::StringLiterals;

namespace Toffee {

void MachineController::describeOwnProbe(SessionResult &result, int tool, std::optional<double> madeReference,
    const QString &note, const QList<double> &touches, const ToolSetter &setter,
    const QString &controller) const
{
    QStringList notes;
    if (madeReference)
        notes << tr("T%1 is this machine's reference tool (its TLO is 0): every tool is measured against its "
                    "contact at machine Z %2 mm.")
                     .arg(tool)
                     .arg(formatNumber(*madeReference, NumberFormat::fixed(3)));
    notes << note;
    if (touches.size() > 1) {
        result.tlo->touches = touches;
        const SetterCycle cycle { setter, probePlan(tool) };
        notes.prepend(spreadFinding(tool, touches, cycle.plan)); // the finding first
        notes << cycle.cannotTurnNote(controller);
    }
    notes.removeAll(QString());
    result.message = notes.join(u' ');
}

} // namespace Toffee
