// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/grblhal/grblhalcontroller.h"

#include <algorithm>
#include <cmath>

#include <QDeadlineTimer>
#include <QStringList>
#include <QTimer>

#include "model/limits.h"
#include "model/numberformat.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QString mm(double v)
{
    return formatNumber(v, NumberFormat::fixed(3));
}

double atResolution(double v)
{
    return std::round(v * 1000.0) / 1000.0;
}

ReplyKind neutralKind(QByteArrayView line)
{
    switch (GrblHal::classifyReply(line).kind) {
    case GrblHal::ReplyKind::Ok:
        return ReplyKind::Ok;
    case GrblHal::ReplyKind::Error:
        return ReplyKind::Error;
    case GrblHal::ReplyKind::Alarm:
        return ReplyKind::Alarm;
    case GrblHal::ReplyKind::Status:
        return ReplyKind::Status;
    default:
        return ReplyKind::Other;
    }
}

// "error:9", "ALARM:5": the line as grblHAL said it; what it means comes from meaningOf.
QString neutralMessage(QByteArrayView line)
{
    return QString::fromUtf8(line.trimmed());
}

// What "ALARM:5" or "error:9" means and what to do.
QString meaningOf(QStringView said)
{
    const QByteArray line = said.toUtf8();
    const GrblHal::Reply reply = GrblHal::classifyReply(line);
    if (!reply.code)
        return {};
    if (reply.kind == GrblHal::ReplyKind::Alarm)
        return GrblHal::alarmMeaning(*reply.code);
    if (reply.kind == GrblHal::ReplyKind::Error)
        return GrblHal::errorMeaning(*reply.code);
    return {};
}

QString stateWord(const GrblHal::StatusReport &report)
{
    return report.stateName.isEmpty() ? u"Unknown"_s : report.stateName;
}

} // namespace

ReplyGrammar GrblHalController::grammar(const GrblHalController *controller)
{
    ReplyGrammar g;
    g.classify = neutralKind;
    g.status = [controller](QByteArrayView line,
                   const std::optional<MachineStatus> &previous) -> std::optional<MachineStatus> {
        const auto report = GrblHal::parseStatusReport(line);
        if (!report)
            return std::nullopt;
        MachineStatus s;
        s.state = stateWord(*report);
        // grblHAL sends WCO now and then: otherwise the last one holds (MPos − WPos of the last status).
        std::array<double, 3> wco { 0, 0, 0 };
        if (report->workCoordinateOffset) {
            wco = { report->workCoordinateOffset->x(), report->workCoordinateOffset->y(),
                report->workCoordinateOffset->z() };
        } else if (previous) {
            for (size_t i = 0; i < 3; ++i)
                wco[i] = previous->mpos[i] - previous->wpos[i];
        }
        for (size_t i = 0; i < 3; ++i) {
            if (report->machinePosition) {
                s.mpos[i] = report->machinePosition->values[i];
                s.wpos[i] = s.mpos[i] - wco[i];
            } else if (report->workPosition) {
                s.wpos[i] = report->workPosition->values[i];
                s.mpos[i] = s.wpos[i] + wco[i];
            }
        }
        if (report->tool)
            s.tool = *report->tool > 0 ? *report->tool : Limits::kEmptySpindle;
        else if (previous)
            s.tool = previous->tool;
        if (controller)
            s.tlo = controller->m_tloInForce;
        return s;
    };
    g.scriptDone = [](QByteArrayView) {
        return false;
    };
    g.message = neutralMessage;
    g.haltMeaning = meaningOf;
    g.refusalMeaning = meaningOf;
    return g;
}

GrblHalController::GrblHalController(MachineLink *link, QObject *parent)
    : MachineController(parent)
    , m_link(link)
{
    m_link->setGrammar(grammar(this));
    connect(m_link, &MachineLink::statusChanged, this, [this](const MachineStatus &status) {
        if (status.tool)
            m_tool = status.tool;
    });
    connect(m_link, &MachineLink::lineReceived, this, [this](const QByteArray &line) {
        // A reset (Ctrl-X, a power dip): grblHAL forgets the offset in force.
        if (GrblHal::classifyReply(line).kind == GrblHal::ReplyKind::Greeting)
            m_tloInForce.reset();
    });
}

QByteArray GrblHalController::number(double value)
{
    return numberBytes(value, NumberFormat::command());
}

void GrblHalController::run(const QByteArray &command, int timeoutMs, Done done, Next next)
{
    m_link->send(command, timeoutMs, [done, next = std::move(next)](const CommandReply &reply) {
        if (!reply.ok()) {
            done(failure(reply));
            return;
        }
        next(reply);
    });
}

void GrblHalController::rememberParameters(const GrblHal::ParameterReport &report)
{
    if (report.toolLengthOffset)
        m_tloInForce = atResolution(report.toolLengthOffset->z());
    m_table.clear();
    for (const auto &[number, entry] : report.tools)
        m_table.append({ number, atResolution(entry.offset.z()), entry.radius });
}

void GrblHalController::readParameters(Done done, std::function<void(const GrblHal::ParameterReport &)> next)
{
    // A line a work offset (and G28, G30, G92, TLO, PRB) and one a tool: more than a reply usually holds.
    constexpr qsizetype kLines = GrblHal::kMaxTools + 64;
    m_link->send(
        "$#", MachineLink::kDefaultTimeoutMs,
        [this, done, next](const CommandReply &reply) {
            if (!reply.ok()) {
                done(failure(reply));
                return;
            }
            GrblHal::ParameterReport report;
            for (const QByteArray &line : reply.lines)
                report.addLine(line);
            if (report.refusedLines > 0 || reply.droppedLines > 0) {
                SessionResult result;
                result.outcome = SessionResult::Outcome::MachineError;
                result.message = tr(
                    "grblHAL's offsets ($#) could not be read whole: lines were malformed or repeated (%1). "
                    "Nothing was changed; check the connection and try again.")
                                     .arg(report.refusedLines + reply.droppedLines);
                done(result);
                return;
            }
            rememberParameters(report);
            next(report);
        },
        ReplyEnd::Ok, kLines);
}

void GrblHalController::inMillimetres(Done done, const QString &what, std::function<void()> next)
{
    readModal(done, [done, what, next](const Modal &modal) {
        if (modal.inches) {
            refuse(done,
                tr("grblHAL is in inches (G20), where its G10 and G38.2 take inches. Toffee %1 in "
                   "millimetres: "
                   "send G21, then try again. Nothing was sent.")
                    .arg(what));
            return;
        }
        next();
    });
}

void GrblHalController::readModal(Done done, std::function<void(const Modal &)> next)
{
    run("$G", MachineLink::kDefaultTimeoutMs, done, [this, done, next](const CommandReply &reply) {
        for (const QByteArray &line : reply.lines) {
            const QByteArray t = line.trimmed();
            if (!t.startsWith("[GC:") || !t.endsWith(']'))
                continue;
            Modal modal;
            for (const QByteArray &word : t.mid(4, t.size() - 5).split(' ')) {
                if (word.startsWith("G5") && word.size() >= 3 && word != "G50")
                    modal.coordinateSystem = QString::fromLatin1(word);
                else if (word == "G20")
                    modal.inches = true;
                else if (word.startsWith('T')) {
                    bool ok = false;
                    const int tool = word.mid(1).toInt(&ok);
                    if (ok && tool >= 0)
                        modal.tool = tool > 0 ? tool : Limits::kEmptySpindle;
                }
            }
            if (modal.tool)
                m_tool = modal.tool;
            next(modal);
            return;
        }
        SessionResult result;
        result.outcome = SessionResult::Outcome::MachineError;
        result.message = tr("grblHAL answered $G without its modal state ([GC:…]); is this grblHAL?");
        done(result);
    });
}

void GrblHalController::connectToMachine(Done done)
{
    openLink(done, [this, done] {
        // A blank line: grblHAL answers "ok", and drops whatever it had half-received.
        run("", MachineLink::kDefaultTimeoutMs, done, [this, done](const CommandReply &) {
            awaitStatus(2000, [this, done](std::optional<MachineStatus> status) {
                if (!status) {
                    SessionResult result;
                    result.outcome = SessionResult::Outcome::LinkFailure;
                    result.message
                        = tr("The machine answered but sent no status report when asked; is it "
                             "grblHAL? If it is a Carvera, choose the Carvera (--controller carvera).");
                    done(result);
                    return;
                }
                // G4 P0 is answered once the machine stands still ($I is refused while it moves); in alarm
                // grblHAL refuses it, and stands still anyway.
                if (status->isAlarm()) {
                    readBuild(done, *status);
                    return;
                }
                run("G4 P0", MachineLink::kMotionTimeoutMs, done,
                    [this, done, status](const CommandReply &) { readBuild(done, *status); });
            });
        });
    });
}

void GrblHalController::readBuild(Done done, const MachineStatus &status)
{
    run("$I", MachineLink::kDefaultTimeoutMs, done, [this, done, status](const CommandReply &reply) {
        GrblHal::BuildInfoBuilder builder;
        for (const QByteArray &line : reply.lines)
            builder.addLine(line);
        if (!builder.info().isGrblHal()) {
            SessionResult result;
            result.outcome = SessionResult::Outcome::MachineError;
            result.message = builder.hasVersionAndOptions()
                ? tr(
                    "This controller answered $I as Grbl does but did not say it is grblHAL "
                    "([FIRMWARE:grblHAL]); it may be classic Grbl, which keeps no tool table. Toffee manages "
                    "grblHAL and the Carvera.")
                : tr("This machine did not answer $I as grblHAL does. If it is a Carvera, connect with the "
                     "Carvera chosen (--controller carvera).");
            done(result);
            return;
        }
        m_build = builder.info();
        m_firmware.kind = FirmwareInfo::Kind::GrblHal;
        m_firmware.version = m_build.version;
        m_firmware.toolTableSize = m_build.toolTableSize;
        readReportUnits(done, [this, done, status] { readOffsetsAfterBuild(done, status); });
    });
}

// $13 = 1 makes grblHAL report every position and offset in inches: Toffee reads millimetres, so it does not
// go on with such a controller rather than take each of its numbers for millimetres.
void GrblHalController::readReportUnits(Done done, std::function<void()> next)
{
    run("$13", MachineLink::kDefaultTimeoutMs, done, [done, next](const CommandReply &reply) {
        for (const QByteArray &line : reply.lines) {
            if (line.trimmed().startsWith("$13=") && line.trimmed().mid(4).toInt() != 0) {
                done(SessionResult::failed(SessionResult::Outcome::Refused,
                    tr("grblHAL reports in inches ($13=1); Toffee reads millimetres. Set $13=0 (reports in "
                       "millimetres), then connect again.")));
                return;
            }
        }
        next();
    });
}

void GrblHalController::readOffsetsAfterBuild(Done done, const MachineStatus &status)
{
    readModal(done, [this, done, status](const Modal &) {
        readParameters(done, [this, done, status](const GrblHal::ParameterReport &) {
            SessionResult result
                = tloResult(m_tool.value_or(Limits::kEmptySpindle), m_tloInForce.value_or(0.0), std::nullopt);
            result.status = status;
            result.status->tool = m_tool;
            result.status->tlo = m_tloInForce;
            result.controllerTools = m_table;
            done(result);
        });
    });
}

SessionResult GrblHalController::tloResult(int tool, double tlo, std::optional<double> contactMz) const
{
    SessionResult result;
    result.tool = tool;
    result.tlo = TloReading { atResolution(tlo), m_reference, contactMz };
    return result;
}

void GrblHalController::status(Done done)
{
    awaitStatus(2000, [this, done](std::optional<MachineStatus> status) {
        SessionResult result;
        if (!status) {
            result.outcome = SessionResult::Outcome::LinkFailure;
            result.message = tr("grblHAL sent no status report within 2 s.");
        } else {
            result.status = status;
            if (!result.status->tool)
                result.status->tool = m_tool; // the report names the tool only now and then
            result.status->tlo = m_tloInForce;
            result.tool = result.status->tool;
        }
        done(result);
    });
}

void GrblHalController::report(Done done)
{
    readParameters(done, [this, done](const GrblHal::ParameterReport &) {
        SessionResult result
            = tloResult(m_tool.value_or(Limits::kEmptySpindle), m_tloInForce.value_or(0.0), std::nullopt);
        result.controllerTools = m_table;
        done(result);
    });
}

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

void GrblHalController::measure(Done done, std::function<void(double)> next)
{
    if (!m_setter) {
        refuse(done,
            tr("Toffee does not know where this machine's tool setter is. Set it first (Machine ▸ Tool "
               "Setter…, or toffee-cli --setter X,Y,ZMIN in machine coordinates)."));
        return;
    }
    const ToolSetter setter = *m_setter;
    readModal(done, [this, done, next, setter](const Modal &modal) {
        if (modal.inches) {
            refuse(done,
                tr("grblHAL is in inches (G20), where its G10 and G38.2 take inches. Toffee %1 in "
                   "millimetres: send G21, then try again. Nothing was sent.")
                    .arg(tr("probes")));
            return;
        }
        readParameters(done, [this, done, next, setter, modal](const GrblHal::ParameterReport &report) {
            // G38.2 takes work coordinates: the machine Z wanted, less the offset in force (the coordinate
            // system's, G92's and the tool's), which is what grblHAL's WCO is.
            double wco = report.toolLengthOffset ? report.toolLengthOffset->z() : 0.0;
            if (const auto it = report.workOffsets.find(modal.coordinateSystem);
                it != report.workOffsets.end())
                wco += it->z();
            if (const auto it = report.workOffsets.find(u"G92"_s); it != report.workOffsets.end())
                wco += it->z();
            const auto work = [wco](double machineZ) {
                return number(machineZ - wco);
            };
            const int motion = MachineLink::kMotionTimeoutMs;
            auto touch = [done, setter](const CommandReply &reply) -> std::optional<double> {
                std::optional<GrblHal::ProbeReport> found;
                for (const QByteArray &line : reply.lines) {
                    if (auto p = GrblHal::parseProbeReport(line))
                        found = p;
                }
                if (!found || !found->touched) {
                    SessionResult result;
                    result.outcome = SessionResult::Outcome::MachineError;
                    result.message = tr("The probe did not report a touch. Nothing was measured.");
                    done(result);
                    return std::nullopt;
                }
                // A contact outside the search (from the safe height down to the setter's lowest Z) is no
                // contact the cycle can make: a reply to trust no further.
                const double z = found->position.z();
                if (z < setter.zMin - 1.0 || z > setter.safeZ + 1.0) {
                    done(SessionResult::failed(SessionResult::Outcome::MachineError,
                        tr("grblHAL reported the contact at machine Z %1 mm, outside the search from %2 to "
                           "%3 "
                           "mm. Nothing was written or recorded; check the tool setter's settings and the "
                           "machine.")
                            .arg(mm(z), mm(setter.safeZ), mm(setter.zMin))));
                    return std::nullopt;
                }
                return z;
            };
            run("M5", MachineLink::kDefaultTimeoutMs, done, [=, this](const CommandReply &) {
                run("G53 G0 Z" + number(setter.safeZ), motion, done, [=, this](const CommandReply &) {
                    run("G53 G0 X" + number(setter.x) + " Y" + number(setter.y), motion, done,
                        [=, this](const CommandReply &) {
                            run("G38.2 Z" + work(setter.zMin) + " F" + number(setter.seekFeed), motion, done,
                                [=, this](const CommandReply &fast) {
                                    const auto first = touch(fast);
                                    if (!first)
                                        return;
                                    const double up = std::min(setter.safeZ, *first + setter.backoff);
                                    const double down = std::max(setter.zMin, *first - setter.backoff);
                                    run("G53 G0 Z" + number(up), motion, done,
                                        [=, this](const CommandReply &) {
                                            run("G38.2 Z" + work(down) + " F" + number(setter.latchFeed),
                                                motion, done, [=, this](const CommandReply &slow) {
                                                    const auto contact = touch(slow);
                                                    if (!contact)
                                                        return;
                                                    run("G53 G0 Z" + number(setter.safeZ), motion, done,
                                                        [=, this](const CommandReply &) {
                                                            // "ok" to a move means queued; G4 P0's comes once
                                                            // the machine has stopped, lifted.
                                                            run("G4 P0", motion, done,
                                                                [next, contact](const CommandReply &) {
                                                                    next(atResolution(*contact));
                                                                });
                                                        });
                                                });
                                        });
                                });
                        });
                });
            });
        });
    });
}

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

void GrblHalController::probe(Done done)
{
    done = recording(std::move(done), RecordingKind::Probe);
    const auto tool = spindleTool(done, tr("measure"));
    if (!tool)
        return;
    measure(done, [this, done, tool = *tool](double contact) {
        const bool first = !m_reference;
        const double reference = m_reference.value_or(contact);
        const double tlo = atResolution(contact - reference);
        writeOffset(tool, tlo, done, [this, done, tool, tlo, contact, first, reference](const QString &note) {
            m_reference = reference;
            SessionResult result = tloResult(tool, tlo, contact);
            QStringList notes;
            if (first)
                notes << tr("T%1 is this machine's reference tool (its TLO is 0): every tool is measured "
                            "against its contact at machine Z %2 mm.")
                             .arg(tool)
                             .arg(mm(reference));
            if (!note.isEmpty())
                notes << note;
            result.message = notes.join(u' ');
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
    if (!m_reference) {
        refuse(done,
            tr("This machine has no reference tool yet, so a new length cannot be compared. Probe a tool "
               "first: the first one measured becomes the reference."));
        return;
    }
    // The stored TLO: the table's; else the controller's own entry for the tool, unless it is empty (0.000,
    // as pull-offsets reads it). Never the offset in force, which after M61 is another tool's.
    std::optional<double> stored = storedTlo;
    for (const ControllerTool &entry : std::as_const(m_table)) {
        if (!stored && entry.tool == *tool && fitsTable(*tool) && std::fabs(entry.tlo) >= kReadBackTolerance)
            stored = entry.tlo;
    }
    if (!stored) {
        refuse(done,
            tr("T%1 has no stored TLO to compare with, in the table or in grblHAL's own: probe it first.")
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
                     "kept in the table and in grblHAL. Look at the tool and replace it before you cut.")
                      .arg(tool)
                      .arg(mm(measured), mm(*stored), mm(difference),
                          formatNumber(tolerance, NumberFormat::upTo(3)));
        }
        done(result);
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

void GrblHalController::selectTool(int tool, Done done)
{
    if (auto valid = validateToolNumber(tool); !valid) {
        refuse(done, valid.error().message);
        return;
    }
    run("M61 Q" + QByteArray::number(std::max(tool, 0)), MachineLink::kDefaultTimeoutMs, done,
        [this, done, tool](const CommandReply &) {
            readModal(done, [done, tool](const Modal &modal) {
                SessionResult result;
                result.tool = modal.tool;
                if (modal.tool != (tool > 0 ? tool : Limits::kEmptySpindle)) {
                    result.outcome = SessionResult::Outcome::MachineError;
                    result.message = tr("grblHAL was told T%1 is in the spindle but reports T%2.")
                                         .arg(tool)
                                         .arg(modal.tool.value_or(0));
                }
                done(result);
            });
        });
}

void GrblHalController::unlock(Done done, std::optional<double> brokenToolTlo)
{
    Q_UNUSED(brokenToolTlo) // a failed break test changed nothing in grblHAL
    run("$X", MachineLink::kDefaultTimeoutMs, done, [this, done](const CommandReply &) { status(done); });
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

void GrblHalController::abort()
{
    m_link->sendRealtime('\x18');
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
    auto remaining = std::make_shared<QList<ControllerTool>>(tools);
    auto written = std::make_shared<QStringList>();
    // A refusal half-way says exactly which entries changed before it and which did not.
    const Done done = [finished, remaining, written](const SessionResult &r) {
        if (r.ok() || (written->isEmpty() && remaining->isEmpty()))
            return finished(r);
        SessionResult partly = r;
        QStringList notWritten;
        for (const ControllerTool &t : std::as_const(*remaining))
            notWritten << u"T%1"_s.arg(t.tool);
        partly.message += u' '
            + tr("Written before it: %1; not written: %2.")
                  .arg(written->isEmpty() ? tr("nothing") : written->join(u", "_s),
                      notWritten.isEmpty() ? tr("nothing") : notWritten.join(u", "_s));
        finished(partly);
    };
    auto step = std::make_shared<std::function<void()>>();
    // Each command's answer holds the function; it holds itself only weakly, so it goes with the last.
    *step = [this, done, tools, remaining, written, self = std::weak_ptr(step)] {
        if (remaining->isEmpty()) {
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
                SessionResult result = tloResult(
                    m_tool.value_or(Limits::kEmptySpindle), m_tloInForce.value_or(0.0), std::nullopt);
                result.controllerTools = m_table;
                if (!differ.isEmpty()) {
                    result.outcome = SessionResult::Outcome::MachineError;
                    result.message
                        = tr("grblHAL's table does not read back as written: %1.").arg(differ.join(u"; "_s));
                }
                done(result);
            });
            return;
        }
        const ControllerTool t = remaining->first();
        run("G10 L1 P" + QByteArray::number(t.tool) + " Z" + number(atResolution(t.tlo)) + " R"
                + number(std::max(0.0, t.radius)),
            MachineLink::kDefaultTimeoutMs, done,
            [remaining, written, step = self.lock()](const CommandReply &) {
                *written << u"T%1"_s.arg(remaining->takeFirst().tool);
                (*step)();
            });
    };
    (*step)();
}

} // namespace Toffee
