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

namespace {

// A probe's result among a script's lines: the last one that triggered (the firmware probes fast, then
// slowly, and takes the second).
std::optional<ProbeResult> lastProbe(const QList<QByteArray> &lines)
{
    std::optional<ProbeResult> found;
    for (const QByteArray &line : lines) {
        if (auto p = parseProbeResult(line))
            found = p;
    }
    return found;
}

} // namespace

void MachineSession::probe(Done done)
{
    measure(recording(std::move(done), RecordingKind::Probe));
}

void MachineSession::measure(Done done)
{
    run(
        "M491", MachineLink::kMotionTimeoutMs, done,
        [this, done](const CommandReply &reply) {
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
            readOffsets(
                [done](const SessionResult &r) {
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
                    done(r);
                },
                SessionResult {});
        },
        ReplyEnd::Script);
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

void MachineSession::unlock(Done done, std::optional<double> brokenToolTlo)
{
    awaitStatus(2000, [this, done, brokenToolTlo](std::optional<MachineStatus> before) {
        if (!before) {
            SessionResult bad;
            bad.outcome = SessionResult::Outcome::LinkFailure;
            bad.message = tr("The machine sent no status report within 2 s; it was not unlocked.");
            done(bad);
            return;
        }
        if (!before->isAlarm()) {
            // The firmware says nothing at all to $X when it is not halted.
            SessionResult result;
            result.status = before;
            result.tool = before->tool;
            result.message = tr("The machine was not halted.");
            done(result);
            return;
        }
        if (!m_restoreOnUnlock && brokenToolTlo && before->tlo
            && std::fabs(*before->tlo - *brokenToolTlo) > 0.0005)
            m_restoreOnUnlock = brokenToolTlo;
        const bool setterHalt = before->haltReason == 4; // the tool setter's: a break test's among them
        run("$X", MachineLink::kDefaultTimeoutMs, done, [this, done, setterHalt](const CommandReply &reply) {
            const bool unlocked = std::any_of(reply.lines.cbegin(), reply.lines.cend(),
                [](const QByteArray &l) { return l.trimmed() == "[Caution: Unlocked]"; });
            if (!unlocked) {
                SessionResult bad;
                bad.outcome = SessionResult::Outcome::MachineError;
                bad.message = tr("The machine did not confirm the unlock; check its state before you go on.");
                done(bad);
                return;
            }
            const auto stored = std::exchange(m_restoreOnUnlock, std::nullopt);
            if (!stored && setterHalt) {
                // Nothing known to set back: what is in force, said as it is.
                status([this, done](const SessionResult &r) {
                    SessionResult result = r;
                    if (r.ok() && r.status && r.status->tlo)
                        result.message
                            = tr("Unlocked. The TLO in force is %1 mm, as the machine left it: after a failed "
                                 "break test, the length the test measured. No stored TLO of T%2 was known "
                                 "here to set back (toffee-cli: --table FILE, or the history that recorded "
                                 "the test). Probe T%2, or set its TLO, before it cuts.")
                                  .arg(millimetres(*r.status->tlo, false))
                                  .arg(m_tool.value_or(-1));
                    done(result);
                });
                return;
            }
            if (!stored) {
                status(done);
                return;
            }
            // A failed break test left the broken length in force: the stored TLO goes back before anything
            // else is sent.
            const double was = *stored;
            setTloTo(was, [this, done, was](const SessionResult &r) {
                SessionResult result = r;
                if (r.ok()) {
                    result.message
                        = tr("Unlocked. T%1's stored TLO, %2 mm, is in force again (the break test "
                             "had left the new length in force).")
                              .arg(m_tool.value_or(-1))
                              .arg(millimetres(was, false));
                } else {
                    m_restoreOnUnlock = was; // tried again at the next unlock
                    result.message = tr("Unlocked, but the stored TLO (%1 mm) could not be set back: %2 The "
                                        "length the break test measured is still in force; do not cut.")
                                         .arg(millimetres(was, false), r.message);
                }
                done(result);
            });
        });
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
