// SPDX-License-Identifier: GPL-3.0-or-later
// LinuxCNC's setter cycle, Toffee's own through MDI (LinuxCNC keeps no reference tool): the probe and the
// break test on the tool setter the operator set, the contact's machine Z against the machine's reference.
#include "serial/linuxcnc/linuxcnccontroller.h"

#include <algorithm>
#include <cmath>

#include <QStringList>

#include "model/numberformat.h"

using namespace Qt::StringLiterals;

namespace Toffee {

std::optional<int> LinuxCncController::spindleTool(const Done &done, const QString &what) const
{
    if (m_tool && *m_tool > 0)
        return m_tool;
    refuse(done,
        tr("LinuxCNC says no tool is in the spindle (T0), so there is nothing to %1. Say which tool is in "
           "(Select Tool, M61 Q<n>) first.")
            .arg(what));
    return std::nullopt;
}

SessionResult LinuxCncController::tloResult(int tool, double tlo, std::optional<double> contactMz) const
{
    SessionResult result;
    result.tool = tool;
    result.tlo = TloReading { atResolution(tlo), m_reference, contactMz };
    return result;
}

// One G38.2 down from machine Z `from` by `depth` (incremental: no work offset, G92 or TLO in force changes
// where it goes), then where it stopped and the contact's machine Z printed back: #5063 is in the coordinates
// the probe ran in, and #<_abs_z> − #<_z> is every offset in force. LinuxCNC 2.9 answers a G38.2 that meets
// nothing, or that starts with its input already triggered, with SET MDI ACK (the error waits in its queue)
// and may leave #5063 and #5070 from an earlier probe: so the outcome is judged from where the machine
// stopped. It did not move: already touching. It went the whole way, or #5070 is 0: nothing met. Otherwise
// the contact must lie within the move.
void LinuxCncController::touch(double from, double depth, double feed, const ToolSetter &setter, Done done,
    std::function<void(double)> next)
{
    const int motion = MachineLink::kMotionTimeoutMs;
    const double to = from - depth;
    // Whatever happened, G90 back in force and the spindle lifted; but nothing moves after a Stop. LinuxCNC's
    // own refusals of a probe said in words.
    const Done lifted = [this, done, setter](const SessionResult &result) {
        SessionResult failed = result;
        if (result.message.contains(u"already tripped"_s)
            || result.message.contains(u"during non-probe move"_s))
            failed.message = tr("The probe was already touching, or touched something, before it probed (the "
                                "setter's input triggered on the way to it or where it started): check the "
                                "setter, its cable and the safe height. Nothing was measured. (%1)")
                                 .arg(result.message);
        if (m_abortedHere || !m_link->isOpen())
            return done(failed);
        m_link->send("set mdi G90", MachineLink::kDefaultTimeoutMs,
            [this, done, failed, setter](const CommandReply &) {
                m_link->send("set mdi G53 G0 Z" + number(setter.safeZ), MachineLink::kMotionTimeoutMs,
                    [done, failed](const CommandReply &) { done(failed); });
            });
    };
    const QByteArray line = "G91 G38.2 Z-" + number(depth) + " F" + number(feed);
    mdi(line, motion, lifted, [this, lifted, from, to, next](const CommandReply &) {
        mdi("G90", MachineLink::kDefaultTimeoutMs, lifted,
            [this, lifted, from, to, next](const CommandReply &) {
                printFields("TOFFEE-PRB", "p=#5063 a=#<_abs_z> z=#<_z> ok=#5070", lifted,
                    [lifted, from, to, next](const Fields &f) {
                        const double stopped = f.at("a");
                        const double z = atResolution(f.at("p") + f.at("a") - f.at("z"));
                        const double slack = 0.01;
                        if (std::fabs(stopped - from) < 0.001)
                            return lifted(SessionResult::failed(SessionResult::Outcome::MachineError,
                                tr("The probe was already touching at machine Z %1 mm, before it moved: the "
                                   "setter's "
                                   "input is triggered there. Check the setter, its cable and the safe "
                                   "height. "
                                   "Nothing was measured.")
                                    .arg(mm(from))));
                        if (f.at("ok") < 0.5 || std::fabs(stopped - to) < 0.001)
                            return lifted(SessionResult::failed(SessionResult::Outcome::MachineError,
                                tr("The probe met nothing down to machine Z %1 mm: is a tool in the spindle, "
                                   "and is "
                                   "the setter where its settings say? Nothing was measured.")
                                    .arg(mm(to))));
                        if (z < to - slack || z > from + slack)
                            return lifted(SessionResult::failed(SessionResult::Outcome::MachineError,
                                tr("LinuxCNC reported the contact at machine Z %1 mm, outside the move from "
                                   "%2 to "
                                   "%3 mm. Nothing was written or recorded; check the tool setter's settings "
                                   "and "
                                   "the machine.")
                                    .arg(mm(z), mm(from), mm(to))));
                        next(z);
                    });
            });
    });
}

void LinuxCncController::measure(int tool, Done done, std::function<void(QList<double>)> next)
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
    const QList<QByteArray> approach { "M5", "G90 G53 G0 Z" + number(cycle.value().setter.safeZ),
        "G53 G0 X" + number(cycle.value().x()) + " Y" + number(cycle.value().y()) };
    mdiChain(approach, MachineLink::kMotionTimeoutMs, done,
        [this, done, next, cycle = cycle.value()] { touchEach(cycle, cycle.setter.safeZ, {}, done, next); });
}

// One touch from machine Z `from` (the search down, back off, the slow touch), then the next from clear of
// the setter, until the plan's touches are made; then lifted, and `next` gets every contact's machine Z.
void LinuxCncController::touchEach(const SetterCycle &cycle, double from, QList<double> contacts, Done done,
    std::function<void(QList<double>)> next)
{
    constexpr int motion = MachineLink::kMotionTimeoutMs;
    const ToolSetter &setter = cycle.setter;
    touch(from, from - setter.zMin, setter.seekFeed, setter, done, [=, this](double first) {
        const double up = std::min(setter.safeZ, first + setter.backoff);
        const double down = std::max(setter.zMin, first - setter.backoff);
        mdi("G53 G0 Z" + number(up), motion, done, [=, this](const CommandReply &) {
            touch(up, up - down, cycle.latchFeed(), setter, done, [=, this](double contact) {
                QList<double> all = contacts;
                all << contact;
                const bool more = all.size() < cycle.plan.touches;
                const double lift = more ? cycle.liftBetween(contact) : setter.safeZ;
                mdi("G53 G0 Z" + number(lift), motion, done, [=, this](const CommandReply &) {
                    if (more)
                        return touchEach(cycle, lift, all, done, next);
                    next(all);
                });
            });
        });
    });
}

void LinuxCncController::probe(Done done)
{
    done = recording(std::move(done), RecordingKind::Probe);
    // Ready first (estop, off, …: what to do comes before which tool), then the tool in the spindle.
    ready(done, tr("probe"), [this, done](const LinuxCnc::State &) { probeReady(done); });
}

void LinuxCncController::probeReady(Done done)
{
    const auto tool = spindleTool(done, tr("measure"));
    if (!tool)
        return;
    measure(*tool, done, [this, done, tool = *tool](const QList<double> &touches) {
        const double contact = highestTouch(touches);
        const bool first = !m_reference;
        const double reference = m_reference.value_or(contact);
        const double tlo = atResolution(contact - reference);
        writeOffset(tool, tlo, done, [this, done, tool, tlo, contact, first, reference, touches] {
            m_reference = reference;
            SessionResult result = tloResult(tool, tlo, contact);
            describeOwnProbe(result, tool, first ? std::optional(reference) : std::nullopt, {}, touches,
                *m_setter, u"LinuxCNC"_s);
            done(result);
        });
    });
}

void LinuxCncController::breakTest(double tolerance, Done done, std::optional<double> storedTlo)
{
    done = recordingVerdict(std::move(done));
    if (auto valid = validateTolerance(tolerance); !valid) {
        refuse(done, valid.error().message);
        return;
    }
    ready(done, tr("break-test"), [this, done, tolerance, storedTlo](const LinuxCnc::State &) {
        breakTestReady(tolerance, done, storedTlo);
    });
}

void LinuxCncController::breakTestReady(double tolerance, Done done, std::optional<double> storedTlo)
{
    const auto tool = spindleTool(done, tr("break-test"));
    if (!tool)
        return;
    const auto stored = breakBaseline(done, *tool, m_reference.has_value(), storedTlo,
        m_table.value_or(QList<ControllerTool> {}), u"LinuxCNC"_s);
    if (!stored)
        return;
    measure(*tool, done, [this, done, tolerance, stored, tool = *tool](const QList<double> &touches) {
        done(breakVerdict(tool, atResolution(*stored), atResolution(highestTouch(touches) - *m_reference),
            tolerance, u"LinuxCNC"_s, touches));
    });
}

} // namespace Toffee
