// SPDX-License-Identifier: GPL-3.0-or-later
// The Carvera's tool change: M6 T through the rack (measured after it, or given a stored TLO), and what a
// person must do when the rack cannot (a tool outside it), with the wait that follows.
#include <QDateTime>
#include <QTimer>

#include "model/clock.h"
#include "model/gcode/carvera.h"
#include "model/numberformat.h"
#include "serial/carvera/machinesession.h"

using namespace Qt::StringLiterals;

namespace Toffee {

void MachineSession::startToolChange(int tool, Done done, std::optional<double> storedTlo)
{
    if (auto r = validateToolNumber(tool); !r)
        return refuse(done, r.error().message);
    if (storedTlo) {
        if (auto r = validateOffset(tr("The tool length offset"), *storedTlo); !r)
            return refuse(done, r.error().message);
        return changeToStoredTlo(tool, *storedTlo, std::move(done));
    }
    if (m_tool == tool && tool >= 0)
        return probe(std::move(done)); // the firmware ignores M6 to the tool it holds
    done = recording(std::move(done), RecordingKind::Probe); // M6 probes the new tool
    run(
        "M6 T" + QByteArray::number(tool), kToolChangeTimeoutMs, done,
        [this, done, tool](const CommandReply &reply) {
            if (tool == Limits::kEmptySpindle)
                return confirmEmptySpindle(done); // nothing to measure
            const auto probe = lastProbe(reply.lines);
            if (!probe || !probe->triggered) {
                SessionResult bad;
                bad.outcome = SessionResult::Outcome::MachineError;
                bad.message
                    = tr("The machine finished changing to T%1, but its probe result ([PRB:…]) could not be "
                         "read. Nothing was recorded; probe the tool again.")
                          .arg(tool)
                    + floodNote(reply);
                done(bad);
                return;
            }
            SessionResult changed;
            changed.tool = tool;
            readOffsets(done, changed);
        },
        ReplyEnd::Script);
}

// M6 T H: a manual change that takes the table's TLO (the firmware measures a rack tool all the same); the
// machine must then report it in force.
void MachineSession::changeToStoredTlo(int tool, double tlo, Done done)
{
    run(
        "M6 T" + QByteArray::number(tool) + " H" + number(tlo), kToolChangeTimeoutMs, done,
        [this, done, tool, tlo](const CommandReply &reply) {
            SessionResult changed;
            changed.tool = tool;
            const auto probe = lastProbe(reply.lines);
            if (probe && probe->triggered) {
                // A rack tool: the firmware measured it, and the measurement is what is in force.
                readOffsets(recording(done, RecordingKind::Probe), changed);
                return;
            }
            readOffsets(expectingTlo(tlo,
                            [done, tool](const SessionResult &r) {
                                SessionResult restored = r;
                                restored.tool = tool;
                                if (r.ok() && r.tlo)
                                    restored.recording = Recording { tool, r.tlo->tlo(), TloSource::Probe,
                                        r.tlo->knownReferenceMz(), std::nullopt, Clock::now(),
                                        RecordingKind::Restore };
                                done(restored);
                            }),
                changed);
        },
        ReplyEnd::Script);
}

QString MachineSession::changeByHand(int tool) const
{
    if (m_tool == tool && tool >= 0)
        return {}; // measured where it is (M491)
    const bool pick = tool != Limits::kEmptySpindle && !carveraChangesByItself(tool);
    QString drop;
    if (!m_tool) // the stock firmware does not say: its drop may be by hand
        drop = tr("the tool in the spindle, which this firmware does not name, may be taken out by hand");
    else if (*m_tool != Limits::kEmptySpindle && !carveraChangesByItself(*m_tool))
        drop = tr("T%1 is taken out by hand").arg(*m_tool);
    if (pick && !drop.isEmpty())
        return tr("%1 and T%2 put in by hand").arg(drop).arg(tool);
    if (pick)
        return tr("T%1 is put in by hand").arg(tool);
    return drop;
}

void MachineSession::cancelWaitingChange()
{
    abort(); // Ctrl-X: the firmware halts, which ends the wait for the button
}

QString MachineSession::cancelledChangeNote() const
{
    return tr(
        "The machine halted to end it: check what is in the spindle, unlock it, then select the tool and "
        "probe it before cutting.");
}

} // namespace Toffee
