// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include <QObject>

#include "model/toolsetter.h"
#include "serial/controllerdetection.h"
#include "serial/machine/machinecontroller.h"
#include "serial/machine/machinelink.h"
#include "serial/machineidentity.h"
#include "serial/transport/tcptransport.h"

namespace Toffee {

class CarveraEmulator;
class LineTransport;

// Where to find the machine: a serial port at a baud rate, a host on the network (Wi-Fi), or the built-in
// emulator.
struct ConnectionTarget
{
    bool emulator = true;
    QString port;
    int baud = 115200;
    int timeoutMs = 0; // every command's limit, connecting included; 0: each command's own
    // The built-in emulator: Makera's stock firmware instead of the community's, and a real machine's pace
    // (toffee --emulator, for a person watching) instead of none (tests).
    bool emulatorStock = false;
    bool emulatorPaced = false;
    // Not the emulator and a host: the machine's console over TCP (Wi-Fi) instead of the serial port.
    QString host;
    quint16 tcpPort = TcpTransport::kDefaultPort;
    // Plain text or Makera's frames, found on connecting; forced, it is checked first (serial port and
    // network alike).
    StreamTransport::Protocol protocol = StreamTransport::Protocol::Auto;
    // Auto: found by asking on connecting (ControllerDetector); forced, the controller checks that it is.
    ControllerKind controller = ControllerKind::Auto;
    // For a controller whose probing cycle is Toffee's (grblHAL): where its tool setter is.
    std::optional<ToolSetter> setter;
    // For a controller that keeps no reference tool (grblHAL): the one Toffee kept for this machine.
    std::optional<double> reference;
    // LinuxCNC: the INI it runs, on this computer (its tool table's file), and linuxcncrsh's enable password
    // (empty: LinuxCNC's own default). The password is never printed or logged.
    QString linuxCncIni;
    QByteArray enablePassword;

    [[nodiscard]] bool isNetwork() const { return !emulator && !host.isEmpty(); }
    // The controller known before connecting: the one chosen, or the Carvera for the built-in emulator;
    // Auto while it is to be found by asking.
    [[nodiscard]] ControllerKind knownController() const;
    // "192.168.1.57:2222", "/dev/ttyACM0" or "emulator", as the history and the settings name it.
    [[nodiscard]] QString name() const;
};

// The transport a target names: a serial port at its baud rate, or a new built-in emulator. The window's
// connection and the CLI both make theirs here.
[[nodiscard]] std::unique_ptr<LineTransport> makeTransport(const ConnectionTarget &target);
// The controller that speaks to the machine on `link`: the Carvera's (MachineSession) or grblHAL's.
[[nodiscard]] std::unique_ptr<MachineController> makeController(
    MachineLink *link, ControllerKind kind = ControllerKind::Carvera);
// The TCP port a controller's console listens on when the address gives none: linuxcncrsh's 5007 for
// LinuxCNC, else the Carvera's 2222 (grblHAL's telnet port varies: give it).
[[nodiscard]] quint16 defaultTcpPort(ControllerKind kind);
// "auto", "carvera", "grblhal", "linuxcnc" (toffee-cli --controller, the settings); nothing for another word.
[[nodiscard]] std::optional<ControllerKind> controllerKindFromName(const QString &name);

// The window's one machine: it builds the transport, the link and the session for a target, keeps them for
// the connection's lifetime, and says what state the link is in. No widgets: the panels watch it.
class MachineConnection final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(MachineConnection)

public:
    enum class State { Disconnected, Connecting, Connected };

    explicit MachineConnection(QObject *parent = nullptr);
    ~MachineConnection() override;

    void connectTo(const ConnectionTarget &target);
    // What the last connectTo() named: the machine connected to, or being connected to (with what the
    // preparer added).
    [[nodiscard]] const ConnectionTarget &target() const { return m_target; }
    // Called once the controller is known (found by asking) and before anything of that controller is sent:
    // the caller adds what belongs to that machine (grblHAL's tool setter and reference), or returns why it
    // cannot connect (the connect then fails with it).
    using Preparer = std::function<QString(const MachineIdentity &identity, ConnectionTarget &target)>;
    void setPreparer(Preparer prepare) { m_prepare = std::move(prepare); }
    // The controller spoken to: chosen or found; Auto while disconnected or still asking.
    [[nodiscard]] ControllerKind controllerKind() const { return m_kind; }
    // Which machine it is, once the controller is known (isKnown() false before).
    [[nodiscard]] MachineIdentity identity() const
    {
        return m_kind == ControllerKind::Auto ? MachineIdentity {} : identityOf(m_target, m_kind, m_selfName);
    }
    void disconnectFromMachine();
    [[nodiscard]] State state() const { return m_state; }
    [[nodiscard]] QString description() const;
    // Null while disconnected.
    [[nodiscard]] MachineController *session() const { return m_session.get(); }
    // How each tool is probed (MachineController::setProbePlans), for this connection's controllers now and
    // after a reconnect: the window's and toffee-cli's table, with a command's own overrides.
    void setProbePlans(std::function<ProbePlan(int tool)> plans);
    [[nodiscard]] MachineLink *link() const { return m_link.get(); }
    // The built-in emulator while connected to it, else null (for tests and the self-test).
    [[nodiscard]] CarveraEmulator *emulator() const;
    // The result of the last connect, with the status and offsets read then.
    [[nodiscard]] const SessionResult &connectResult() const { return m_connectResult; }
    // The status is stale when the last report is older than this (a link that stopped answering).
    static constexpr int kStaleAfterMs = 1500;
    [[nodiscard]] bool isStatusStale() const;

    // The machine's operations, by name. Each runs only when the machine can take it (canOperate; unlock
    // needs only a connection), shows as the one operation running, and reports one result; false when it
    // did not start. Panels reach the machine through these, never through the session.
    using Done = MachineController::Done;
    bool status(Done done); // also while halted: it only reads
    bool report(Done done);
    // The controller's own tool table (grblHAL's), read, or written and read back.
    bool readToolTable(Done done);
    bool writeToolTable(const QList<ControllerTool> &tools, Done done);
    bool selectTool(int tool, Done done);
    // With `storedTlo`, a manual change takes it instead of probing (MachineController::changeTool).
    bool changeTool(int tool, Done done, std::optional<double> storedTlo = std::nullopt);
    // Moves the machine by `stepMm` (MachineController::jog): the status says where it stands after.
    bool jog(const std::array<double, 3> &stepMm, double feed, Done done);
    bool probe(Done done);
    // `storedTlo`: the table's TLO for the tool, which the firmware is to compare with (set first when the
    // machine has another in force).
    bool breakTest(double tolerance, Done done, std::optional<double> storedTlo = std::nullopt);
    bool setTlo(double tlo, Done done);
    bool setTloAboveZ0(double height, Done done);
    bool restoreTlo(int tool, double tlo, Done done);
    // `brokenToolTlo`: MachineController::unlock's.
    bool unlock(Done done, std::optional<double> brokenToolTlo = std::nullopt);
    // A line typed in the console, sent as it is (ConsoleCheck has judged it first); offsets in its reply are
    // announced like any operation's.
    // `done` gets the reply and the result announced for it (the offsets it reported, the tool in the
    // spindle).
    bool sendLine(
        const QByteArray &line, std::function<void(const CommandReply &, const SessionResult &)> done);
    // Stops whatever the machine does now (Ctrl-X); it halts, and Unlock follows.
    void stop();
    // Stops a jog under way where the machine stands: without a halt where the controller has a jog cancel
    // (grblHAL), else as stop().
    void stopJog();
    // While a tool change waits for the person (waitingForOperator): the tool is in, go on (where the
    // controller takes that from here: resumesFromHere), or end the change (MachineController's).
    [[nodiscard]] bool resumesFromHere() const { return m_session && m_session->resumesFromHere(); }
    // The next probe makes the tool in the spindle this machine's reference: its controller keeps none of its
    // own (grblHAL) and none was measured on this machine yet.
    [[nodiscard]] bool probeMakesReference() const
    {
        return m_session && !m_session->keepsReference() && !m_session->keptReference();
    }
    void resumeToolChange();
    void endToolChange(const QString &why);
    // What the machine said it runs on connecting; Unknown while disconnected.
    [[nodiscard]] FirmwareInfo firmware() const;
    // The tool the machine reports in the spindle, if known.
    [[nodiscard]] std::optional<int> activeTool() const;
    // "T2", or "the current tool" when the machine has not said.
    [[nodiscard]] QString activeToolName() const;

    // One operation at a time, whichever panel starts it: begin returns false while another runs.
    bool beginOperation(const QString &what);
    // Reads the offsets again (M493.4) when nothing else runs, so that every panel shows them as they are.
    void refreshOffsets();
    void endOperation(const SessionResult &result);
    // A sequence of operations held as one (the rack's): what it does now, for the busy text.
    void updateOperation(const QString &what);
    // Offsets a result reports become the machine's (what endOperation does for one operation).
    void announce(const SessionResult &result);
    [[nodiscard]] bool isBusy() const { return !m_operation.isEmpty(); }
    // Halted (Alarm): the controller refuses every motion and offset command until Unlock.
    [[nodiscard]] bool isHalted() const { return m_halted; }
    [[nodiscard]] std::optional<int> haltReason() const { return m_haltReason; }
    // What the firmware said when it halted ("Unexpected tool absence detected, …"), while it stays halted;
    // empty when it said nothing this connection saw (halted before it connected).
    [[nodiscard]] QString haltSaid() const { return m_haltSaid; }
    // A halt reason the status gave, in the connected controller's words.
    [[nodiscard]] HaltWords haltWords(int reason) const;
    // Why an operation cannot run on a halted machine, and what to do, for people.
    [[nodiscard]] QString haltedMessage() const;
    // The reference and current MCS Z the machine last reported (M493.4, M493.3), if any since connecting.
    [[nodiscard]] const std::optional<TloReading> &lastOffsets() const { return m_offsets; }
    // Connected, idle and not halted: what every panel's machine operation (but Unlock and Stop) needs.
    [[nodiscard]] bool canOperate() const;
    [[nodiscard]] QString operation() const { return m_operation; }

    // An operation the link was lost in the middle of (a cable pulled, the machine out of Wi-Fi): what it was
    // and what the machine held when it began. Nothing of it was recorded, since the machine confirmed
    // nothing; on connecting to the same machine again Toffee reads the offsets back and says what became of
    // it (interruptionChecked), then forgets it.
    struct Interruption
    {
        QString operation; // "Probing T3…"
        QString machine; // ConnectionTarget::name()
        std::optional<int> tool; // in the spindle when it began
        std::optional<double> tloInForce;
        std::optional<double> currentMz; // M493.4's current tool offset, when known
    };
    [[nodiscard]] const std::optional<Interruption> &interruption() const { return m_interruption; }
    // The last operation ended because the link went: linkLost follows, or came already (a panel leaves the
    // telling to whoever offers to reconnect).
    [[nodiscard]] bool linkLostDuringOperation() const
    {
        return m_interruption && (m_state != State::Connected || !m_link || !m_link->isOpen());
    }
    // What the machine holds now against what it held before `interruption`, for people: whether it ran.
    [[nodiscard]] static QString interruptionVerdict(const Interruption &before, const SessionResult &now);

Q_SIGNALS:
    void stateChanged(Toffee::MachineConnection::State state);
    void connectFailed(const QString &message);
    void disconnected(const QString &reason);
    void statusChanged(const Toffee::MachineStatus &status);
    // Every line sent (outgoing = true) and received, for the console.
    void consoleLine(const QByteArray &line, bool outgoing);
    void alarmRaised(const QString &message);
    void busyChanged(bool busy, const QString &operation);
    void haltedChanged(bool halted);
    // Offsets learned from any operation (M493.4 and M493.3 replies).
    void offsetsChanged(const Toffee::TloReading &offsets, int tool);
    // The link went without being asked to: while `operation` ran (interruption() says what the machine held
    // before it), or while idle (`operation` empty).
    void linkLost(const QString &operation, const QString &reason);
    // Connected again to the machine of interruption(): what the machine holds now says whether it ran.
    void interruptionChecked(const QString &verdict);
    // A tool change waits for the person to put `tool` in, for at most `limitMs`; then it finished.
    void waitingForOperator(int tool, int limitMs);
    void toolChangeFinished();

private:
    void setState(State state);
    void setHalt(bool halted, std::optional<int> reason);
    // Runs `operation` on the session as the one operation `what`, ending it with the result before `done`.
    bool perform(const QString &what, bool evenIfHalted,
        const std::function<void(MachineController *, Done)> &operation, Done done);
    void teardown();
    // The controller is known: prepare, make its controller and connect it.
    void startController(ControllerKind kind);
    void failConnect(const SessionResult &result, bool closeLink);

    State m_state = State::Disconnected;
    std::unique_ptr<LineTransport> m_transport;
    std::unique_ptr<MachineLink> m_link;
    std::unique_ptr<MachineController> m_session;
    std::function<ProbePlan(int tool)> m_probePlans;
    std::unique_ptr<ControllerDetector> m_detector;
    Preparer m_prepare;
    ControllerKind m_kind = ControllerKind::Auto;
    QString m_selfName; // what the controller called itself when asked (grblHAL's build name)
    SessionResult m_connectResult;
    QString m_operation;
    bool m_halted = false;
    ConnectionTarget m_target;
    std::optional<TloReading> m_offsets;
    std::optional<int> m_haltReason;
    QString m_haltSaid;
    // What the machine held when the running operation began (the tool and TLO of the last status report).
    std::optional<Interruption> m_before;
    std::optional<Interruption> m_interruption;
};

} // namespace Toffee
