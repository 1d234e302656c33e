// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/machinesession.h"

#include <cmath>

#include <QDateTime>
#include <QPointer>
#include <QTimer>

#include "model/numberformat.h"
#include "model/textparsing.h"
#include "serial/linetransport.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// A tolerance as the operator typed it: "0.02", not "0.020"; in their own decimal mark.
QString toleranceText(double tolerance)
{
    return formatNumber(tolerance, NumberFormat::upTo(3).inLocale());
}

QString text(const QByteArray &line)
{
    return QString::fromUtf8(line);
}

// A machine's line in a message for people: enough to recognise, never pages of it.
QString excerpt(const QByteArray &line)
{
    constexpr qsizetype kMaxBytes = 200;
    return line.size() <= kMaxBytes ? text(line) : text(line.first(kMaxBytes)) + u'\u2026';
}

// Why a result may be missing from a reply: the machine printed more than a reply keeps.
QString floodNote(const CommandReply &reply)
{
    if (reply.droppedLines == 0)
        return {};
    return u' '
        + MachineSession::tr(
            "The machine printed %1 lines before its answer; only the last %2 were kept, and "
            "the result may have been among the others.")
              .arg(reply.droppedLines + reply.lines.size())
              .arg(reply.lines.size());
}

// Running a command of its own: a late answer to it could be taken for one of ours.
} // namespace

MachineSession::MachineSession(MachineLink *link, QObject *parent)
    : QObject(parent)
    , m_link(link)
{
    connect(m_link, &MachineLink::statusChanged, this, [this](const MachineStatus &status) {
        if (status.tool)
            m_tool = status.tool;
        else if (m_firmware.kind == FirmwareInfo::Kind::Stock)
            m_tool = Limits::kEmptySpindle; // the stock firmware leaves T: out for an empty spindle
    });
}

Result<void> MachineSession::validateTolerance(double tolerance)
{
    if (!std::isfinite(tolerance))
        return Error { tr("The break-test tolerance is not a number; enter a value such as 0.1 mm.") };
    if (tolerance < kMinTolerance)
        return Error {
            tr("A break-test tolerance of %1 mm is too small: the machine halts below %2 mm. Use %2 mm "
               "or more (%3 mm is the default).")
                .arg(toleranceText(tolerance), toleranceText(kMinTolerance), toleranceText(kDefaultTolerance))
        };
    if (tolerance > kMaxOffset)
        return Error {
            tr("A break-test tolerance of %1 mm is larger than any tool.").arg(toleranceText(tolerance))
        };
    return {};
}

Result<void> MachineSession::validateOffset(const QString &what, double value)
{
    if (!std::isfinite(value) || std::fabs(value) > kMaxOffset)
        return Error { tr("%1 must be a number from -%2 to %2 mm.").arg(what).arg(kMaxOffset) };
    return {};
}

Result<void> MachineSession::validateToolNumber(int tool)
{
    if (tool < Limits::kEmptySpindle || tool > Limits::kMaxToolNumber)
        return Error { tr("Tool %1 is not a tool number; use %2 to %3 (%4 for an empty spindle).")
                           .arg(tool)
                           .arg(Limits::kMinToolNumber)
                           .arg(Limits::kMaxToolNumber)
                           .arg(Limits::kEmptySpindle) };
    return {};
}

QByteArray MachineSession::number(double value)
{
    return numberBytes(value, NumberFormat::command());
}

void MachineSession::refuse(Done done, const QString &message)
{
    SessionResult result;
    result.outcome = SessionResult::Outcome::Refused;
    result.message = message;
    QTimer::singleShot(0, [done, result] { done(result); });
}

SessionResult MachineSession::failure(const CommandReply &reply)
{
    SessionResult result;
    result.message = reply.message;
    switch (reply.status) {
    case CommandReply::Status::Timeout:
    case CommandReply::Status::LinkLost:
        result.outcome = SessionResult::Outcome::LinkFailure;
        break;
    default:
        result.outcome = SessionResult::Outcome::MachineError;
    }
    return result;
}

void MachineSession::run(
    const QByteArray &command, int timeoutMs, Done done, std::function<void(const CommandReply &)> next)
{
    m_link->send(command, timeoutMs, [done, next = std::move(next)](const CommandReply &reply) {
        if (!reply.ok()) {
            done(failure(reply));
            return;
        }
        next(reply);
    });
}

void MachineSession::readOffsets(Done done, SessionResult result)
{
    if (m_firmware.kind == FirmwareInfo::Kind::Stock)
        return readStatusTlo(std::move(done), std::move(result)); // M493.4 says nothing there
    run("M493.4", MachineLink::kDefaultTimeoutMs, done,
        [this, done, result](const CommandReply &reply) mutable {
            for (const QByteArray &line : reply.lines) {
                if (auto tlo = parseTloReport(line)) {
                    result.tlo = tlo;
                    result.tool = result.tool ? result.tool : m_tool;
                    done(result);
                    return;
                }
            }
            SessionResult bad;
            bad.outcome = SessionResult::Outcome::MachineError;
            const auto report
                = std::find_if(reply.lines.cbegin(), reply.lines.cend(), isImplausibleTloReport);
            if (report != reply.lines.cend()) {
                bad.message = tr("The machine's offset report (M493.4) holds values no machine can have: "
                                 "\"%1\". Nothing was recorded; check the offsets on the machine before "
                                 "you cut.")
                                  .arg(excerpt(*report));
            } else {
                bad.message
                    = tr("The machine's offset report (M493.4) could not be read%1. Nothing was "
                         "recorded; try again, and check the cable if it happens twice.")
                          .arg(reply.lines.isEmpty() ? QString()
                                                     : u": \""_s + excerpt(reply.lines.front()) + u'"')
                    + floodNote(reply);
            }
            done(bad);
        });
}

void MachineSession::status(Done done)
{
    awaitStatus(2000, [done](std::optional<MachineStatus> status) {
        SessionResult result;
        if (!status) {
            result.outcome = SessionResult::Outcome::LinkFailure;
            result.message = tr("The machine sent no status report within 2 s.");
        } else {
            result.status = status;
            result.tool = status->tool;
        }
        done(result);
    });
}

void MachineSession::report(Done done)
{
    readOffsets(done, SessionResult {});
}

MachineSession::Done MachineSession::recording(Done done, RecordingKind kind)
{
    return [done = std::move(done), kind](const SessionResult &r) {
        if (!r.ok() || !r.tlo || !r.tool || *r.tool < 0)
            return done(r);
        SessionResult recorded = r;
        const TloSource source = kind == RecordingKind::Probe ? TloSource::Probe : TloSource::Manual;
        recorded.recording = Recording { *r.tool, r.tlo->tlo(), source, r.tlo->knownReferenceMz(),
            std::nullopt, QDateTime::currentDateTimeUtc(), kind, r.tlo->knownCurrentMz() };
        done(recorded);
    };
}

MachineSession::Done MachineSession::recordingVerdict(Done done)
{
    return [done = std::move(done)](const SessionResult &r) {
        const bool broken = r.outcome == SessionResult::Outcome::ToolBroken;
        if (!r.breakTest || !r.tool || *r.tool < 0 || !(r.ok() || broken))
            return done(r);
        SessionResult recorded = r;
        recorded.recording = Recording { *r.tool, std::nullopt, TloSource::Probe, std::nullopt, broken,
            QDateTime::currentDateTimeUtc(), RecordingKind::BreakTest, std::nullopt, r.tolerance,
            r.breakTest->oldTlo, r.breakTest->newTlo };
        done(recorded);
    };
}

void MachineSession::probe(Done done)
{
    done = recording(std::move(done), RecordingKind::Probe);
    run("M491", MachineLink::kMotionTimeoutMs, done, [this, done](const CommandReply &reply) {
        const auto probe = std::find_if(reply.lines.cbegin(), reply.lines.cend(),
            [](const QByteArray &l) { return parseProbeResult(l).has_value(); });
        if (probe == reply.lines.cend() || !parseProbeResult(*probe)->triggered) {
            SessionResult bad;
            bad.outcome = SessionResult::Outcome::MachineError;
            bad.message = tr("The machine finished probing but its probe result ([PRB:…]) could not be read. "
                             "Nothing was recorded; check the offsets (Report) before you cut.")
                + floodNote(reply);
            done(bad);
            return;
        }
        readOffsets(done, SessionResult {});
    });
}

void MachineSession::breakTest(double tolerance, Done done)
{
    done = recordingVerdict(std::move(done));
    if (auto why = unsupported(true))
        return refuse(done, *why);
    if (auto r = validateTolerance(tolerance); !r)
        return refuse(done, r.error().message);
    const QByteArray command = "M491.1 H" + number(tolerance);
    m_link->send(command, MachineLink::kMotionTimeoutMs, [this, done, tolerance](const CommandReply &reply) {
        std::optional<BreakTestReading> reading;
        bool noPrevious = false;
        bool broken = false;
        for (const QByteArray &line : reply.lines) {
            if (!reading)
                reading = parseBreakTest(line);
            noPrevious = noPrevious || line.trimmed() == "No previous TLO included, aborting";
            broken = broken || line.contains("Tool Break Check - check tool for breakage");
        }
        SessionResult result;
        result.tool = m_tool;
        result.tolerance = tolerance;
        result.breakTest = reading;
        if (broken && reading) {
            result.outcome = SessionResult::Outcome::ToolBroken;
            result.message
                = tr("Tool T%1 may be broken: it measured a TLO of %2 mm against %3 mm before (a "
                     "difference of %4 mm; the tolerance is %5 mm). The machine has halted. Check the "
                     "tool and replace it if it is damaged, then Unlock.")
                      .arg(m_tool.value_or(-1))
                      .arg(millimetres(reading->newTlo, false))
                      .arg(millimetres(reading->oldTlo, false))
                      .arg(millimetres(std::fabs(reading->newTlo - reading->oldTlo), false))
                      .arg(toleranceText(tolerance));
            done(result);
            return;
        }
        if (!reply.ok()) {
            done(failure(reply));
            return;
        }
        if (noPrevious) {
            result.outcome = SessionResult::Outcome::MachineError;
            result.message
                = tr("The machine has no TLO for this tool to compare with. Probe the tool first, then "
                     "run the break test.");
        } else if (!reading) {
            result.outcome = SessionResult::Outcome::MachineError;
            result.message
                = tr("The break test ran but its result (\"Old: … , new: …\") could not be read. Run it "
                     "again before you trust the tool.")
                + floodNote(reply);
        } else if (std::fabs(reading->newTlo - reading->oldTlo) > tolerance) {
            // The firmware should have halted; do not call this tool good on our side either.
            result.outcome = SessionResult::Outcome::ToolBroken;
            result.message = tr("Tool T%1 measured %2 mm against %3 mm, more than the %4 mm tolerance.")
                                 .arg(m_tool.value_or(-1))
                                 .arg(millimetres(reading->newTlo, false))
                                 .arg(millimetres(reading->oldTlo, false))
                                 .arg(toleranceText(tolerance));
        }
        done(result);
    });
}

void MachineSession::finishWithReport(const QList<QByteArray> &lines, Done done, const QString &what)
{
    for (const QByteArray &line : lines) {
        if (auto tlo = parseTloReport(line)) {
            SessionResult result;
            result.tlo = tlo;
            result.tool = m_tool;
            done(result);
            return;
        }
    }
    SessionResult bad;
    bad.outcome = SessionResult::Outcome::MachineError;
    bad.message
        = tr("The machine's reply to %1 could not be read. Check the offsets (Report) before you cut.")
              .arg(what);
    done(bad);
}

void MachineSession::setTlo(double tlo, Done done)
{
    done = recording(std::move(done), RecordingKind::ManualSet);
    if (auto why = unsupported(false))
        return refuse(done, *why);
    if (auto r = validateOffset(tr("The tool length offset"), tlo); !r)
        return refuse(done, r.error().message);
    run("M493.3 Z" + number(tlo), MachineLink::kDefaultTimeoutMs, done,
        [this, done, tlo](const CommandReply &reply) {
            finishWithReport(
                reply.lines,
                [done, tlo](const SessionResult &result) {
                    if (result.ok() && std::fabs(result.tlo->tlo() - tlo) > 0.0005) {
                        SessionResult bad = result;
                        bad.outcome = SessionResult::Outcome::MachineError;
                        bad.message = tr("The machine was told TLO %1 mm but reports %2 mm. Check the "
                                         "offsets before you cut.")
                                          .arg(millimetres(tlo, false))
                                          .arg(millimetres(result.tlo->tlo(), false));
                        done(bad);
                        return;
                    }
                    done(result);
                },
                u"M493.3"_s);
        });
}

void MachineSession::setTloAboveZ0(double height, Done done)
{
    done = recording(std::move(done), RecordingKind::ManualSet);
    if (auto why = unsupported(false))
        return refuse(done, *why);
    if (auto r = validateOffset(tr("The height above Z0"), height); !r)
        return refuse(done, r.error().message);
    run("M493.3 H" + number(height), MachineLink::kDefaultTimeoutMs, done,
        [this, done](const CommandReply &reply) { finishWithReport(reply.lines, done, u"M493.3"_s); });
}

void MachineSession::selectTool(int tool, Done done)
{
    if (auto r = validateToolNumber(tool); !r)
        return refuse(done, r.error().message);
    run("M493.2 T" + QByteArray::number(tool), MachineLink::kDefaultTimeoutMs, done,
        [this, done, tool](const CommandReply &) {
            m_tool = tool;
            SessionResult result;
            result.tool = tool;
            done(result);
        });
}

void MachineSession::changeTool(int tool, Done done, std::optional<double> storedTlo)
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
    run("M6 T" + QByteArray::number(tool), kToolChangeTimeoutMs, done,
        [this, done, tool](const CommandReply &reply) {
            m_tool = tool;
            if (tool == Limits::kEmptySpindle)
                return confirmEmptySpindle(done); // nothing to measure
            const bool probed
                = std::any_of(reply.lines.cbegin(), reply.lines.cend(), [](const QByteArray &l) {
                      const auto p = parseProbeResult(l);
                      return p && p->triggered;
                  });
            if (!probed) {
                SessionResult bad;
                bad.outcome = SessionResult::Outcome::MachineError;
                bad.message
                    = tr("T%1 is in the spindle, but its probe result ([PRB:…]) could not be read. Nothing "
                         "was recorded; probe the tool again.")
                          .arg(tool)
                    + floodNote(reply);
                done(bad);
                return;
            }
            readOffsets(done, SessionResult {});
        });
}

// M6 T H: a manual change that takes the table's TLO; the machine's report must then show it.
void MachineSession::changeToStoredTlo(int tool, double tlo, Done done)
{
    run("M6 T" + QByteArray::number(tool) + " H" + number(tlo), kToolChangeTimeoutMs, done,
        [this, done, tool, tlo](const CommandReply &) {
            m_tool = tool;
            SessionResult changed;
            changed.tool = tool;
            readOffsets(
                [done, tool, tlo](const SessionResult &r) {
                    if (r.ok() && (!r.tlo || std::fabs(r.tlo->tlo() - tlo) > 0.0005)) {
                        SessionResult bad = r;
                        bad.outcome = SessionResult::Outcome::MachineError;
                        bad.message
                            = tr("T%1 is in the spindle, but the machine reports TLO %2 mm where it was "
                                 "told %3 mm. Probe T%1 before you cut.")
                                  .arg(tool)
                                  .arg(r.tlo ? millimetres(r.tlo->tlo(), false) : tr("none"))
                                  .arg(millimetres(tlo, false));
                        done(bad);
                        return;
                    }
                    SessionResult restored = r;
                    restored.tool = tool;
                    if (r.tlo)
                        restored.recording
                            = Recording { tool, r.tlo->tlo(), TloSource::Probe, r.tlo->knownReferenceMz(),
                                  std::nullopt, QDateTime::currentDateTimeUtc(), RecordingKind::Restore };
                    done(restored);
                },
                changed);
        });
}

void MachineSession::unlock(Done done)
{
    run("$X", MachineLink::kDefaultTimeoutMs, done, [this, done](const CommandReply &reply) {
        const bool unlocked = std::any_of(reply.lines.cbegin(), reply.lines.cend(),
            [](const QByteArray &l) { return l.trimmed() == "[Caution: Unlocked]"; });
        if (!unlocked) {
            SessionResult bad;
            bad.outcome = SessionResult::Outcome::MachineError;
            bad.message = tr("The machine did not confirm the unlock; check its state before you go on.");
            done(bad);
            return;
        }
        status(done);
    });
}

void MachineSession::restoreTlo(int tool, double tlo, Done done)
{
    if (auto r = validateToolNumber(tool); !r)
        return refuse(done, r.error().message);
    if (auto r = validateOffset(tr("The tool length offset"), tlo); !r)
        return refuse(done, r.error().message);
    selectTool(tool, [this, done, tlo](const SessionResult &selected) {
        if (!selected.ok()) {
            done(selected);
            return;
        }
        // The table already holds this TLO: a restore changes no tool, and goes into the history as a
        // restore.
        setTlo(tlo, [done](const SessionResult &r) {
            SessionResult restored = r;
            if (restored.recording)
                restored.recording->kind = RecordingKind::Restore;
            done(restored);
        });
    });
}

void MachineSession::abort()
{
    m_link->sendRealtime(0x18);
}

} // namespace Toffee
