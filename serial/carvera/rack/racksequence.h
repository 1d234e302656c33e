// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QHash>
#include <QList>
#include <QObject>

#include "model/limits.h"
#include "serial/carvera/machinesession.h"

namespace Toffee {

class MachineConnection;
class ToolTable;

// One rack tool in a Measure Rack or a Check Rack, and how it went.
struct RackStep
{
    enum class State {
        Waiting,
        Running,
        Measured, // Measure: its TLO is stored
        Passed, // Check: within the tolerance of its stored TLO
        Broken, // Check: outside it; the machine halted
        Failed, // the machine or the link failed on this tool: nothing was recorded for it
        NotRun, // the sequence stopped before this tool
        Skipped, // Check: the firmware's break test cannot test it (breakTestExclusion); `message` says why
    };
    int tool = 0;
    State state = State::Waiting;
    std::optional<double> storedTlo; // Check: what it is compared with
    std::optional<double> storedReferenceMz; // Check: what that TLO was measured against
    std::optional<double> measuredTlo; // Measure: the new TLO; Check: the break test's
    QString message; // why it failed or broke
};

// Measures every rack tool once (Measure Rack: M6 T picks each and the machine calibrates it), or checks
// every one for breakage (Check Rack: M6 T, M493.3 Z with its stored TLO, M491.1 H, so that the firmware
// itself compares and halts on a broken tool), then puts the last one back (M6 T-1). One tool at a time, as
// one machine operation that no panel can interleave. It stops at the first failure or broken tool; Cancel
// lets the current tool finish, then stops. Writes nothing itself: each result worth keeping comes out of
// recorded(), and the caller stores it (table and history), so that only what was measured is kept.
class RackSequence final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(RackSequence)

public:
    enum class Mode { Measure, Check };
    struct Plan
    {
        Mode mode = Mode::Measure;
        QList<RackStep> steps; // the rack's tools, in order
        double tolerance = Limits::kDefaultBreakTolerance;
    };

    // A plan for `rack`'s tools with what `table` holds of each (Check compares with those TLOs).
    [[nodiscard]] static Plan plan(
        Mode mode, const QList<int> &rack, const ToolTable &table, double tolerance);
    // Why `plan` cannot run on a machine with this firmware, or nothing: checked before anything moves.
    [[nodiscard]] static std::optional<QString> refusal(const Plan &plan, const FirmwareInfo &firmware);

    // "T1, T2, T5", for messages.
    [[nodiscard]] static QString toolNames(const QList<int> &tools);

    RackSequence(MachineConnection *connection, Plan plan, QObject *parent = nullptr);

    // False (with the reason in outcome()) when it cannot start: refused, or the machine is busy or halted.
    bool start();
    // The current tool finishes (its change, its measurement or test); then the sequence stops.
    void cancel();
    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] bool isCancelled() const { return m_cancelled; }
    [[nodiscard]] const QList<RackStep> &steps() const { return m_plan.steps; }
    [[nodiscard]] Mode mode() const { return m_plan.mode; }
    // The whole sequence's result once finished: Success, or the first failure (ToolBroken naming the tool).
    [[nodiscard]] const SessionResult &outcome() const { return m_outcome; }

Q_SIGNALS:
    void stepChanged(int index);
    // A measurement or a break-test verdict for the caller to store (SessionResult::recording).
    void recorded(const Toffee::SessionResult &result);
    void finished(const Toffee::SessionResult &outcome);

private:
    template<typename Next> [[nodiscard]] MachineController::Done step(Next next);
    void next();
    void measure(int index);
    void check(int index);
    void testInSpindle(int index);
    void putBack();
    // The step ends with `state`; a failure ends the sequence with `result`.
    void settle(int index, RackStep::State state, const SessionResult &result);
    void finish(const SessionResult &result);
    [[nodiscard]] QString progressText(int index) const;

    MachineConnection *m_connection;
    Plan m_plan;
    int m_current = -1;
    bool m_running = false;
    bool m_cancelled = false;
    SessionResult m_outcome;
};

} // namespace Toffee
