// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <functional>
#include <optional>

#include <QElapsedTimer>
#include <QList>
#include <QObject>

#include "model/limits.h"
#include "model/probing.h"
#include "model/recording.h"
#include "model/result.h"
#include "model/toolsetter.h"
#include "serial/machine/consolecheck.h"
#include "serial/machine/machinereplies.h"

class QTimer;

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

// A change under way (MachineController::changeTool): whether the machine waits for the person, and why the
// wait was ended.
struct PendingToolChange
{
    int tool = 0;
    bool waiting = false;
    std::optional<QString> ended;
    QMetaObject::Connection statusWatch;
    QTimer *limit = nullptr;
    QElapsedTimer waited;
};

// What the window and the CLI ask of a machine, whatever controller it runs: connect, read the status and the
// offsets, select and change a tool, probe it on the setter, break-test it, set or restore its TLO, unlock
// and stop. Each operation validates before it sends, runs to one result, and records nothing itself: the
// caller records a whole success (SessionResult::recording). Each controller implements it in its own words
// (MachineSession: the Carvera, over M491, M493 and M6); what one cannot do, it refuses by name, and
// firmware() says so beforehand, so that no panel or command needs to ask which controller it has.
// A halt reason in words: its name ("PROBE_FAIL (3)"), what it means, and what clears it.
struct HaltWords
{
    QString name;
    QString meaning;
    QString recovery;
};

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
    // Changes to `tool`; with `storedTlo`, takes it instead of measuring where the controller can. A change
    // that waits for a person at the machine (a manual change: changeByHand) is refused before
    // anything is sent when nobody is there (setOperatorAbsent); otherwise the wait is said
    // (waitingForOperator) and lasts at most operatorWaitMs(), then the change is ended on the machine.
    // Every change of every controller passes here: this is where the operator's presence is enforced.
    void changeTool(int tool, Done done, std::optional<double> storedTlo = std::nullopt);
    // What a person must do by hand in a change to `tool` from the tool in the spindle ("T8 is taken out by
    // hand"); empty when the machine changes by itself.
    [[nodiscard]] virtual QString changeByHand(int tool) const = 0;
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
    // How each tool is probed (the table's settings, ToolTable::probePlan, or a command's own): every probe
    // and break test of a tool, whichever operation starts it (a change measures too), asks here. Plain (one
    // touch at the centre) when nobody said.
    using ProbePlans = std::function<ProbePlan(int tool)>;
    void setProbePlans(ProbePlans plans) { m_probePlans = std::move(plans); }
    [[nodiscard]] ProbePlan probePlan(int tool) const
    {
        return m_probePlans ? m_probePlans(tool) : ProbePlan {};
    }
    // What a spread of `touches` wider than the plan's limit says ("T3's edges differ by 0.060 mm: runout or
    // a chipped edge…"); empty within it, or without a limit.
    [[nodiscard]] static QString spreadFinding(int tool, const QList<double> &touches, const ProbePlan &plan);
    // A probe of Toffee's own setter cycle (grblHAL, LinuxCNC) for `tool`, its TLO written: `result` takes
    // its touches, and its words: a spread beyond the limit first, the reference it made (`madeReference`),
    // the controller's own `note`, and that `controller` cannot turn its spindle (ownsetter.cpp).
    void describeOwnProbe(SessionResult &result, int tool, std::optional<double> madeReference,
        const QString &note, const QList<double> &touches, const ToolSetter &setter,
        const QString &controller) const;
    virtual void setToolSetter(const ToolSetter &setter) { Q_UNUSED(setter) }
    [[nodiscard]] virtual std::optional<ToolSetter> toolSetter() const { return std::nullopt; }
    static constexpr double kMaxJogStepMm = 50.0;
    // A line the operator typed in the console: how this controller's reply to it ends, and the offsets the
    // reply reports (the Carvera's M493.3 and M493.4 print them), if any. Every line is answered with "ok" or
    // "error:" unless the controller says otherwise.
    [[nodiscard]] virtual ReplyEnd consoleReplyEnd(QByteArrayView line) const
    {
        Q_UNUSED(line)
        return ReplyEnd::Ok;
    }
    [[nodiscard]] virtual std::optional<OffsetReport> offsetsIn(const QList<QByteArray> &reply) const
    {
        Q_UNUSED(reply)
        return std::nullopt;
    }
    // A probe's result among the lines of a reply to a typed line (the Carvera's M491 prints it), if any.
    [[nodiscard]] virtual std::optional<ProbeResult> probeIn(const QList<QByteArray> &reply) const
    {
        Q_UNUSED(reply)
        return std::nullopt;
    }
    // A halt reason a status report gave (the Carvera's 1-41), in this controller's words.
    [[nodiscard]] virtual HaltWords haltWords(int reason) const { return neutralHaltWords(reason); }
    [[nodiscard]] static HaltWords neutralHaltWords(int reason);
    // A line typed in the console as this controller takes it (linuxcncrsh takes G-code only as "set mdi …");
    // as typed by default.
    [[nodiscard]] virtual QByteArray consoleCommand(const QByteArray &typed) const { return typed; }
    // A line worth typing on this controller, for the console's hint ("M493.4", "$#").
    [[nodiscard]] virtual QString consoleExample() const { return QStringLiteral("G4 P0"); }
    // This family's own rules for a typed line, before every controller's (ConsoleCheck); none by default.
    [[nodiscard]] virtual ConsoleRules consoleRules() const { return nullptr; }
    // Moves the machine by `stepMm` (X, Y, Z, relative, at most kMaxJogStepMm each) at `feed` mm/min, to
    // find where the setter is; done once it has stopped, with its status. Only a controller whose setter is
    // Toffee's jogs; the others refuse.
    virtual void jog(const std::array<double, 3> &stepMm, double feed, Done done);
    // Stops a jog under way where the machine stands. By default as abort() does (a halt, then Unlock); a
    // controller with a jog cancel of its own stops it without a halt.
    virtual void stopJog() { abort(); }
    [[nodiscard]] virtual bool keepsReference() const { return true; }
    virtual void adoptReference(std::optional<double> referenceMz) { Q_UNUSED(referenceMz) }
    // The reference Toffee keeps for such a controller, once measured or adopted; none for one that keeps its
    // own.
    [[nodiscard]] virtual std::optional<double> keptReference() const { return std::nullopt; }
    // Who is at the machine. The window's operator is; toffee-cli's is only when its input is a terminal.
    // `why` (empty: someone is there) says why nobody is counted as there, for the refusal.
    void setOperatorAbsent(const QString &why) { m_operatorAbsent = why; }
    [[nodiscard]] const QString &operatorAbsent() const { return m_operatorAbsent; }
    // How long a change waits for the person: the link's time limit when one is set (toffee-cli
    // --timeout), else kOperatorWaitMs.
    static constexpr int kOperatorWaitMs = 600000;
    [[nodiscard]] int operatorWaitMs() const;
    // While a change waits (waitingForOperator): the person put the tool in and says so here, as the
    // machine's cycle start does (grblHAL); where only the machine's own button goes on (the Carvera),
    // resumesFromHere() is false and this does nothing.
    [[nodiscard]] virtual bool resumesFromHere() const { return false; }
    void resumeToolChange();
    // ... or the wait ends (the person said so, closed the terminal, or the limit passed): the machine's
    // change is stopped, and the change ends as a failure saying `why`, nothing measured or recorded.
    void endToolChange(const QString &why);
    [[nodiscard]] bool isWaitingForOperator() const { return m_change && m_change->waiting; }
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
    // A manual tool change waits for the operator to put `tool` in (state Tool), for at most `limitMs`.
    void waitingForOperator(int tool, int limitMs);
    // The change ended, whichever way (done, failed, ended while it waited).
    void toolChangeFinished();

public:
    [[nodiscard]] static Result<void> validateTolerance(double tolerance);
    [[nodiscard]] static Result<void> validateOffset(const QString &what, double value);
    [[nodiscard]] static Result<void> validateToolNumber(int tool);

protected:
    // The family's change, called by changeTool() once the operator's presence is settled.
    virtual void startToolChange(int tool, Done done, std::optional<double> storedTlo) = 0;
    // The family's words for "the tool is in, go on" and for stopping a change that waits.
    virtual void resumeWaitingChange() { }
    virtual void cancelWaitingChange() = 0;
    // What stopping a waiting change leaves on the machine, for the operator ("grblHAL was reset: …").
    [[nodiscard]] virtual QString cancelledChangeNote() const = 0;
    // Whether the change under way was ended (endToolChange): its polling stops there.
    [[nodiscard]] bool toolChangeEnded() const { return m_change && m_change->ended; }

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
    // A break test Toffee compares itself (grblHAL, LinuxCNC): `measured` against `stored` for `tool` at
    // `tolerance`, broken when further apart, the stored TLO said to be kept in the table and in `keptIn`.
    // With several `touches` (measured is the highest's), edges further apart than the tool's spread limit
    // are broken too: a chipped edge.
    [[nodiscard]] SessionResult breakVerdict(int tool, double stored, double measured, double tolerance,
        const QString &keptIn, const QList<double> &touches = {}) const;
    // What such a break test compares with, or `done` refused: the machine's reference must be kept
    // (`hasReference`), and a stored TLO found: the table's (`storedTlo`), else the controller's own entry
    // for `tool` in `table` unless it is empty (0.000, as pull-offsets reads it); never the offset in force,
    // which after M61 is another tool's. `controller` names it ("grblHAL").
    [[nodiscard]] static std::optional<double> breakBaseline(const Done &done, int tool, bool hasReference,
        std::optional<double> storedTlo, const QList<ControllerTool> &table, const QString &controller);
    // Writes `tools` one after another (`writeOne` calls its `next` once one is written), then `verify` ends
    // it; a failure half-way says which were written before it and which were not.
    using WriteOne = std::function<void(const ControllerTool &tool, Done done, std::function<void()> next)>;
    static void writeEach(const QList<ControllerTool> &tools, WriteOne writeOne,
        std::function<void(Done)> verify, Done finished);
    // `done`, with the recording a successful result carries: the TLO as `kind`, or a break test's verdict.
    [[nodiscard]] static Done recording(Done done, RecordingKind kind);
    [[nodiscard]] static Done recordingVerdict(Done done);

private:
    void operatorWaitBegan();
    [[nodiscard]] static QString waitedTooLong(int tool, int limitMs);
    [[nodiscard]] Done finishingChange(Done done);

    QString m_operatorAbsent;
    std::optional<PendingToolChange> m_change;
    ProbePlans m_probePlans;
};

} // namespace Toffee
