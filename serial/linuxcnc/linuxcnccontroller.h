// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <optional>

#include <QTimer>

#include "model/toolsetter.h"
#include "serial/linuxcnc/linuxcncreplies.h"
#include "serial/machine/machinecontroller.h"
#include "serial/machine/machinelink.h"

namespace Toffee {

// A running LinuxCNC's MachineController, over linuxcncrsh, its remote console (docs/LINUXCNC.md). Every line
// is a `get` (one answer line) or a `set` (SET … ACK or NAK); motion goes through `set mdi` with `set_wait
// done`, so its ACK comes once the line has run, and a NAK is explained by `get error`. LinuxCNC keeps no
// reference tool for a setter, so, as on grblHAL, Toffee runs the cycle (G38.2 fast, back off, G38.2 slow,
// incremental so that no work offset matters), reads the contact's machine Z (#5063 + #<_abs_z> − #<_z>,
// printed with (DEBUG,…)) and keeps the machine's reference: the first tool measured on it. A TLO is written
// into LinuxCNC's table (G10 L1, which rewrites tool.tbl before its ACK), applied (G43 H) and read back
// before it counts. Before anything moves or is written, LinuxCNC must be out of estop, on, homed, idle, in
// MDI, and Toffee must still hold linuxcncrsh's enable: otherwise it is refused, saying what to do. Toffee
// never releases an estop, switches a machine on or changes LinuxCNC's mode by itself.
class LinuxCncController final : public MachineController
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LinuxCncController)

public:
    // A value read back agrees with what was written within this (LinuxCNC prints 6 decimals; Toffee writes
    // 3).
    static constexpr double kReadBackTolerance = 0.0005;
    // How many (DEBUG,…) lines of others are read past before Toffee's own is given up.
    static constexpr int kMaxDisplayReads = 8;

    explicit LinuxCncController(MachineLink *link, QObject *parent = nullptr);

    [[nodiscard]] MachineLink *link() const override { return m_link; }
    [[nodiscard]] std::optional<int> activeTool() const override { return m_tool; }
    [[nodiscard]] const FirmwareInfo &firmware() const override { return m_firmware; }

    // linuxcncrsh's enable password (a machine setting; LinuxCNC's own default when not set). Never printed.
    void setEnablePassword(const QByteArray &password) { m_enablePassword = password; }
    // The INI of this LinuxCNC on this computer, whose [EMCIO] TOOL_TABLE is LinuxCNC's table: linuxcncrsh
    // has no command that reads the table. Without it, the INI LinuxCNC names (get inifile) is read when
    // LinuxCNC runs on this computer (127.0.0.1).
    void setIniFile(const QString &path) { m_iniPath = path; }
    [[nodiscard]] QString toolTableFile() const { return m_tablePath; }

    // hello, verbose on, echo off, enable, set_wait done; then its state, units and tool, and its table
    // when its file is at hand. Connecting moves nothing and works in estop (the operations then refuse).
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
    // Nothing to unlock: LinuxCNC has no alarm lock; its state is read again.
    void unlock(Done done, std::optional<double> brokenToolTlo = std::nullopt) override;
    [[nodiscard]] std::optional<double> tloToRestore() const override { return std::nullopt; }
    void restoreTlo(int tool, double tlo, Done done) override;
    // `set abort`: on this connection when it is free, else on a second one (this one waits for its MDI
    // line).
    void abort() override;

    [[nodiscard]] QString setTloCommand(double tlo) const override;
    [[nodiscard]] QString aboveZ0Command(double height) const override;
    [[nodiscard]] QString restoreCommand(int tool, double tlo) const override;
    [[nodiscard]] bool needsToolSetter() const override { return true; }
    // A typed line is G-code for LinuxCNC's MDI: linuxcncrsh's own commands (set estop, shutdown, …) are not
    // the console's to send.
    [[nodiscard]] QByteArray consoleCommand(const QByteArray &typed) const override
    {
        return "set mdi " + typed;
    }
    [[nodiscard]] QString consoleExample() const override { return QStringLiteral("G43 H2"); }
    void setToolSetter(const ToolSetter &setter) override { m_setter = setter; }
    [[nodiscard]] std::optional<ToolSetter> toolSetter() const override { return m_setter; }
    [[nodiscard]] bool keepsReference() const override { return false; }
    void adoptReference(std::optional<double> referenceMz) override { m_reference = referenceMz; }
    [[nodiscard]] std::optional<double> keptReference() const override { return m_reference; }
    // LinuxCNC's table, read from its file (refused by name without one).
    void readToolTable(Done done) override;
    [[nodiscard]] std::optional<QList<ControllerTool>> controllerTable() const override { return m_table; }
    // G10 L1 P<n> Z<tlo> for each, once every tool is known to be in LinuxCNC's table (all or nothing), then
    // the file read back.
    void writeToolTable(const QList<ControllerTool> &tools, Done done) override;

    [[nodiscard]] static ReplyGrammar grammar();
    // How often the state is asked for while nothing else is sent.
    static constexpr int kPollIntervalMs = 500;

protected:
    // M6 T<n>: LinuxCNC runs its own change (with hal_manualtoolchange it asks at its own screen, and the
    // line's ACK waits for the person); then the tool is measured, or takes `storedTlo`.
    void startToolChange(int tool, Done done, std::optional<double> storedTlo) override;
    void cancelWaitingChange() override { abort(); }
    [[nodiscard]] QString cancelledChangeNote() const override;

private:
    using Next = std::function<void(const CommandReply &reply)>;
    using Fields = std::map<QByteArray, double>;

    // `set <what>`: `next` on ACK; a NAK fails with `refusal` (LinuxCNC's own words are read for MDI).
    void set(const QByteArray &what, int timeoutMs, Done done, Next next);
    // `set mdi <line>`, which returns once the line has run: a NAK fails with `get error`'s words.
    void mdi(const QByteArray &line, int timeoutMs, Done done, Next next);
    void mdiChain(const QList<QByteArray> &lines, int timeoutMs, Done done, std::function<void()> next);
    // `get <what>`: `next` with the answer's value (after its keyword); a refusal is asked again once
    // (`again`), kGetRetryMs later.
    static constexpr int kGetRetryMs = 200;
    void get(const QByteArray &what, const QByteArray &keyword, Done done,
        std::function<void(const QByteArray &value)> next, bool again = false);
    // What LinuxCNC's error queue holds now, one message (empty when it says OK).
    void lastError(std::function<void(const QString &error)> next);
    // Prints `fields` with (DEBUG,<name>-<n> …) and reads them back from the operator display.
    void printFields(const QByteArray &name, const QByteArray &fields, Done done,
        std::function<void(const Fields &)> next);
    void readState(Done done, std::function<void(const LinuxCnc::State &)> next);
    // The state, refused (what to do) unless LinuxCNC can take `what` now: out of estop, on, homed, idle, in
    // MDI, enabled here, in millimetres.
    void ready(Done done, const QString &what, std::function<void(const LinuxCnc::State &)> next);
    [[nodiscard]] std::optional<QString> notReady(const LinuxCnc::State &state, const QString &what) const;
    // The TLO in force and the spindle's tool: #<_abs_z> − #<_z> less the work offsets.
    void readOffsetInForce(Done done, std::function<void()> next);
    // The table file, when known, read into m_table; `next` with why it could not be (empty: read).
    void readTableFile(std::function<void(const QString &why)> next);
    void locateTable(Done done, std::function<void()> next);
    void afterHello(Done done);
    // The setter's cycle with the tool in the spindle: `next` gets the slow touch's machine Z.
    void measure(int tool, Done done, std::function<void(QList<double> contactsMz)> next);
    void touchEach(const SetterCycle &cycle, double from, QList<double> contacts, Done done,
        std::function<void(QList<double>)> next);
    void probeReady(Done done);
    void breakTestReady(double tolerance, Done done, std::optional<double> storedTlo);
    void touch(double from, double depth, double feed, const ToolSetter &setter, Done done,
        std::function<void(double)> next);
    // Writes `tlo` for `tool` (G10 L1, then G43 H when it is in the spindle) and reads it back.
    void writeOffset(int tool, double tlo, Done done, std::function<void()> next);
    void writeEntries(const QList<ControllerTool> &tools, Done done);
    [[nodiscard]] std::optional<int> spindleTool(const Done &done, const QString &what) const;
    [[nodiscard]] SessionResult tloResult(int tool, double tlo, std::optional<double> contactMz) const;
    [[nodiscard]] MachineStatus statusOf(const LinuxCnc::State &state) const;
    void abortOnSecondConnection();
    void sendEnable(int timeoutMs, std::function<void(const CommandReply &)> handler);
    void poll();
    static QByteArray number(double value);
    [[nodiscard]] static QString mm(double v);
    [[nodiscard]] static double atResolution(double v);

    MachineLink *m_link;
    FirmwareInfo m_firmware;
    QByteArray m_enablePassword = LinuxCnc::kDefaultEnablePassword;
    QString m_iniPath;
    QString m_tablePath;
    std::optional<int> m_tool;
    std::optional<double> m_tloInForce;
    std::optional<ToolSetter> m_setter;
    std::optional<double> m_reference;
    std::optional<QList<ControllerTool>> m_table;
    QTimer *m_poll
        = nullptr; // the state asked for while the link is idle (linuxcncrsh reports nothing itself)
    bool m_polling = false;
    quint64 m_printed = 0; // (DEBUG,…) lines asked for, to number them
    QByteArray m_session; // this controller's own mark in them: another's left in the queue is never taken
    bool m_abortedHere = false; // our own abort took enable from this connection: take it back
};

} // namespace Toffee
