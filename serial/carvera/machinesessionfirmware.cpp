// SPDX-License-Identifier: GPL-3.0-or-later
// Which firmware the machine runs, and what follows from it: the stock firmware has neither a break test nor
// a manual offset, and no offset report (docs/CARVERA.md).
#include "serial/carvera/machinesession.h"

using namespace Qt::StringLiterals;

namespace Toffee {

void MachineSession::readVersion(Done done, std::function<void()> next)
{
    // A shell command: the firmware prints "version = …" and no "ok".
    m_link->send(
        "version", MachineLink::kDefaultTimeoutMs,
        [this, done, next](const CommandReply &reply) {
            if (reply.status == CommandReply::Status::Timeout
                || reply.status == CommandReply::Status::LinkLost) {
                done(failure(reply));
                return;
            }
            // Every Carvera firmware answers its shell's `version`; grblHAL refuses it as G-code.
            if (reply.status == CommandReply::Status::Refused) {
                SessionResult result;
                result.outcome = SessionResult::Outcome::MachineError;
                result.message = tr("%1, which no Carvera does: this is another controller (grblHAL refuses it "
                                    "so). Nothing of the Carvera's was sent. Choose grblHAL, or Automatic, and "
                                    "connect again.")
                                     .arg(reply.message);
                done(result);
                return;
            }
            // A firmware that refuses "version" (or garbles its answer) stays Unknown: offered only what both
            // firmwares do.
            m_firmware = FirmwareInfo {};
            for (const QByteArray &line : reply.lines) {
                if (auto info = parseVersion(line)) {
                    m_firmware = *info;
                    break;
                }
            }
            next();
        },
        ReplyEnd::Line);
}

void MachineSession::confirmEmptySpindle(Done done)
{
    awaitStatus(2000, [this, done](std::optional<MachineStatus> status) {
        SessionResult result;
        result.status = status;
        result.tool = Limits::kEmptySpindle;
        // The stock firmware leaves T: out for an empty spindle; the community firmware says T:-1.
        const bool empty = status
            && (status->tool ? *status->tool == Limits::kEmptySpindle
                             : m_firmware.kind == FirmwareInfo::Kind::Stock);
        if (!empty) {
            result.outcome
                = status ? SessionResult::Outcome::MachineError : SessionResult::Outcome::LinkFailure;
            result.message = status && status->tool
                ? tr(
                    "The machine was told to put its tool back, but it reports T%1 in the spindle. Check the "
                    "spindle and the rack before you go on.")
                      .arg(*status->tool)
                : tr("The machine was told to put its tool back but did not report an empty spindle. Check "
                     "the "
                     "spindle and the rack before you go on.");
        }
        done(result);
    });
}

std::optional<QString> MachineSession::unsupported(bool breakTest) const
{
    using Kind = FirmwareInfo::Kind;
    if (breakTest && m_firmware.kind == Kind::Stock)
        return tr("The machine runs %1: its M491.1 only measures the tool again and takes the new length "
                  "without comparing, so a broken tool would pass. Probe the tool and compare its TLO with "
                  "the table, or install the community firmware for break tests.")
            .arg(m_firmware.description());
    if (breakTest && m_firmware.kind == Kind::Unknown)
        return tr("The machine did not say which firmware it runs (%1), so Toffee cannot tell whether its "
                  "M491.1 compares the tool or only measures it again. No break test was run; probe the "
                  "tool and compare its TLO with the table.")
            .arg(m_firmware.description());
    if (!breakTest && !m_firmware.hasManualOffset())
        return tr("The machine runs %1, which ignores M493.3 without a word: a TLO set by hand would not be "
                  "used. Probe the tool instead, or change to it with its TLO (a manual change).")
            .arg(m_firmware.description());
    return std::nullopt;
}

} // namespace Toffee
