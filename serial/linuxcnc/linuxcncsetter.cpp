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

// One G38.2 (incremental: no work offset, G92 or TLO in force changes where it goes), then the contact's
// machine Z printed back: #5063 is in the coordinates the probe ran in, and #<_abs_z> − #<_z> is every offset
// in force.
void LinuxCncController::touch(
    const QByteArray &probeLine, const ToolSetter &setter, Done done, std::function<void(double)> next)
{
    const int motion = MachineLink::kMotionTimeoutMs;
    // A probe that meets nothing (or starts touching) leaves G91 in force: G90 and a lift, whatever happened.
    const Done lifted = [this, done, setter](const SessionResult &failed) {
        SessionResult said = failed;
        if (said.message.contains(u"without making contact"_s))
            said.message
                = tr("The probe met nothing down to machine Z %1 mm: is a tool in the spindle, and is "
                     "the setter where its settings say? Nothing was measured. (%2)")
                      .arg(mm(setter.zMin), failed.message);
        else if (said.message.contains(u"already tripped"_s))
            said.message = tr("The probe was already touching when the move began: the setter's input is "
                              "triggered. Check the setter and its cable. Nothing was measured. (%1)")
                               .arg(failed.message);
        m_link->send(
            "set mdi G90", MachineLink::kDefaultTimeoutMs, [this, done, said, setter](const CommandReply &) {
                m_link->send("set mdi G53 G0 Z" + number(setter.safeZ), MachineLink::kMotionTimeoutMs,
                    [done, said](const CommandReply &) { done(said); });
            });
    };
    mdi(probeLine, motion, lifted, [this, done, setter, next](const CommandReply &) {
        mdi("G90", MachineLink::kDefaultTimeoutMs, done, [this, done, setter, next](const CommandReply &) {
            printFields("TOFFEE-PRB", "p=#5063 a=#<_abs_z> z=#<_z> ok=#5070", done,
                [done, setter, next](const Fields &f) {
                    // ok (#5070) is 0 when the probe was aborted: its ACK then proves nothing.
                    if (f.at("ok") < 0.5)
                        return done(SessionResult::failed(SessionResult::Outcome::MachineError,
                            tr("LinuxCNC's probe ended without a contact (#5070 = 0). Nothing was "
                               "measured.")));
                    const double z = atResolution(f.at("p") + f.at("a") - f.at("z"));
                    if (z < setter.zMin - 1.0 || z > setter.safeZ + 1.0)
                        return done(SessionResult::failed(SessionResult::Outcome::MachineError,
                            tr("LinuxCNC reported the contact at machine Z %1 mm, outside the search from %2 "
                               "to "
                               "%3 mm. Nothing was written or recorded; check the tool setter's settings and "
                               "the machine.")
                                .arg(mm(z), mm(setter.safeZ), mm(setter.zMin))));
                    next(z);
                });
        });
    });
}

void LinuxCncController::measure(Done done, std::function<void(double)> next)
{
    if (!m_setter) {
        refuse(done,
            tr("Toffee does not know where this machine's tool setter is. Set it first (Machine ▸ Tool "
               "Setter…, or toffee-cli --setter X,Y,ZMIN in machine coordinates)."));
        return;
    }
    const ToolSetter setter = *m_setter;
    {
        const int motion = MachineLink::kMotionTimeoutMs;
        const QList<QByteArray> approach { "M5", "G90 G53 G0 Z" + number(setter.safeZ),
            "G53 G0 X" + number(setter.x) + " Y" + number(setter.y) };
        mdiChain(approach, motion, done, [this, done, next, setter, motion] {
            const double depth = setter.safeZ - setter.zMin;
            touch("G91 G38.2 Z-" + number(depth) + " F" + number(setter.seekFeed), setter, done,
                [this, done, next, setter, motion](double first) {
                    const double up = std::min(setter.safeZ, first + setter.backoff);
                    const double down = std::max(setter.zMin, first - setter.backoff);
                    mdi("G53 G0 Z" + number(up), motion, done, [=, this](const CommandReply &) {
                        touch("G91 G38.2 Z-" + number(up - down) + " F" + number(setter.latchFeed), setter,
                            done, [=, this](double contact) {
                                mdi("G53 G0 Z" + number(setter.safeZ), motion, done,
                                    [next, contact](const CommandReply &) { next(contact); });
                            });
                    });
                });
        });
    }
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
    measure(done, [this, done, tool = *tool](double contact) {
        const bool first = !m_reference;
        const double reference = m_reference.value_or(contact);
        const double tlo = atResolution(contact - reference);
        writeOffset(tool, tlo, done, [this, done, tool, tlo, contact, first, reference] {
            m_reference = reference;
            SessionResult result = tloResult(tool, tlo, contact);
            if (first)
                result.message = tr("T%1 is this machine's reference tool (its TLO is 0): every tool is "
                                    "measured against its contact at machine Z %2 mm.")
                                     .arg(tool)
                                     .arg(mm(reference));
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
    if (!m_reference) {
        refuse(done,
            tr("This machine has no reference tool yet, so a new length cannot be compared. Probe a tool "
               "first: the first one measured becomes the reference."));
        return;
    }
    // The stored TLO: the table's; else LinuxCNC's own entry for the tool (its file), unless it is empty.
    std::optional<double> stored = storedTlo;
    for (const ControllerTool &entry : m_table.value_or(QList<ControllerTool> {})) {
        if (!stored && entry.tool == *tool && std::fabs(entry.tlo) >= kReadBackTolerance)
            stored = entry.tlo;
    }
    if (!stored) {
        refuse(done,
            tr("T%1 has no stored TLO to compare with, in the table or in LinuxCNC's own: probe it first.")
                .arg(*tool));
        return;
    }
    measure(done, [this, done, tolerance, stored, tool = *tool](double contact) {
        SessionResult result;
        result.tool = tool;
        result.tolerance = tolerance;
        const double measured = atResolution(contact - *m_reference);
        result.breakTest = BreakTestReading { atResolution(*stored), measured };
        const double difference = std::fabs(measured - *stored);
        if (difference > tolerance) {
            result.outcome = SessionResult::Outcome::ToolBroken;
            result.message
                = tr("T%1 measured %2 mm against its stored TLO %3 mm: %4 mm apart, more than the tolerance "
                     "%5 mm. It may be broken or worn. The spindle is stopped and lifted; its stored TLO is "
                     "kept in the table and in LinuxCNC. Look at the tool and replace it before you cut.")
                      .arg(tool)
                      .arg(mm(measured), mm(*stored), mm(difference),
                          formatNumber(tolerance, NumberFormat::upTo(3)));
        }
        done(result);
    });
}

} // namespace Toffee
