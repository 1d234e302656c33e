// SPDX-License-Identifier: GPL-3.0-or-later
// What Toffee writes into grblHAL: a TLO (G10 L1 and G43 H, or G43.1 beyond its table) read back before it
// counts, set by hand or restored, and its whole tool table (push), each refused before anything is sent when
// it cannot be right (beyond the one range, in inches, beyond the table).
#include "serial/grblhal/grblhalcontroller.h"

#include <algorithm>
#include <cmath>

#include <QStringList>

#include "model/numberformat.h"

using namespace Qt::StringLiterals;

namespace Toffee {

bool GrblHalController::fitsTable(int tool) const
{
    return m_firmware.hasToolTable() && tool >= 1 && tool <= m_firmware.toolTableSize;
}

void GrblHalController::writeOffset(
    int tool, double tlo, Done done, std::function<void(const QString &note)> next)
{
    // The one range, whichever path brings the TLO (a probe, a set, a restore): nothing beyond it reaches
    // grblHAL.
    if (auto valid = validateOffset(tr("T%1's TLO").arg(tool), tlo); !valid) {
        done(SessionResult::failed(SessionResult::Outcome::MachineError,
            valid.error().message + u' ' + tr("Nothing was written to grblHAL or recorded.")));
        return;
    }
    const bool table = fitsTable(tool);
    auto check = [this, done, next, tool, tlo, table](const GrblHal::ParameterReport &report) {
        QStringList wrong;
        if (!report.toolLengthOffset || std::fabs(report.toolLengthOffset->z() - tlo) > kReadBackTolerance)
            wrong << tr("the offset in force reads %1 mm")
                         .arg(report.toolLengthOffset ? mm(report.toolLengthOffset->z()) : tr("nothing"));
        if (table) {
            const auto entry = report.tools.find(tool);
            if (entry == report.tools.end() || std::fabs(entry->second.offset.z() - tlo) > kReadBackTolerance)
                wrong << tr("T%1's entry reads %2 mm")
                             .arg(tool)
                             .arg(entry == report.tools.end() ? tr("nothing") : mm(entry->second.offset.z()));
        }
        if (!wrong.isEmpty()) {
            SessionResult result;
            result.outcome = SessionResult::Outcome::MachineError;
            result.message = tr("grblHAL was given T%1's TLO %2 mm, but read back %3. Nothing was recorded; "
                                "check the controller's offsets ($#) before you cut.")
                                 .arg(tool)
                                 .arg(mm(tlo), wrong.join(u", "_s));
            done(result);
            return;
        }
        next(table ? QString()
                : m_firmware.hasToolTable()
                ? tr("T%1 is beyond grblHAL's table of %2 tools: its TLO is in force (G43.1) but not "
                     "stored in the controller.")
                      .arg(tool)
                      .arg(m_firmware.toolTableSize)
                : tr("This grblHAL keeps no tool table: the TLO is in force (G43.1) until a reset."));
    };
    inMillimetres(done, tr("writes TLOs"), [=, this] {
        if (table) {
            run("G10 L1 P" + QByteArray::number(tool) + " Z" + number(tlo), MachineLink::kDefaultTimeoutMs,
                done, [=, this](const CommandReply &) {
                    run("G43 H" + QByteArray::number(tool), MachineLink::kDefaultTimeoutMs, done,
                        [=, this](const CommandReply &) { readParameters(done, check); });
                });
        } else {
            run("G43.1 Z" + number(tlo), MachineLink::kDefaultTimeoutMs, done,
                [=, this](const CommandReply &) { readParameters(done, check); });
        }
    });
}

void GrblHalController::setTlo(double tlo, Done done)
{
    done = recording(std::move(done), RecordingKind::ManualSet);
    if (auto valid = validateOffset(tr("The TLO"), tlo); !valid) {
        refuse(done, valid.error().message);
        return;
    }
    const auto tool = spindleTool(done, tr("set a TLO for"));
    if (!tool)
        return;
    const double value = atResolution(tlo);
    writeOffset(*tool, value, done, [this, done, tool = *tool, value](const QString &note) {
        SessionResult result = tloResult(tool, value, std::nullopt);
        result.message = note;
        done(result);
    });
}

void GrblHalController::setTloAboveZ0(double height, Done done)
{
    if (auto valid = validateOffset(tr("The height above Z0"), height); !valid) {
        refuse(done, valid.error().message);
        return;
    }
    awaitStatus(2000, [this, done, height](std::optional<MachineStatus> status) {
        if (!status) {
            SessionResult result;
            result.outcome = SessionResult::Outcome::LinkFailure;
            result.message = tr("grblHAL sent no status report, so the tool's height is not known.");
            done(result);
            return;
        }
        // The work Z grows by what the TLO shrinks: the tip is `height` above Z0 when WPos Z reads it.
        setTlo(m_tloInForce.value_or(0.0) + status->wpos[2] - height, done);
    });
}

void GrblHalController::restoreTlo(int tool, double tlo, Done done)
{
    done = recording(std::move(done), RecordingKind::Restore);
    if (auto valid = validateToolNumber(tool); !valid || tool <= 0) {
        refuse(done,
            valid ? tr("A TLO is restored for a tool, not for an empty spindle.") : valid.error().message);
        return;
    }
    if (auto valid = validateOffset(tr("The TLO"), tlo); !valid) {
        refuse(done, valid.error().message);
        return;
    }
    const double value = atResolution(tlo);
    run("M61 Q" + QByteArray::number(tool), MachineLink::kDefaultTimeoutMs, done,
        [this, done, tool, value](const CommandReply &) {
            m_tool = tool;
            writeOffset(tool, value, done, [this, done, tool, value](const QString &note) {
                SessionResult result = tloResult(tool, value, std::nullopt);
                result.message = note;
                done(result);
            });
        });
}

QString GrblHalController::setTloCommand(double tlo) const
{
    const int tool = m_tool.value_or(0);
    const QString value = QString::fromLatin1(number(atResolution(tlo)));
    return fitsTable(tool) ? u"G10 L1 P%1 Z%2, G43 H%1"_s.arg(tool).arg(value) : u"G43.1 Z"_s + value;
}

QString GrblHalController::aboveZ0Command(double height) const
{
    return tr("%1 (the TLO that puts the tip %2 mm above Z0, from where it is)")
        .arg(setTloCommand(0.0).replace(u"Z0"_s, u"Z…"_s), QString::fromLatin1(number(height)));
}

QString GrblHalController::restoreCommand(int tool, double tlo) const
{
    const QString value = QString::fromLatin1(number(atResolution(tlo)));
    return fitsTable(tool) ? u"M61 Q%1, G10 L1 P%1 Z%2, G43 H%1"_s.arg(tool).arg(value)
                           : u"M61 Q%1, G43.1 Z%2"_s.arg(tool).arg(value);
}

void GrblHalController::readToolTable(Done done)
{
    if (!m_firmware.hasToolTable()) {
        MachineController::readToolTable(done);
        return;
    }
    report(done);
}

void GrblHalController::writeToolTable(const QList<ControllerTool> &tools, Done done)
{
    if (!m_firmware.hasToolTable()) {
        MachineController::writeToolTable(tools, done);
        return;
    }
    QStringList beyond;
    for (const ControllerTool &t : tools) {
        if (!fitsTable(t.tool))
            beyond << u"T%1"_s.arg(t.tool);
        else if (auto valid = validateOffset(tr("T%1's TLO").arg(t.tool), t.tlo); !valid) {
            refuse(done, valid.error().message);
            return;
        }
    }
    if (!beyond.isEmpty()) {
        refuse(done,
            tr("grblHAL's table holds T1 to T%1; %2 cannot be written. Nothing was written: renumber them "
               "or leave them out.")
                .arg(m_firmware.toolTableSize)
                .arg(beyond.join(u", "_s)));
        return;
    }
    inMillimetres(done, tr("writes its table"), [this, done, tools] { writeEntries(tools, done); });
}

void GrblHalController::writeEntries(const QList<ControllerTool> &tools, Done finished)
{
    const WriteOne writeOne = [this](const ControllerTool &t, Done done, std::function<void()> next) {
        run("G10 L1 P" + QByteArray::number(t.tool) + " Z" + number(atResolution(t.tlo)) + " R"
                + number(std::max(0.0, t.radius)),
            MachineLink::kDefaultTimeoutMs, done, [next](const CommandReply &) { next(); });
    };
    const auto verify = [this, tools](Done done) {
        readParameters(done, [this, done, tools](const GrblHal::ParameterReport &report) {
            QStringList differ;
            for (const ControllerTool &t : tools) {
                const auto entry = report.tools.find(t.tool);
                if (entry == report.tools.end()
                    || std::fabs(entry->second.offset.z() - t.tlo) > kReadBackTolerance)
                    differ << tr("T%1 reads %2 mm, not %3 mm")
                                  .arg(t.tool)
                                  .arg(entry == report.tools.end() ? tr("nothing")
                                                                   : mm(entry->second.offset.z()),
                                      mm(t.tlo));
            }
            SessionResult result
                = tloResult(m_tool.value_or(Limits::kEmptySpindle), m_tloInForce.value_or(0.0), std::nullopt);
            result.controllerTools = m_table;
            if (!differ.isEmpty()) {
                result.outcome = SessionResult::Outcome::MachineError;
                result.message
                    = tr("grblHAL's table does not read back as written: %1.").arg(differ.join(u"; "_s));
            }
            done(result);
        });
    };
    writeEach(tools, writeOne, verify, std::move(finished));
}

} // namespace Toffee
