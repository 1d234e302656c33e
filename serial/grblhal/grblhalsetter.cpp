// SPDX-License-Identifier: GPL-3.0-or-later
// grblHAL's setter cycle, Toffee's own (grblHAL keeps no reference): the probe and the break test on the tool
// setter the operator set, the contact's machine Z against the machine's reference.
#include "serial/grblhal/grblhalcontroller.h"

#include <algorithm>
#include <cmath>

#include <QStringList>
#include <QTimer>

#include "model/numberformat.h"

using namespace Qt::StringLiterals;

namespace Toffee {

std::optional<int> GrblHalController::spindleTool(const Done &done, const QString &what) const
{
    if (m_tool && *m_tool > 0)
        return m_tool;
    refuse(done,
        tr("grblHAL says no tool is in the spindle (T0), so there is nothing to %1. Say which tool is in "
           "(Select Tool, M61 Q<n>) first.")
            .arg(what));
    return std::nullopt;
}

void GrblHalController::measure(int tool, Done done, std::function<void(QList<double>)> next)
{
    if (!m_setter) {
        refuse(done,
            tr("Toffee does not know where this machine's tool setter is. Set it first (Machine ▸ Tool "
               "Setter…, or toffee-cli --setter X,Y,ZMIN in machine coordinates)."));
        return;
    }
    const auto cycle = SetterCycle::of(*m_setter, probePlan(tool));
    if (!cycle) {
        refuse(
            done, tr("T%1 cannot be probed so: %2 Nothing was sent.").arg(tool).arg(cycle.error().message));
        return;
    }
    readModal(done, [this, done, next, cycle = cycle.value()](const Modal &modal) {
        if (modal.inches) {
            refuse(done,
                tr("grblHAL is in inches (G20), where its G10 and G38.2 take inches. Toffee %1 in "
                   "millimetres: send G21, then try again. Nothing was sent.")
                    .arg(tr("probes")));
            return;
        }
        readParameters(done, [this, done, next, cycle, modal](const GrblHal::ParameterReport &report) {
            // G38.2 takes work coordinates: the machine Z wanted, less the offset in force (the coordinate
            // system's, G92's and the tool's), which is what grblHAL's WCO is.
            double wco = report.toolLengthOffset ? report.toolLengthOffset->z() : 0.0;
            if (const auto it = report.workOffsets.find(modal.coordinateSystem);
                it != report.workOffsets.end())
                wco += it->z();
            if (const auto it = report.workOffsets.find(u"G92"_s); it != report.workOffsets.end())
                wco += it->z();
            const int motion = MachineLink::kMotionTimeoutMs;
            const ToolSetter &setter = cycle.setter;
            run("M5", MachineLink::kDefaultTimeoutMs, done, [=, this](const CommandReply &) {
                run("G53 G0 Z" + number(setter.safeZ), motion, done, [=, this](const CommandReply &) {
                    run("G53 G0 X" + number(cycle.x()) + " Y" + number(cycle.y()), motion, done,
                        [=, this](const CommandReply &) { touchEach(cycle, wco, {}, done, next); });
                });
            });
        });
    });
}

// The contact in a G38.2's reply, or `done` with why there is none to trust.
std::optional<double> GrblHalController::contactIn(
    const CommandReply &reply, const ToolSetter &setter, const Done &done)
{
    std::optional<GrblHal::ProbeReport> found;
    for (const QByteArray &line : reply.lines) {
        if (auto p = GrblHal::parseProbeReport(line))
            found = p;
    }
    if (!found || !found->touched) {
        done(SessionResult::failed(SessionResult::Outcome::MachineError,
            tr("The probe did not report a touch. Nothing was measured.")));
        return std::nullopt;
    }
    // A contact outside the search (from the safe height down to the setter's lowest Z) is no contact the
    // cycle can make: a reply to trust no further.
    const double z = found->position.z();
    if (z < setter.zMin - 1.0 || z > setter.safeZ + 1.0) {
        done(SessionResult::failed(SessionResult::Outcome::MachineError,
            tr("grblHAL reported the contact at machine Z %1 mm, outside the search from %2 to %3 mm. "
               "Nothing "
               "was written or recorded; check the tool setter's settings and the machine.")
                .arg(mm(z), mm(setter.safeZ), mm(setter.zMin))));
        return std::nullopt;
    }
    return z;
}

// One touch (the search down, back off, the slow touch), then the next from clear of the setter, until the
// plan's touches are made; then lifted to the safe height, and `next` gets every contact's machine Z.
void GrblHalController::touchEach(const SetterCycle &cycle, double wco, QList<double> contacts, Done done,
    std::function<void(QList<double>)> next)
{
    const auto work = [wco](double machineZ) {
        return number(machineZ - wco);
    };
    const int motion = MachineLink::kMotionTimeoutMs;
    const ToolSetter &setter = cycle.setter;
    run("G38.2 Z" + work(setter.zMin) + " F" + number(setter.seekFeed), motion, done,
        [=, this](const CommandReply &fast) {
            const auto first = contactIn(fast, setter, done);
            if (!first)
                return;
            const double up = std::min(setter.safeZ, *first + setter.backoff);
            const double down = std::max(setter.zMin, *first - setter.backoff);
            run("G53 G0 Z" + number(up), motion, done, [=, this](const CommandReply &) {
                run("G38.2 Z" + work(down) + " F" + number(cycle.latchFeed()), motion, done,
                    [=, this](const CommandReply &slow) {
                        const auto contact = contactIn(slow, setter, done);
                        if (!contact)
                            return;
                        QList<double> all = contacts;
                        all << atResolution(*contact);
                        const bool more = all.size() < cycle.plan.touches;
                        const double lift = more ? cycle.liftBetween(*contact) : setter.safeZ;
                        run("G53 G0 Z" + number(lift), motion, done, [=, this](const CommandReply &) {
                            if (more)
                                return touchEach(cycle, wco, all, done, next);
                            // "ok" to a move means queued; G4 P0's comes once the machine has stopped,
                            // lifted.
                            run("G4 P0", motion, done, [next, all](const CommandReply &) { next(all); });
                        });
                    });
            });
        });
}

// A jog ($J=, relative, in millimetres whatever G20/G21 is in force): grblHAL answers "ok" as it starts, so
// its state is read until it stops. A jog beyond the soft limits is refused by grblHAL (error:15), unmoved.
void GrblHalController::jog(const std::array<double, 3> &stepMm, double feed, Done done)
{
    const bool fits = std::all_of(stepMm.cbegin(), stepMm.cend(),
        [](double step) { return std::isfinite(step) && std::fabs(step) <= kMaxJogStepMm; });
    if (!fits || !std::isfinite(feed) || feed < 1.0 || feed > ToolSetter::kMaxFeed) {
        refuse(done,
            tr("A jog moves at most %1 mm along each axis, at 1 to %2 mm/min. Nothing was sent.")
                .arg(mm(kMaxJogStepMm), mm(ToolSetter::kMaxFeed)));
        return;
    }
    QByteArray command = "$J=G91 G21";
    const char axes[] = { 'X', 'Y', 'Z' };
    for (std::size_t i = 0; i < stepMm.size(); ++i) {
        if (stepMm[i] != 0.0)
            command += ' ' + QByteArray(1, axes[i]) + number(stepMm[i]);
    }
    if (command.size() == 10) {
        refuse(done, tr("A jog of 0 mm moves nothing. Nothing was sent."));
        return;
    }
    command += " F" + number(feed);
    m_jogging = true;
    m_jogCancelled = false;
    const Done ended = [this, done](const SessionResult &r) {
        m_jogging = false;
        SessionResult result = r;
        if (m_jogCancelled && result.ok())
            result.message = tr("The jog was stopped where the machine stands; it is ready (no alarm).");
        m_jogCancelled = false;
        done(result);
    };
    run(command, MachineLink::kDefaultTimeoutMs, ended, [this, done = ended](const CommandReply &) {
        auto poll = std::make_shared<std::function<void()>>();
        // Each poll holds the function; it holds itself only weakly, so it goes with the last poll.
        *poll = [this, done, self = std::weak_ptr(poll)] {
            awaitStatus(2000, [this, done, again = self.lock()](std::optional<MachineStatus> s) {
                if (!s) {
                    done(SessionResult::failed(SessionResult::Outcome::LinkFailure,
                        tr("grblHAL stopped reporting its state while it jogged.")));
                } else if (s->state == u"Jog" || s->state == u"Run") {
                    QTimer::singleShot(MachineLink::kPollIntervalMs, this, [again] { (*again)(); });
                } else if (s->isAlarm()) {
                    done(SessionResult::failed(SessionResult::Outcome::MachineError,
                        tr("grblHAL went into alarm while it jogged: check the machine, then Unlock.")));
                } else {
                    SessionResult result;
                    result.status = *s;
                    done(result);
                }
            });
        };
        (*poll)();
    });
}

void GrblHalController::probe(Done done)
{
    done = recording(std::move(done), RecordingKind::Probe);
    const auto tool = spindleTool(done, tr("measure"));
    if (!tool)
        return;
    measure(*tool, done, [this, done, tool = *tool](const QList<double> &touches) {
        const double contact = highestTouch(touches);
        const bool first = !m_reference;
        const double reference = m_reference.value_or(contact);
        const double tlo = atResolution(contact - reference);
        writeOffset(tool, tlo, done,
            [this, done, tool, tlo, contact, first, reference, touches](const QString &note) {
                m_reference = reference;
                SessionResult result = tloResult(tool, tlo, contact);
                describeOwnProbe(result, tool, first ? std::optional(reference) : std::nullopt, note, touches,
                    *m_setter, u"grblHAL"_s);
                done(result);
            });
    });
}

void GrblHalController::breakTest(double tolerance, Done done, std::optional<double> storedTlo)
{
    done = recordingVerdict(std::move(done));
    if (auto valid = validateTolerance(tolerance); !valid) {
        refuse(done, valid.error().message);
        return;
    }
    const auto tool = spindleTool(done, tr("break-test"));
    if (!tool)
        return;
    const auto stored = breakBaseline(done, *tool, m_reference.has_value(), storedTlo, m_table, u"grblHAL"_s);
    if (!stored)
        return;
    measure(*tool, done, [this, done, tolerance, stored, tool = *tool](const QList<double> &touches) {
        done(breakVerdict(tool, atResolution(*stored), atResolution(highestTouch(touches) - *m_reference),
            tolerance, u"grblHAL"_s, touches));
    });
}

} // namespace Toffee
