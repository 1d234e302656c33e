// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include <QList>
#include <QObject>

#include "model/limits.h"
#include "model/recording.h"
#include "model/result.h"
#include "model/toolsetter.h"
#include "serial/machine/machinereplies.h"

namespace Toffee {

class MachineLink;
struct CommandReply;

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
    // The controller's own tool table, as read back (a controller that keeps one: grblHAL).
    std::optional<QList<ControllerTool>> controllerTools;
    // What the table should record of this result (a TLO with its source, or a break test's verdict), when
    // the operation measured or set something for a tool in the spindle.
    std::optional<Recording> recording;

    [[nodiscard]] bool ok() const { return outcome == Outcome::Success; }
    [[nodiscard]] static SessionResult failed(Outcome outcome, const QString &message)
    {
        SessionResult result;
        result.outcome = outcome;
        result.message = message;
        return result;
    }
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

    // What only some controllers need or have; the others' defaults say so. A controller whose probing cycle
    // is Toffee's (grblHAL) must be told where the setter is; one whose firmware keeps no reference tool
    // (grblHAL) is given the reference Toffee kept for the machine (the first tool measured on it), before
    // connecting: its TLOs are measured against it, and a probe without one makes the tool the reference.
    [[nodiscard]] virtual bool needsToolSetter() const { return false; }
    virtual void setToolSetter(const ToolSetter &setter) { Q_UNUSED(setter) }
    [[nodiscard]] virtual std::optional<ToolSetter> toolSetter() const { return std::nullopt; }
    [[nodiscard]] virtual bool keepsReference() const { return true; }
    virtual void adoptReference(std::optional<double> referenceMz) { Q_UNUSED(referenceMz) }
    // A manual tool change waiting for the operator (state Tool): the tool is in, go on (grblHAL's cycle
    // start). Nothing where the firmware asks on its own.
    virtual void resumeToolChange() { }
    // What setTlo(), setTloAboveZ0() and restoreTlo() send, for the operator to read before they are sent
    // ("M493.3 Z-12.5"; "G10 L1 P3 Z-12.5, G43 H3").
    [[nodiscard]] virtual QString setTloCommand(double tlo) const = 0;
    [[nodiscard]] virtual QString aboveZ0Command(double height) const = 0;
    [[nodiscard]] virtual QString restoreCommand(int tool, double tlo) const = 0;
    // The controller's own tool table (firmware().hasToolTable()): read it, or write `tools` into it and
    // read it back. A controller without one refuses by name.
    virtual void readToolTable(Done done);
    // The controller's own table as last read (on connecting, after a probe, a push), without asking it.
    [[nodiscard]] virtual std::optional<QList<ControllerTool>> controllerTable() const
    {
        return std::nullopt;
    }
    virtual void writeToolTable(const QList<ControllerTool> &tools, Done done);

Q_SIGNALS:
    // A manual tool change waits for the operator to put `tool` in (grblHAL's state Tool): resumeToolChange()
    // goes on, as the machine's cycle start does.
    void waitingForToolChange(int tool);

public:
    [[nodiscard]] static Result<void> validateTolerance(double tolerance);
    [[nodiscard]] static Result<void> validateOffset(const QString &what, double value);
    [[nodiscard]] static Result<void> validateToolNumber(int tool);

protected:
    // Opens the link (unless open) and calls `afterOpen`, or `done` with why it did not open within the
    // transport's own limit.
    void openLink(Done done, std::function<void()> afterOpen);
    // The next status report, or nothing after `timeoutMs`.
    void awaitStatus(int timeoutMs, std::function<void(std::optional<MachineStatus>)> next);
    // `done` with a Refused result, from the event loop (never inside the caller's call).
    static void refuse(Done done, const QString &message);
    // A failed command as an operation's result: the link's failures as LinkFailure, the machine's as
    // MachineError.
    static SessionResult failure(const CommandReply &reply);
    // `done`, with the recording a successful result carries: the TLO as `kind`, or a break test's verdict.
    [[nodiscard]] static Done recording(Done done, RecordingKind kind);
    [[nodiscard]] static Done recordingVerdict(Done done);
};

} // namespace Toffee
