// SPDX-License-Identifier: GPL-3.0-or-later
// What a connection offers the window and toffee-cli: each machine operation, started through perform() (one
// at a time, none while halted unless it clears the halt), run by the controller that took the link.
#include "serial/machineconnection.h"

#include "serial/machine/machinecontroller.h"
#include "serial/machine/machinelink.h"

using namespace Qt::StringLiterals;

namespace Toffee {

bool MachineConnection::status(Done done)
{
    return perform(
        tr("Reading the status…"), true, [](MachineController *s, Done d) { s->status(std::move(d)); },
        std::move(done));
}

bool MachineConnection::readToolTable(Done done)
{
    return perform(
        tr("Reading the controller's tool table…"), false,
        [](MachineController *s, Done d) { s->readToolTable(std::move(d)); }, std::move(done));
}

bool MachineConnection::writeToolTable(const QList<ControllerTool> &tools, Done done)
{
    return perform(
        tr("Writing the controller's tool table…"), false,
        [tools](MachineController *s, Done d) { s->writeToolTable(tools, std::move(d)); }, std::move(done));
}

bool MachineConnection::report(Done done)
{
    return perform(
        tr("Reading the offsets…"), false, [](MachineController *s, Done d) { s->report(std::move(d)); },
        std::move(done));
}

bool MachineConnection::selectTool(int tool, Done done)
{
    return perform(
        tr("Selecting T%1…").arg(tool), false,
        [tool](MachineController *s, Done d) { s->selectTool(tool, std::move(d)); }, std::move(done));
}

bool MachineConnection::changeTool(int tool, Done done, std::optional<double> storedTlo)
{
    return perform(
        tool == Limits::kEmptySpindle ? tr("Emptying the spindle…") : tr("Changing to T%1…").arg(tool), false,
        [tool, storedTlo](MachineController *s, Done d) { s->changeTool(tool, std::move(d), storedTlo); },
        std::move(done));
}

bool MachineConnection::jog(const std::array<double, 3> &stepMm, double feed, Done done)
{
    return perform(
        tr("Jogging…"), false,
        [stepMm, feed](MachineController *s, Done d) { s->jog(stepMm, feed, std::move(d)); },
        std::move(done));
}

void MachineConnection::resumeToolChange()
{
    if (m_session)
        m_session->resumeToolChange();
}

void MachineConnection::endToolChange(const QString &why)
{
    if (m_session)
        m_session->endToolChange(why);
}

bool MachineConnection::probe(Done done)
{
    return perform(
        tr("Probing %1…").arg(activeToolName()), false,
        [](MachineController *s, Done d) { s->probe(std::move(d)); }, std::move(done));
}

bool MachineConnection::breakTest(double tolerance, Done done, std::optional<double> storedTlo)
{
    return perform(
        tr("Break-testing %1…").arg(activeToolName()), false,
        [tolerance, storedTlo](
            MachineController *s, Done d) { s->breakTest(tolerance, std::move(d), storedTlo); },
        std::move(done));
}

bool MachineConnection::setTlo(double tlo, Done done)
{
    return perform(
        tr("Setting %1's TLO…").arg(activeToolName()), false,
        [tlo](MachineController *s, Done d) { s->setTlo(tlo, std::move(d)); }, std::move(done));
}

bool MachineConnection::setTloAboveZ0(double height, Done done)
{
    return perform(
        tr("Setting %1's TLO…").arg(activeToolName()), false,
        [height](MachineController *s, Done d) { s->setTloAboveZ0(height, std::move(d)); }, std::move(done));
}

bool MachineConnection::restoreTlo(int tool, double tlo, Done done)
{
    return perform(
        tr("Restoring T%1…").arg(tool), false,
        [tool, tlo](MachineController *s, Done d) { s->restoreTlo(tool, tlo, std::move(d)); },
        std::move(done));
}

bool MachineConnection::unlock(Done done, std::optional<double> brokenToolTlo)
{
    return perform(
        tr("Unlock"), true,
        [brokenToolTlo](MachineController *s, Done d) { s->unlock(std::move(d), brokenToolTlo); },
        std::move(done));
}

bool MachineConnection::sendLine(
    const QByteArray &line, std::function<void(const CommandReply &, const SessionResult &)> done)
{
    if (!beginOperation(QString::fromUtf8(line)))
        return false;
    // A script (M491, M6) ends with "Done ATC", a shell command perhaps with nothing: each as the firmware
    // answers it, so that no later "ok" is taken for this line's.
    m_link->send(
        m_session ? m_session->consoleCommand(line) : line, MachineLink::kMotionTimeoutMs,
        [this, done](const CommandReply &reply) {
            // Offsets the reply reports (an M493.3 or M493.4 typed by hand): the TLO in force is the status
            // report's, read next.
            const std::optional<OffsetReport> report
                = m_session ? m_session->offsetsIn(reply.lines) : std::nullopt;
            auto finish = [this, done, reply](SessionResult result) {
                result.tool = activeTool();
                endOperation(result);
                if (done)
                    done(reply, result);
            };
            if (!reply.ok() || !m_session)
                return finish(SessionResult {});
            // A typed M6 or M493.2 changed the tool: the operation ends when a fresh status says which tool
            // is in the spindle, so that a probe started right after cannot be recorded for the tool before.
            m_session->status([finish, report](const SessionResult &status) {
                SessionResult result;
                if (report && status.status && status.status->tlo)
                    result.tlo = TloReading::from(*status.status->tlo, report);
                finish(result);
            });
        },
        m_session ? m_session->consoleReplyEnd(line) : ReplyEnd::Ok);
    return true;
}

} // namespace Toffee
