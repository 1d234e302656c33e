// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/carvera/machinesession.h"

#include <cmath>

#include <QDateTime>
#include <QPointer>
#include <QTimer>

#include "model/clock.h"
#include "model/gcode/carvera.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "serial/transport/linetransport.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

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

} // namespace

QString MachineSession::floodNote(const CommandReply &reply)
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

MachineSession::MachineSession(MachineLink *link, QObject *parent)
    : MachineController(parent)
    , m_link(link)
{
    m_link->setGrammar(carveraGrammar());
    connect(m_link, &MachineLink::statusChanged, this, [this](const MachineStatus &status) {
        if (status.tool)
            m_tool = status.tool;
        else if (m_firmware.kind == FirmwareInfo::Kind::Stock)
            m_tool = Limits::kEmptySpindle; // the stock firmware leaves T: out for an empty spindle
    });
}

std::optional<OffsetReport> MachineSession::offsetsIn(const QList<QByteArray> &reply) const
{
    std::optional<OffsetReport> last;
    for (const QByteArray &line : reply) {
        if (auto r = parseTloReport(line))
            last = r;
    }
    return last;
}

QString MachineSession::setTloCommand(double tlo) const
{
    return u"M493.3 Z"_s + QString::fromLatin1(number(tlo));
}

QString MachineSession::aboveZ0Command(double height) const
{
    return u"M493.3 H"_s + QString::fromLatin1(number(height));
}

QString MachineSession::restoreCommand(int tool, double tlo) const
{
    return tr("M493.2 T%1, then M493.3 Z%2").arg(tool).arg(QString::fromLatin1(number(tlo)));
}

QByteArray MachineSession::number(double value)
{
    return numberBytes(value, NumberFormat::command());
}

void MachineSession::run(const QByteArray &command, int timeoutMs, Done done,
    std::function<void(const CommandReply &)> next, ReplyEnd end)
{
    m_link->send(
        command, timeoutMs,
        [done, next = std::move(next)](const CommandReply &reply) {
            if (!reply.ok()) {
                done(failure(reply));
                return;
            }
            next(reply);
        },
        end);
}

// The TLO in force is the status report's (T:), whatever the firmware prints elsewhere: after M493.3 Z<v>
// its M493.4 prints v as the "current tool offset". M493.4 adds the reference, and the current MCS Z when
// current - reference is that TLO (after a probe).
void MachineSession::readOffsets(Done done, SessionResult result)
{
    awaitStatus(2000, [this, done, result](std::optional<MachineStatus> status) mutable {
        if (!status) {
            SessionResult bad;
            bad.outcome = SessionResult::Outcome::LinkFailure;
            bad.message = tr("The machine sent no status report within 2 s, and the TLO in force is read "
                             "from it. Nothing was recorded; check the cable or the Wi-Fi and try again.");
            done(bad);
            return;
        }
        result.status = status;
        if (status->tool)
            m_tool = status->tool;
        if (!status->tool || !status->tlo) {
            // The stock firmware leaves T: out when the spindle is empty.
            result.tool = result.tool ? result.tool : std::optional<int>(Limits::kEmptySpindle);
            done(result);
            return;
        }
        result.tool = result.tool ? result.tool : status->tool;
        const double tloInForce = *status->tlo;
        if (m_firmware.kind == FirmwareInfo::Kind::Stock) {
            result.tlo = TloReading::from(tloInForce, std::nullopt); // M493.4 says nothing there
            done(result);
            return;
        }
        run("M493.4", MachineLink::kDefaultTimeoutMs, done,
            [done, result, tloInForce](const CommandReply &reply) mutable {
                for (const QByteArray &line : reply.lines) {
                    if (auto report = parseTloReport(line)) {
                        result.tlo = TloReading::from(tloInForce, report);
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
                             "recorded; try again, and check the cable or the Wi-Fi if it happens twice.")
                              .arg(reply.lines.isEmpty() ? QString()
                                                         : u": \""_s + excerpt(reply.lines.front()) + u'"')
                        + floodNote(reply);
                }
                done(bad);
            });
    });
}

void MachineSession::status(Done done)
{
    awaitStatus(2000, [this, done](std::optional<MachineStatus> status) {
        SessionResult result;
        if (!status) {
            result.outcome = SessionResult::Outcome::LinkFailure;
            result.message = tr("The machine sent no status report within 2 s.");
        } else {
            result.status = status;
            result.tool = status->tool;
            if (status->tool)
                m_tool = status->tool;
        }
        done(result);
    });
}

void MachineSession::report(Done done)
{
    readOffsets(done, SessionResult {});
}

void MachineSession::probe(Done done)
{
    measure(recording(std::move(done), RecordingKind::Probe));
}

// M491 as the tool's plan says: R<n> for its touches, X and Y for its touch-off point (the community
// firmware's; Makera's measures once at the centre). The firmware's latch feed is its own setting.
void MachineSession::measure(Done done)
{
    const int tool = m_tool.value_or(Limits::kEmptySpindle);
    const ProbePlan plan = probePlan(tool);
    QByteArray command = "M491";
    QStringList notes;
    if (plan.touches > 1 || plan.isOffCentre()) {
        if (m_firmware.kind == FirmwareInfo::Kind::Stock)
            return refuse(done,
                tr("Makera's firmware measures a tool once, at the setter's centre (its M491 takes no R, X "
                   "or "
                   "Y): T%1's settings (%2) need the community firmware. Nothing was sent.")
                    .arg(tool)
                    .arg(plan.summary()));
        if (auto valid = plan.validate(); !valid)
            return refuse(done,
                tr("T%1 cannot be probed so: %2 Nothing was sent.").arg(tool).arg(valid.error().message));
        if (plan.touches > 1) {
            command += " R" + QByteArray::number(plan.touches);
            if (plan.turn)
                notes << tr(
                    "Between its %1 touches the firmware lifts 25 mm for you to turn the cutter to its "
                    "next edge by hand.")
                             .arg(plan.touches);
        }
        if (plan.offsetX != 0.0)
            command += " X" + number(plan.offsetX);
        if (plan.offsetY != 0.0)
            command += " Y" + number(plan.offsetY);
    }
    if (plan.latchFeed)
        notes << tr(
            "The firmware touches at its own latch feed (atc.probe.slow_rate_mm_m in its config), not "
            "T%1's %2 mm/min.")
                     .arg(tool)
                     .arg(millimetres(*plan.latchFeed, false));
    run(
        command, MachineLink::kMotionTimeoutMs, done,
        [this, done, plan, tool, notes](const CommandReply &reply) {
            const auto probe = lastProbe(reply.lines);
            if (!probe || !probe->triggered) {
                SessionResult bad;
                bad.outcome = SessionResult::Outcome::MachineError;
                bad.message
                    = tr("The machine finished probing but its probe result ([PRB:…]) could not be read. "
                         "Nothing was recorded; check the offsets (Report) before you cut.")
                    + floodNote(reply);
                done(bad);
                return;
            }
            if (plan.touches > 1)
                return takeLongestEdge(tool, plan, repeatedMeasurement(reply.lines), notes, done);
            readOffsets(
                [done, notes](const SessionResult &r) {
                    // After a probe, current - reference is the TLO: when the machine's two reports disagree,
                    // neither is recorded.
                    if (r.ok() && r.tlo && r.tlo->referenceMz && !r.tlo->currentMz) {
                        SessionResult bad = r;
                        bad.outcome = SessionResult::Outcome::MachineError;
                        bad.message
                            = tr("The machine measured the tool, but its two reports disagree: the TLO "
                                 "in force is %1 mm, and its offset report does not add up to it. "
                                 "Nothing was recorded; probe again.")
                                  .arg(millimetres(r.tlo->tlo(), false));
                        done(bad);
                        return;
                    }
                    SessionResult noted = r;
                    noted.message = QStringList(notes).join(u' ');
                    done(noted);
                },
                SessionResult {});
        },
        ReplyEnd::Script);
}

// After M491 R<n>: each pass's TLO from the firmware's summary, their machine Z against its reference. The
// firmware prints the longest edge's as "Using" but keeps the shortest edge's in force (ATCHandler.cpp: the
// lowest contact): Toffee sets the longest edge's (M493.3 Z), so that no edge cuts deeper than the offset
// says, and reads it back.
void MachineSession::takeLongestEdge(
    int tool, const ProbePlan &plan, const RepeatedMeasurement &measured, const QStringList &notes, Done done)
{
    if (measured.tlos.size() != plan.touches) {
        return done(SessionResult::failed(SessionResult::Outcome::MachineError,
            tr("The firmware printed %1 of the %2 measurements it was asked for (M491 R%2). Nothing was "
               "recorded; check the offsets (Report) before you cut.")
                .arg(measured.tlos.size())
                .arg(plan.touches)));
    }
    const double longest = *std::max_element(measured.tlos.cbegin(), measured.tlos.cend());
    readOffsets(
        [this, done, tool, plan, measured, notes, longest](const SessionResult &r) {
            if (!r.ok() || !r.tlo)
                return done(r);
            if (!r.tlo->referenceMz)
                return done(SessionResult::failed(SessionResult::Outcome::MachineError,
                    tr("The firmware reported no reference tool offset, so its %1 measurements cannot be put "
                       "in machine coordinates. Nothing was recorded.")
                        .arg(plan.touches)));
            const double reference = *r.tlo->referenceMz;
            QList<double> touches;
            for (double tlo : measured.tlos)
                touches << std::round((tlo + reference) * 1000.0) / 1000.0;
            const auto finish = [done, tool, plan, touches, reference, longest, notes](
                                    const SessionResult &set, const QString &corrected) {
                if (!set.ok())
                    return done(set);
                SessionResult result = set;
                result.tool = tool;
                result.tlo = TloReading { longest, reference, longest + reference, touches };
                // The finding first: it is what the operator must act on.
                QStringList all { spreadFinding(tool, touches, plan), corrected };
                all << notes;
                all.removeAll(QString());
                result.message = all.join(u' ');
                done(result);
            };
            if (std::fabs(r.tlo->tlo() - longest) <= 0.0005)
                return finish(r, {});
            const QString corrected = tr(
                "Toffee set the longest edge's TLO (%2 mm) where the firmware kept the shortest's (%1 mm): "
                "no edge cuts deeper than the offset says.")
                                          .arg(millimetres(r.tlo->tlo(), false), millimetres(longest, false));
            setTloTo(longest, [finish, corrected](const SessionResult &set) { finish(set, corrected); });
        },
        SessionResult {});
}

MachineSession::Done MachineSession::expectingTlo(double tlo, Done done)
{
    return [done = std::move(done), tlo](const SessionResult &r) {
        if (r.ok() && (!r.tlo || std::fabs(r.tlo->tlo() - tlo) > 0.0005)) {
            SessionResult bad = r;
            bad.outcome = SessionResult::Outcome::MachineError;
            bad.message = tr("The machine was told TLO %1 mm but reports %2 mm in force. Check the offsets "
                             "before you cut.")
                              .arg(millimetres(tlo, false))
                              .arg(r.tlo ? millimetres(r.tlo->tlo(), false) : tr("none"));
            done(bad);
            return;
        }
        done(r);
    };
}

void MachineSession::setTloTo(double tlo, Done done)
{
    run("M493.3 Z" + number(tlo), MachineLink::kDefaultTimeoutMs, done,
        [this, done, tlo](const CommandReply &) { readOffsets(expectingTlo(tlo, done), SessionResult {}); });
}

void MachineSession::setTlo(double tlo, Done done)
{
    done = recording(std::move(done), RecordingKind::ManualSet);
    if (auto why = unsupported(false))
        return refuse(done, *why);
    if (auto r = validateOffset(tr("The tool length offset"), tlo); !r)
        return refuse(done, r.error().message);
    if (auto why = emptySpindle())
        return refuse(done, *why);
    setTloTo(tlo, done);
}

// The firmware takes M493.3 with an empty spindle (T-1), shows 0.000 in force and gives the value to the next
// tool M493.2 names (seen on the community firmware): a TLO is only set for a tool in the spindle.
std::optional<QString> MachineSession::emptySpindle() const
{
    if (m_tool != Limits::kEmptySpindle)
        return std::nullopt;
    return tr("The machine says the spindle is empty (T-1): a TLO set now would be kept by the firmware and "
              "given to whichever tool is selected next. Put the tool in and select it (Machine ▸ Select "
              "Tool, toffee-cli select-tool N), then set its TLO. Nothing was sent.");
}

// The tool tip is `height` above work Z0. The firmware's M493.3 H adds to its "current tool offset", which
// after an M493.3 Z is no MCS Z (it is off by the reference then, 115 mm on a C1): Toffee works the TLO out
// from the status report instead (work Z = machine Z - work offset - TLO, so the TLO that puts the tip at
// `height` is the TLO in force + work Z - height) and sets it with M493.3 Z.
void MachineSession::setTloAboveZ0(double height, Done done)
{
    done = recording(std::move(done), RecordingKind::ManualSet);
    if (auto why = unsupported(false))
        return refuse(done, *why);
    if (auto r = validateOffset(tr("The height above Z0"), height); !r)
        return refuse(done, r.error().message);
    if (auto why = emptySpindle())
        return refuse(done, *why);
    awaitStatus(2000, [this, done, height](std::optional<MachineStatus> status) {
        if (!status || !status->tlo) {
            SessionResult bad;
            bad.outcome = SessionResult::Outcome::LinkFailure;
            bad.message = tr("The machine sent no status report within 2 s; its TLO was not set.");
            done(bad);
            return;
        }
        const double tlo = std::round((*status->tlo + status->wpos[2] - height) * 1000.0) / 1000.0;
        if (auto r = validateOffset(tr("The tool length offset"), tlo); !r)
            return refuse(done, r.error().message);
        setTloTo(tlo, done);
    });
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

void MachineSession::restoreTlo(int tool, double tlo, Done done)
{
    if (auto r = validateToolNumber(tool); !r)
        return refuse(done, r.error().message);
    if (auto r = validateOffset(tr("The tool length offset"), tlo); !r)
        return refuse(done, r.error().message);
    if (auto why = unsupported(false))
        return refuse(done, *why);
    selectTool(tool, [this, done, tlo](const SessionResult &selected) {
        if (!selected.ok()) {
            done(selected);
            return;
        }
        // The table already holds this TLO: a restore changes no tool, and goes into the history as a
        // restore.
        setTloTo(tlo,
            recording(
                [done](const SessionResult &r) {
                    SessionResult restored = r;
                    if (restored.recording)
                        restored.recording->kind = RecordingKind::Restore;
                    done(restored);
                },
                RecordingKind::ManualSet));
    });
}

void MachineSession::abort()
{
    m_link->sendRealtime(0x18);
}

} // namespace Toffee
