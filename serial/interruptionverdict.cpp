// SPDX-License-Identifier: GPL-3.0-or-later
// What an operation the link was lost in did, told from what the machine holds after reconnecting.
#include "serial/machineconnection.h"

#include <cmath>

using namespace Qt::StringLiterals;

namespace Toffee {

QString MachineConnection::interruptionVerdict(const Interruption &before, const SessionResult &now)
{
    const auto tool = now.status ? now.status->tool : now.tool;
    const std::optional<double> tlo = now.tlo ? std::optional(now.tlo->tlo())
        : now.status                          ? now.status->tlo
                                              : std::nullopt;
    const std::optional<double> currentMz = now.tlo ? now.tlo->knownCurrentMz() : std::nullopt;
    auto toolName = [](std::optional<int> t) {
        return !t ? tr("an unknown tool") : *t < 0 ? tr("no tool") : u"T"_s + QString::number(*t);
    };
    auto mm = [](std::optional<double> v) {
        return v ? QString::number(*v, 'f', 3) : tr("unknown");
    };
    auto differs = [](std::optional<double> a, std::optional<double> b) {
        return a && b && std::abs(*a - *b) >= 0.0005;
    };
    const QString held
        = tr("Before \"%1\" the machine had %2 in the spindle with TLO %3; now it has %4 with "
             "TLO %5.")
              .arg(before.operation, toolName(before.tool), mm(before.tloInForce), toolName(tool), mm(tlo));
    if (!tlo || !before.tloInForce)
        return held + u' '
            + tr("Toffee cannot tell whether it ran. Nothing of it was recorded; check the machine and run "
                 "it again.");
    // A machine switched off and on again holds no TLO: the operation's traces are gone with it.
    if (std::abs(*tlo) < 0.0005 && std::abs(*before.tloInForce) >= 0.0005 && !currentMz)
        return held + u' '
            + tr("The machine holds no TLO now, as after a restart: Toffee cannot tell whether it ran. "
                 "Nothing of it was recorded; check the tool in the spindle and measure it again.");
    if (tool != before.tool || differs(tlo, before.tloInForce) || differs(currentMz, before.currentMz))
        return held + u' '
            + tr("It ran on the machine, at least in part, but the machine's confirmation was lost: "
                 "nothing of it was recorded. Run it again to record it.");
    return held + u' '
        + tr("Nothing changed on the machine: it did not run, or it measured exactly the length held "
             "before. Nothing of it was recorded; run it again.");
}

} // namespace Toffee
