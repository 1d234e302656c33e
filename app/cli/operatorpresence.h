// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

class QObject;
class QTextStream;

namespace Toffee {
class MachineController;
}

namespace Toffee::Cli {

// Why nobody counts as at the machine: toffee-cli's input is not a terminal (a script, cron, ssh -n, a
// pipe), so no person can answer. Empty when it is one.
[[nodiscard]] QString whyNobodyIsThere();

// For as long as `context` lives: each wait of `controller` for the person (a manual tool change) is said on
// `err` with its limit; on a terminal, Enter is the person's "the tool is in" where the controller takes it
// from here; end of input (a closed terminal) and Ctrl-C end the change on the machine.
void attendToolChanges(MachineController *controller, QTextStream &err, QObject *context);

} // namespace Toffee::Cli
