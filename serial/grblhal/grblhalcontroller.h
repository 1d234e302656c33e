// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include "model/toolsetter.h"
#include "serial/grblhal/grblhalreplies.h"
#include "serial/machine/machinecontroller.h"
#include "serial/machine/machinelink.h"

namespace Toffee {

// grblHAL's MachineController (../shared/GRBLHAL.md, docs/GRBLHAL.md). grblHAL has no tool-setter cycle of
// its own that keeps a reference, so Toffee runs the cycle (G38.2 fast, back off, G38.2 slow, on the setter
// the operator set) and keeps the machine's reference: the first tool measured on it, whose contact's machine
// Z every TLO is measured against (TLO = contact − reference). A measured or set TLO is written into
// grblHAL's own table (G10 L1 P<n> Z<tlo>), applied (G43 H<n>) and read back ($#) before it counts; a build
// without a table, or a tool beyond it, gets G43.1 Z<tlo> instead. A break test probes again and compares
// here: a broken tool's stored TLO stays in the table and in the controller, the spindle stopped and lifted.
class GrblHalController final : public MachineController
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(GrblHalController)

public:
    // A reported value agrees with what was written within this (grblHAL prints 0.001 mm).
    static constexpr double kReadBackTolerance = 0.0005;

    explicit GrblHalController(MachineLink *link, QObject *parent = nullptr);

    [[nodiscard]] MachineLink *link() const override { return m_link; }
    [[nodiscard]] std::optional<int> activeTool() const override { return m_tool; }
    [[nodiscard]] const FirmwareInfo &firmware() const override { return m_firmware; }
    [[nodiscard]] const GrblHal::BuildInfo &buildInfo() const { return m_build; }

    // Opens the link, reads the status, $I (which must say grblHAL), the modal state ($G) and the offsets
    // ($#).
    void connectToMachine(Done done) override;
    void status(Done done) override;
    void report(Done done) override;
    void probe(Done done) override;
    void breakTest(double tolerance, Done done, std::optional<double> storedTlo = std::nullopt) override;
    void setTlo(double tlo, Done done) override;
    void setTloAboveZ0(double height, Done done) override;
    // M61 Q<n>: the tool is said to be in the spindle; the offset in force stays what it was.
    void selectTool(int tool, Done done) override;
    [[nodiscard]] QString changeByHand(int tool) const override;
    [[nodiscard]] bool resumesFromHere() const override { return true; }
    void unlock(Done done, std::optional<double> brokenToolTlo = std::nullopt) override;
    // Nothing: a failed break test never changes grblHAL's offsets.
    [[nodiscard]] std::optional<double> tloToRestore() const override { return std::nullopt; }
    void restoreTlo(int tool, double tlo, Done done) override;
    // Ctrl-X, grblHAL's soft reset: it stops at once, and forgets the offset in force.
    void abort() override;
    // grblHAL's jog cancel (0x85): the jog decelerates to a stop and the machine stays ready, no alarm. With
    // no jog under way, as abort().
    void stopJog() override;

    [[nodiscard]] QString setTloCommand(double tlo) const override;
    [[nodiscard]] QString aboveZ0Command(double height) const override;
    [[nodiscard]] QString restoreCommand(int tool, double tlo) const override;
    [[nodiscard]] bool needsToolSetter() const override { return true; }
    [[nodiscard]] QString consoleExample() const override { return QStringLiteral("$#"); }
    void setToolSetter(const ToolSetter &setter) override { m_setter = setter; }
    void jog(const std::array<double, 3> &stepMm, double feed, Done done) override;
    [[nodiscard]] std::optional<ToolSetter> toolSetter() const override { return m_setter; }
    [[nodiscard]] bool keepsReference() const override { return false; }
    void adoptReference(std::optional<double> referenceMz) override { m_reference = referenceMz; }
    [[nodiscard]] std::optional<double> keptReference() const override { return m_reference; }
    void readToolTable(Done done) override;
    [[nodiscard]] std::optional<QList<ControllerTool>> controllerTable() const override
    {
        return m_firmware.hasToolTable() ? std::optional(m_table) : std::nullopt;
    }
    // Refuses the whole list, naming them, when a tool is beyond the controller's table; otherwise writes
    // each (G10 L1 P Z R), reads $# back and fails naming every entry that differs.
    void writeToolTable(const QList<ControllerTool> &tools, Done done) override;

    // How MachineLink reads grblHAL's lines; `controller` (may be null) fills in the offset in force it
    // knows.
    [[nodiscard]] static ReplyGrammar grammar(const GrblHalController *controller);

protected:
    // M6 T<n>: a manual change waits (state Tool) until the operator presses cycle start, or `~` from here;
    // then the tool is measured, or takes `storedTlo` (grblhaltoolchange.cpp). A soft reset ends the wait.
    void startToolChange(int tool, Done done, std::optional<double> storedTlo) override;
    void resumeWaitingChange() override;
    void cancelWaitingChange() override;
    [[nodiscard]] QString cancelledChangeNote() const override;

private:
    // How long a reset may take to be answered with grblHAL's greeting.
    static constexpr int kGreetingWaitMs = 2000;
    // `next` once grblHAL's greeting came after a reset, or the wait for it passed.
    void awaitGreeting(std::function<void()> next);
    using Next = std::function<void(const CommandReply &reply)>;
    // The modal state $G reports, as far as Toffee needs it.
    struct Modal
    {
        QString coordinateSystem = QStringLiteral("G54");
        bool inches = false;
        std::optional<int> tool;
    };

    void run(const QByteArray &command, int timeoutMs, Done done, Next next);
    void readParameters(Done done, std::function<void(const GrblHal::ParameterReport &)> next);
    void readModal(Done done, std::function<void(const Modal &)> next);
    // `next` when grblHAL's G10 and G38.2 take millimetres (G21); else `what` ("writes TLOs") is refused.
    void inMillimetres(Done done, const QString &what, std::function<void()> next);
    // $13: a controller that reports in inches is refused on connecting.
    void readReportUnits(Done done, std::function<void()> next);
    void readOffsetsAfterBuild(Done done, const MachineStatus &status);
    // G10 L1 for each entry, then $# read back (writeToolTable, once every entry is checked).
    void writeEntries(const QList<ControllerTool> &tools, Done done);
    // $I (which must say grblHAL), $G and $#, after the status read on connecting.
    void readBuild(Done done, const MachineStatus &status);
    // The setter's cycle with `tool` in the spindle, as its probe plan says: `next` gets each slow touch's
    // machine Z.
    void measure(int tool, Done done, std::function<void(QList<double> contactsMz)> next);
    void touchEach(const SetterCycle &cycle, double wco, QList<double> contacts, Done done,
        std::function<void(QList<double>)> next);
    [[nodiscard]] static std::optional<double> contactIn(
        const CommandReply &reply, const ToolSetter &setter, const Done &done);
    // Writes `tlo` for `tool` (table entry and G43 H, or G43.1) and reads it back: `next` once it holds.
    void writeOffset(int tool, double tlo, Done done, std::function<void(const QString &note)> next);
    // The tool in the spindle, or a refusal for T0.
    [[nodiscard]] std::optional<int> spindleTool(const Done &done, const QString &what) const;
    [[nodiscard]] SessionResult tloResult(int tool, double tlo, std::optional<double> contactMz) const;
    [[nodiscard]] bool fitsTable(int tool) const;
    static QByteArray number(double value);
    // A length for people ("15.300"), and at grblHAL's 0.001 mm.
    [[nodiscard]] static QString mm(double v);
    [[nodiscard]] static double atResolution(double v);
    void rememberParameters(const GrblHal::ParameterReport &report);

    MachineLink *m_link;
    std::optional<int> m_tool;
    bool m_jogging = false; // a jog is under way: stopJog cancels it
    bool m_jogCancelled = false;
    FirmwareInfo m_firmware;
    GrblHal::BuildInfo m_build;
    std::optional<ToolSetter> m_setter;
    std::optional<double> m_reference;
    std::optional<double> m_tloInForce;
    QList<ControllerTool> m_table;
};

} // namespace Toffee
