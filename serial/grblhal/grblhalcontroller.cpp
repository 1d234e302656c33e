// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/grblhal/grblhalcontroller.h"

#include <algorithm>
#include <cmath>

#include <QStringList>
#include <QTimer>

#include "model/limits.h"
#include "model/numberformat.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

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

QString GrblHalController::mm(double v)
{
    return formatNumber(v, NumberFormat::fixed(3));
}

double GrblHalController::atResolution(double v)
{
    return std::round(v * 1000.0) / 1000.0;
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

void GrblHalController::abort()
{
    m_link->sendRealtime('\x18');
}

void GrblHalController::stopJog()
{
    if (!m_jogging)
        return abort();
    m_jogCancelled = true;
    m_link->sendRealtime('\x85');
}
} // namespace Toffee
