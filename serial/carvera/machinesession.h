// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include <QDeadlineTimer>
#include <QObject>

#include "model/limits.h"
#include "model/recording.h"
#include "model/result.h"
#include "serial/carvera/carveraconsole.h"
#include "serial/carvera/carverareplies.h"
#include "serial/machine/machinecontroller.h"
#include "serial/machine/machinelink.h"

namespace Toffee {

// The Carvera's MachineController. Turns operator intents into command sequences and results. It validates
// before sending (a tolerance under 0.02 never leaves the computer), tracks the active tool from the status
// reports, and reports each operation's outcome as one value. It writes no table: callers record a
// measurement only from a successful result.
class MachineSession final : public MachineController
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(MachineSession)

public:
    // M6: a manual change waits for the operator to take one tool out and put the next in, and a rack change
    // drops, picks and measures; either may take minutes.
    static constexpr int kToolChangeTimeoutMs = 600000;

    explicit MachineSession(MachineLink *link, QObject *parent = nullptr);

    [[nodiscard]] MachineLink *link() const override { return m_link; }
    [[nodiscard]] std::optional<int> activeTool() const override { return m_tool; }
    // What the machine said it runs when it connected (`version`); Unknown before.
    [[nodiscard]] const FirmwareInfo &firmware() const override { return m_firmware; }

    // Opens the link, flushes the controller's buffer, reads the status and, unless halted, the offsets.
    void connectToMachine(Done done) override;
    void status(Done done) override;
    void report(Done done) override;
    void probe(Done done) override;
    // M491.1 compares with the TLO in force: with `storedTlo` (the table's), that is set first when the
    // machine has another one (after M493.2 the firmware still has the previous tool's).
    void breakTest(double tolerance, Done done, std::optional<double> storedTlo = std::nullopt) override;
    void setTlo(double tlo, Done done) override;
    void setTloAboveZ0(double height, Done done) override;
    void selectTool(int tool, Done done) override;
    // A change to or from a tool outside the rack (carveraChangesByItself) waits for the operator's button.
    [[nodiscard]] QString changeByHand(int tool) const override;
    // $X when the machine is halted (it says nothing to $X otherwise), then, after a failed break test, the
    // stored TLO set back before anything can move: the firmware halts with the broken length in force.
    // `brokenToolTlo`: the table's stored TLO for the tool in the spindle when the table marks it broken (a
    // break test in an earlier session): set back too when the machine has another TLO in force.
    void unlock(Done done, std::optional<double> brokenToolTlo = std::nullopt) override;
    // The TLO a failed break test left the machine without (the firmware keeps the new, broken length in
    // force while it halts): set back by unlock().
    [[nodiscard]] std::optional<double> tloToRestore() const override { return m_restoreOnUnlock; }
    // Makes `tool` active with a TLO already known (from the table), without probing.
    void restoreTlo(int tool, double tlo, Done done) override;
    // Ctrl-X: stops whatever the machine is doing. It halts; Unlock afterwards.
    void abort() override;
    [[nodiscard]] ReplyEnd consoleReplyEnd(QByteArrayView line) const override { return replyEndFor(line); }
    [[nodiscard]] std::optional<OffsetReport> offsetsIn(const QList<QByteArray> &reply) const override;
    [[nodiscard]] ConsoleRules consoleRules() const override { return &CarveraConsole::rules; }
    [[nodiscard]] QString consoleExample() const override { return QStringLiteral("M493.4"); }
    [[nodiscard]] std::optional<ProbeResult> probeIn(const QList<QByteArray> &reply) const override
    {
        return lastProbe(reply);
    }
    [[nodiscard]] HaltWords haltWords(int reason) const override
    {
        return { haltReasonName(reason), haltMeaning(reason), haltRecovery(reason) };
    }
    [[nodiscard]] QString setTloCommand(double tlo) const override;
    [[nodiscard]] QString aboveZ0Command(double height) const override;
    [[nodiscard]] QString restoreCommand(int tool, double tlo) const override;

protected:
    // M6 T: the machine changes and measures the tool. With `storedTlo` (a manual change only: the firmware
    // always measures a rack tool), M6 T H takes that TLO instead of probing. The tool already in the spindle
    // is measured where it is (M491): the firmware ignores a change to it.
    void startToolChange(int tool, Done done, std::optional<double> storedTlo) override;
    // Only the machine's button goes on; Ctrl-X (a halt) ends the wait.
    void cancelWaitingChange() override;
    [[nodiscard]] QString cancelledChangeNote() const override;

private:
    void run(const QByteArray &command, int timeoutMs, Done done,
        std::function<void(const CommandReply &)> next, ReplyEnd end = ReplyEnd::Ok);
    // The offsets after an operation: the TLO in force from a fresh status report, the reference (and the
    // current MCS Z, when it agrees) from M493.4.
    void readOffsets(Done done, SessionResult result);
    void takeLongestEdge(int tool, const ProbePlan &plan, const RepeatedMeasurement &measured,
        const QStringList &notes, Done done);
    // M493.3 Z<tlo>, then the offsets: the machine must report that TLO in force.
    void setTloTo(double tlo, Done done);
    // Why a TLO cannot be set now: the spindle is empty.
    [[nodiscard]] std::optional<QString> emptySpindle() const;
    // `done`'s result, or a failure when the status report's TLO is not `tlo`.
    [[nodiscard]] static Done expectingTlo(double tlo, Done done);
    void readVersion(Done done, std::function<void()> next);
    void readStatusAfterConnect(Done done);
    void changeToStoredTlo(int tool, double tlo, Done done);
    // After M6 T-1: the status must show the spindle empty.
    void confirmEmptySpindle(Done done);
    // Why an operation this firmware does not have is refused, or nothing.
    [[nodiscard]] std::optional<QString> unsupported(bool breakTest) const;
    // `zero`: the stored TLO is 0.000, compared as 0.001 (comparableTlo).
    void runBreakTest(double tolerance, Done done, std::optional<double> storedTlo, bool zero = false);
    // Polls until the machine is no longer running a command (a late answer of a timed-out command would
    // otherwise be taken for the next command's), then lets stray output settle. `next` gets false on
    // give-up.
    void awaitIdle(QDeadlineTimer deadline, std::function<void(bool idle, const QString &state)> next);
    // `done`, called once: by the operation, or with a failure when `limitMs` have passed (the link is then
    // closed).
    [[nodiscard]] Done withDeadline(int limitMs, Done done);
    [[nodiscard]] static SessionResult stayedBusy(const QString &state, qint64 waitedMs);
    // `done`, with the recording a successful result carries: the TLO as `source`, or a break test's verdict.
    static QByteArray number(double value);
    // Why a result may be missing from a reply: the machine printed more than a reply keeps.
    [[nodiscard]] static QString floodNote(const CommandReply &reply);
    // M491 and the offsets after it, recorded as nothing (probe() records it).
    void measure(Done done);

    MachineLink *m_link;
    std::optional<int> m_tool;
    FirmwareInfo m_firmware;
    std::optional<double> m_restoreOnUnlock;
};

} // namespace Toffee
