// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/operatorpresence.h"

#include <memory>

#include <unistd.h>

#include <QSocketNotifier>
#include <QTextStream>

#include "app/cli/interrupt.h"
#include "serial/machine/machinecontroller.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

QString whyNobodyIsThere()
{
    if (::isatty(STDIN_FILENO))
        return {};
    return u"toffee-cli's input is not a terminal (a script, cron, ssh -n or a pipe), so nobody can answer"_s;
}

void attendToolChanges(MachineController *controller, QTextStream &err, QObject *context)
{
    controller->setOperatorAbsent(whyNobodyIsThere());
    QObject::connect(controller, &MachineController::waitingForOperator, context,
        [controller, &err, context](int tool, int limitMs) {
            const bool here = controller->resumesFromHere();
            err << "toffee-cli: put T" << tool << " in the spindle, then press "
                << (here ? "the machine's cycle start, or Enter here" : "the machine's button")
                << ". Waiting up to " << limitMs / 1000 << " s; Ctrl-C or end of input ends the change."
                << Qt::endl;
            // The hook lives as long as the wait: Ctrl-C then ends the change on the machine first.
            auto hook = std::make_shared<InterruptHook>(
                [controller] { controller->endToolChange(u"Ctrl-C ended the wait."_s); });
            auto *input = new QSocketNotifier(STDIN_FILENO, QSocketNotifier::Read, context);
            QObject::connect(input, &QSocketNotifier::activated, context, [controller, input, here, &err] {
                char buffer[256];
                const ssize_t got = ::read(STDIN_FILENO, buffer, sizeof buffer);
                if (got <= 0) { // end of input: the terminal closed; it is no "go on"
                    input->setEnabled(false);
                    controller->endToolChange(
                        u"The terminal closed (end of input) while the change waited."_s);
                } else if (here) {
                    input->setEnabled(false);
                    controller->resumeToolChange();
                } else {
                    err << "toffee-cli: the machine goes on when its button is pressed." << Qt::endl;
                }
            });
            // Both go when the change ends, however it ends.
            auto ended = std::make_shared<QMetaObject::Connection>();
            *ended = QObject::connect(
                controller, &MachineController::toolChangeFinished, context, [input, hook, ended]() mutable {
                    QObject::disconnect(*ended);
                    input->deleteLater();
                    hook.reset();
                });
        });
}

} // namespace Toffee::Cli
