// SPDX-License-Identifier: GPL-3.0-or-later
// The Carvera's break test: the firmware's M491.1 compares the tool's new length with the TLO in force (the
// table's, set first), halting on a broken tool; and the unlock after it, which sets the stored TLO back
// first. A TLO of 0.000 mm (the reference tool's), which it takes for none, goes in as 0.001 mm
// (comparableTlo), so that no tool goes untested for it.
#include <cmath>

#include "model/breaktestrule.h"
#include "model/numberformat.h"
#include "serial/carvera/machinesession.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QString toleranceText(double tolerance)
{
    return formatNumber(tolerance, NumberFormat::upTo(3).inLocale());
}

} // namespace

void MachineSession::breakTest(double tolerance, Done done, std::optional<double> storedTlo)
{
    done = recordingVerdict(std::move(done));
    if (auto why = unsupported(true))
        return refuse(done, *why);
    if (auto r = validateTolerance(tolerance); !r)
        return refuse(done, r.error().message);
    // The community firmware takes T0 and every tool from T9 up for its wireless probe in M491.1: it
    // measures, then halts for a probe that is "dead or not set" (ATCHandler, seen on the firmware).
    if (m_tool && (*m_tool == 0 || *m_tool >= 9))
        return refuse(done,
            tr("The firmware's break test takes T%1 for its wireless probe (T0, and every tool from T9 up): "
               "it "
               "would measure the tool, then halt. Break-test tools T1 to T8, or probe T%1 and compare its "
               "TLO "
               "with the table.")
                .arg(*m_tool));
    // M491.1 takes no X or Y: a face mill touched at its recessed centre would measure another length.
    if (m_tool && probePlan(*m_tool).isOffCentre())
        return refuse(done,
            tr("The firmware's break test (M491.1) touches at the setter's centre only, and T%1 is measured "
               "off-centre: probe it (M491 with its settings) and compare the TLO with the table instead. "
               "Nothing was sent.")
                .arg(*m_tool));
    if (storedTlo) {
        if (auto r = validateOffset(tr("The stored TLO"), *storedTlo); !r)
            return refuse(done, r.error().message);
    }
    // What the firmware compares with is the TLO in force: the table's, when there is one, set first.
    awaitStatus(2000, [this, done, tolerance, storedTlo](std::optional<MachineStatus> status) {
        if (!status || !status->tlo) {
            SessionResult bad;
            bad.outcome = SessionResult::Outcome::LinkFailure;
            bad.message = tr("The machine sent no status report within 2 s; no break test was run.");
            done(bad);
            return;
        }
        const double inForce = storedTlo ? *storedTlo : *status->tlo;
        // The stored TLO goes in first, always: after a tool change the machine has just measured the tool,
        // and a tool broken before the change would be compared with its own broken length. A TLO of 0.000,
        // which the firmware takes for none, goes in as 0.001 (comparableTlo), whether stored or in force.
        if (storedTlo || isZeroTlo(inForce)) {
            const double compared = comparableTlo(inForce);
            run("M493.3 Z" + number(compared), MachineLink::kDefaultTimeoutMs, done,
                [this, done, tolerance, compared, inForce](
                    const CommandReply &) { runBreakTest(tolerance, done, compared, isZeroTlo(inForce)); });
            return;
        }
        runBreakTest(tolerance, done, std::nullopt);
    });
}

void MachineSession::runBreakTest(double tolerance, Done done, std::optional<double> storedTlo, bool zero)
{
    const QByteArray command = "M491.1 H" + number(tolerance);
    m_link->send(
        command, MachineLink::kMotionTimeoutMs,
        [this, done, tolerance, storedTlo, zero](const CommandReply &reply) {
            std::optional<BreakTestReading> reading;
            bool noPrevious = false;
            bool broken = false;
            for (const QByteArray &line : reply.lines) {
                if (auto r = parseBreakTest(line))
                    reading = r;
                noPrevious = noPrevious || line.trimmed() == "No previous TLO included, aborting";
                broken = broken || line.contains("Tool Break Check - check tool for breakage");
            }
            SessionResult result;
            result.tool = m_tool;
            result.tolerance = tolerance;
            result.breakTest = reading;
            // The firmware says what it compared with: it must be the stored TLO that was set.
            const bool comparedWithAnother
                = reading && storedTlo && std::fabs(reading->oldTlo - *storedTlo) > 0.0005;
            if (comparedWithAnother) {
                if (broken)
                    m_restoreOnUnlock = storedTlo;
                result.breakTest.reset();
                result.outcome = SessionResult::Outcome::MachineError;
                result.message
                    = tr("The machine compared T%1 with a TLO of %2 mm, not its stored %3 mm, so its "
                         "verdict does not hold. Check the offsets, then run the break test again.")
                          .arg(m_tool.value_or(-1))
                          .arg(millimetres(reading->oldTlo, false))
                          .arg(millimetres(*storedTlo, false));
                done(result);
                return;
            }
            // Compared as 0.001 for a TLO of 0.000 (comparableTlo): the stored TLO, for people and the
            // history, is the 0.000.
            if (zero && reading && result.breakTest) {
                reading->oldTlo = 0.0;
                result.breakTest->oldTlo = 0.0;
            }
            if (broken && reading) {
                // The firmware halts with the new, broken length in force: Unlock sets the stored one back
                // before anything can move.
                m_restoreOnUnlock = reading->oldTlo;
                result.outcome = SessionResult::Outcome::ToolBroken;
                result.message
                    = tr("Tool T%1 may be broken: it measured a TLO of %2 mm against %3 mm before (a "
                         "difference of %4 mm; the tolerance is %5 mm). The machine has halted with the new "
                         "length, %2 mm, in force. Check the tool and replace it if it is damaged, then "
                         "Unlock: Toffee sets the stored TLO, %3 mm, back first.")
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
                    = tr("The machine had no TLO for this tool to compare with: it measured the tool "
                         "and took the new length without comparing. Check the TLO it reports "
                         "against the table before you cut.");
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
            } else if (const int touches = probePlan(m_tool.value_or(0)).touches; touches > 1) {
                // M491.1 takes no R: said, so that one touch is not taken for every edge's.
                result.message = tr("The firmware's break test touched T%1 once, at one edge, not the %2 "
                                    "touches its settings ask for: probe it to compare every edge.")
                                     .arg(m_tool.value_or(-1))
                                     .arg(touches);
            }
            done(result);
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
                        result.message = tr(
                            "Unlocked. The TLO in force is %1 mm, as the machine left it: after a failed "
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

} // namespace Toffee
