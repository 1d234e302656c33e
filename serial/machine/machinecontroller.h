// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include <QObject>

#include "model/limits.h"
#include "model/recording.h"
#include "model/result.h"
#include "serial/machine/machinereplies.h"

namespace Toffee {

class MachineLink;

// One operation's outcome, for an operator: success with the new values, or a failure with what to do.
struct SessionResult
{
    enum class Outcome {
        Success,
        Refused, // the input was refused before anything was sent
        ToolBroken, // the break test found the tool shorter or longer than its TLO
        MachineError, // the machine refused, halted, or sent what could not be read
        LinkFailure, // no answer in time, or the connection was lost
    };
    Outcome outcome = Outcome::Success;
    QString message;
    std::optional<int> tool;
    std::optional<TloReading> tlo;
    std::optional<BreakTestReading> breakTest;
    double tolerance = 0.0;
    std::optional<MachineStatus> status;
    // What the table should record of this result (a TLO with its source, or a break test's verdict), when
    // the operation measured or set something for a tool in the spindle.
    std::optional<Recording> recording;

    [[nodiscard]] bool ok() const { return outcome == Outcome::Success; }
};

// What the window and the CLI ask of a machine, whatever controller it runs: connect, read the status and the
// offsets, select and change a tool, probe it on the setter, break-test it, set or restore its TLO, unlock
// and stop. Each operation validates before it sends, runs to one result, and records nothing itself: the
// caller records a whole success (SessionResult::recording). Each controller implements it in its own words
// (MachineSession: the Carvera, over M491, M493 and M6); what one cannot do, it refuses by name, and
// firmware() says so beforehand, so that no panel or command needs to ask which controller it has.
class MachineController : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(MachineController)

public:
    using Done = std::function<void(const SessionResult &result)>;
    // The break test's limits (the Carvera's firmware halts below 0.02 mm; grblHAL is held to the same), and
    // the largest offset any machine is given.
    static constexpr double kMinTolerance = Limits::kMinBreakTolerance;
    static constexpr double kDefaultTolerance = Limits::kDefaultBreakTolerance;
    static constexpr double kMaxOffset = Limits::kMaxMachineOffsetMm;

    using QObject::QObject;
    ~MachineController() override;

    [[nodiscard]] virtual MachineLink *link() const = 0;
    // The tool the machine reports in the spindle (Limits::kEmptySpindle: none), if it has said.
    [[nodiscard]] virtual std::optional<int> activeTool() const = 0;
    // What the machine runs and what it can do, as it said on connecting; Unknown before.
    [[nodiscard]] virtual const FirmwareInfo &firmware() const = 0;

    // Opens the link and reads what the machine is, its status and, unless halted, its offsets.
    virtual void connectToMachine(Done done) = 0;
    virtual void status(Done done) = 0;
    virtual void report(Done done) = 0;
    // Measures the tool in the spindle on the tool setter: its TLO against the machine's reference.
    virtual void probe(Done done) = 0;
    // Measures it again and compares with `storedTlo` (the table's; else the TLO in force) at `tolerance`.
    virtual void breakTest(double tolerance, Done done, std::optional<double> storedTlo = std::nullopt) = 0;
    virtual void setTlo(double tlo, Done done) = 0;
    // The TLO that puts the tool's tip `height` above the work's Z0.
    virtual void setTloAboveZ0(double height, Done done) = 0;
    // Says which tool is in the spindle, without a change.
    virtual void selectTool(int tool, Done done) = 0;
    // Changes to `tool` (a manual change waits for the operator); with `storedTlo`, takes it instead of
    // measuring where the controller can.
    virtual void changeTool(int tool, Done done, std::optional<double> storedTlo = std::nullopt) = 0;
    // Clears a halt; `brokenToolTlo`: the stored TLO of a tool the table marks broken, set back first.
    virtual void unlock(Done done, std::optional<double> brokenToolTlo = std::nullopt) = 0;
    // The TLO a failed break test left the machine without, which unlock() sets back; none when nothing is
    // due.
    [[nodiscard]] virtual std::optional<double> tloToRestore() const = 0;
    // Makes `tool` active with a TLO already known (from the table), without measuring.
    virtual void restoreTlo(int tool, double tlo, Done done) = 0;
    // Stops whatever the machine is doing at once; it halts, and Unlock follows.
    virtual void abort() = 0;

    [[nodiscard]] static Result<void> validateTolerance(double tolerance);
    [[nodiscard]] static Result<void> validateOffset(const QString &what, double value);
    [[nodiscard]] static Result<void> validateToolNumber(int tool);
};

} // namespace Toffee
