// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/machineconnection.h"

#include <cmath>
#include <utility>

#include "serial/carvera/machinesession.h"
#include "serial/emulator/carveraemulator.h"
#include "serial/emulator/emulatortransport.h"
#include "serial/grblhal/grblhalcontroller.h"
#include "serial/linuxcnc/linuxcnccontroller.h"
#include "serial/transport/serialporttransport.h"
#include "serial/transport/tcptransport.h"

using namespace Qt::StringLiterals;

namespace Toffee {

MachineConnection::MachineConnection(QObject *parent)
    : QObject(parent)
{ }

MachineConnection::~MachineConnection()
{
    // Whoever started a command may be gone already (the window closes): drop pending handlers unheard,
    // the link before the transport, so that closing the port calls none of them.
    const QSignalBlocker blocker(this);
    m_detector.reset();
    m_session.reset();
    m_link.reset();
    m_transport.reset();
}

void MachineConnection::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    if (state != State::Connected) {
        setHalt(false, std::nullopt); // nothing is known of a machine Toffee is not connected to
        m_offsets.reset();
    }
    Q_EMIT stateChanged(state);
}

QString MachineConnection::description() const
{
    return m_transport ? m_transport->description() : QString();
}

CarveraEmulator *MachineConnection::emulator() const
{
    auto *emulated = qobject_cast<EmulatorTransport *>(m_transport.get());
    return emulated ? emulated->emulator() : nullptr;
}

bool MachineConnection::isStatusStale() const
{
    if (!m_link || m_state != State::Connected)
        return true;
    const qint64 age = m_link->statusAgeMs();
    return age < 0 || age > kStaleAfterMs;
}

void MachineConnection::teardown()
{
    if (!m_operation.isEmpty()) {
        m_operation.clear();
        Q_EMIT busyChanged(false, {});
    }
    if (m_link)
        m_link->disconnect(this);
    if (m_transport)
        m_transport->close();
    m_detector.reset();
    m_session.reset();
    m_kind = ControllerKind::Auto;
    m_selfName.clear();
    m_link.reset();
    m_transport.reset();
}

void MachineConnection::connectTo(const ConnectionTarget &target)
{
    m_target = target;
    teardown();
    m_transport = makeTransport(target);
    m_link = std::make_unique<MachineLink>(m_transport.get());
    m_link->setTimeoutOverride(target.timeoutMs);
    connect(m_link.get(), &MachineLink::statusChanged, this, [this](const MachineStatus &status) {
        setHalt(status.isAlarm(), status.haltReason);
        Q_EMIT statusChanged(status);
    });
    connect(m_link.get(), &MachineLink::alarmRaised, this, [this](const QString &message) {
        // The alarm line comes before the status that says "Alarm": the window stops offering motion now,
        // not a status report later (when a broken-tool box already says halted).
        setHalt(true, m_haltReason);
        if (m_haltSaid.isEmpty())
            m_haltSaid = message; // the firmware's own words for the halt, kept until it is unlocked
        Q_EMIT alarmRaised(message);
    });
    connect(m_link.get(), &MachineLink::lineSent, this,
        [this](const QByteArray &l) { Q_EMIT consoleLine(l, true); });
    connect(m_link.get(), &MachineLink::lineReceived, this, [this](const QByteArray &l) {
        // Status reports and the answers to status questions (LinuxCNC's gets): four a second would drown
        // the console.
        if (m_link->grammar().classify(l) != ReplyKind::Status && !m_link->isQuiet())
            Q_EMIT consoleLine(l, false);
    });
    connect(m_link.get(), &MachineLink::closed, this, [this](const QString &reason) {
        if (m_state == State::Connected) {
            // An operation still running (between two commands) was interrupted as well.
            if (!m_interruption && !m_operation.isEmpty())
                m_interruption = m_before;
            const std::optional<Interruption> lost = m_interruption;
            setState(State::Disconnected);
            Q_EMIT disconnected(reason);
            Q_EMIT linkLost(lost ? lost->operation : QString(), reason);
        }
    });
    setState(State::Connecting);
    if (target.emulator)
        return startController(ControllerKind::Carvera);
    // Nothing of any controller's is sent before the controller is known, chosen or not: a controller chosen
    // is checked against the one found.
    m_detector = std::make_unique<ControllerDetector>(m_link.get());
    m_detector->detect([this](const Result<DetectedController> &found) {
        SessionResult failed;
        failed.outcome = SessionResult::Outcome::LinkFailure;
        if (!found) {
            failed.message = found.error().message;
            return failConnect(failed, true);
        }
        const ControllerKind chosen = m_target.controller;
        const ControllerKind kind = found.value().kind;
        if (chosen != ControllerKind::Auto && chosen != kind) {
            failed.outcome = SessionResult::Outcome::MachineError;
            failed.message
                = tr("%1 answered as %2, not as %3 as chosen. Nothing of %3's was sent. Choose %2, or "
                     "Automatic (toffee-cli --controller %4, or auto), and connect again.")
                      .arg(m_target.name(), controllerKindTitle(kind), controllerKindTitle(chosen),
                          controllerKindName(kind));
            return failConnect(failed, true);
        }
        m_selfName = found.value().name;
        startController(kind);
    });
}

void MachineConnection::failConnect(const SessionResult &result, bool closeLink)
{
    m_connectResult = result;
    // Nothing more goes to a machine refused before its controller took the link (closed once the reply
    // being handled has returned).
    if (closeLink && m_link)
        QMetaObject::invokeMethod(m_link.get(), &MachineLink::close, Qt::QueuedConnection);
    setState(State::Disconnected);
    Q_EMIT connectFailed(result.message);
}

void MachineConnection::startController(ControllerKind kind)
{
    m_kind = kind;
    if (m_prepare) {
        if (const QString refused = m_prepare(identity(), m_target); !refused.isEmpty()) {
            SessionResult failed;
            failed.outcome = SessionResult::Outcome::Refused; // the caller's refusal, not the machine's
            failed.message = refused;
            return failConnect(failed, true);
        }
    }
    m_session = makeController(m_link.get(), kind);
    if (auto *linuxCnc = qobject_cast<LinuxCncController *>(m_session.get())) {
        linuxCnc->setIniFile(m_target.linuxCncIni);
        if (!m_target.enablePassword.isEmpty())
            linuxCnc->setEnablePassword(m_target.enablePassword);
    }
    if (m_target.setter)
        m_session->setToolSetter(*m_target.setter);
    m_session->setProbePlans(m_probePlans);
    if (!m_session->keepsReference())
        m_session->adoptReference(m_target.reference);
    connect(m_session.get(), &MachineController::waitingForOperator, this,
        &MachineConnection::waitingForOperator);
    connect(m_session.get(), &MachineController::toolChangeFinished, this,
        &MachineConnection::toolChangeFinished);
    m_session->connectToMachine([this](const SessionResult &result) {
        m_connectResult = result;
        if (!result.ok())
            return failConnect(result, false);
        // The offsets connecting read are the machine's before anyone is told it is connected: a caller that
        // starts an operation on stateChanged (toffee-cli) checks a stored TLO against them.
        if (result.tlo)
            m_offsets = result.tlo;
        setState(State::Connected);
        if (result.status) {
            setHalt(result.status->isAlarm(), result.status->haltReason);
            Q_EMIT statusChanged(*result.status);
        }
        if (result.tlo)
            Q_EMIT offsetsChanged(*result.tlo, result.tool.value_or(-1));
        if (m_interruption && m_interruption->machine == m_target.name()) {
            const Interruption before = *std::exchange(m_interruption, std::nullopt);
            Q_EMIT interruptionChecked(interruptionVerdict(before, result));
        }
    });
}

void MachineConnection::setHalt(bool halted, std::optional<int> reason)
{
    m_haltReason = halted ? reason : std::nullopt;
    if (!halted)
        m_haltSaid.clear();
    if (m_halted == halted)
        return;
    m_halted = halted;
    Q_EMIT haltedChanged(halted);
}

bool MachineConnection::canOperate() const
{
    return m_state == State::Connected && !isBusy() && !m_halted;
}

bool MachineConnection::perform(const QString &what, bool evenIfHalted,
    const std::function<void(MachineController *, Done)> &operation, Done done)
{
    if ((m_halted && !evenIfHalted) || !beginOperation(what))
        return false;
    operation(m_session.get(), [this, done](const SessionResult &r) {
        // The link went in the middle of it: what the machine held before is kept for reconnecting.
        if (r.outcome == SessionResult::Outcome::LinkFailure && m_before)
            m_interruption = m_before;
        endOperation(r);
        if (done)
            done(r);
    });
    return true;
}

std::optional<int> MachineConnection::activeTool() const
{
    return m_session ? m_session->activeTool() : std::nullopt;
}

QString MachineConnection::activeToolName() const
{
    const auto tool = activeTool();
    return tool && *tool >= 0 ? u"T"_s + QString::number(*tool) : tr("the current tool");
}

FirmwareInfo MachineConnection::firmware() const
{
    return m_session ? m_session->firmware() : FirmwareInfo {};
}

HaltWords MachineConnection::haltWords(int reason) const
{
    return m_session ? m_session->haltWords(reason) : MachineController::neutralHaltWords(reason);
}

QString MachineConnection::haltedMessage() const
{
    const QString said = m_haltSaid.isEmpty() ? QString() : tr("It said: \"%1\". ").arg(m_haltSaid);
    const HaltWords words = m_haltReason ? haltWords(*m_haltReason) : HaltWords {};
    const QString reason = said
        + (m_haltReason ? words.name + u": "_s + words.recovery : tr("Check the machine, then unlock it."));
    return tr("The machine is halted (Alarm lock) and takes no command but Unlock. %1").arg(reason);
}

void MachineConnection::stop()
{
    if (m_session)
        m_session->abort();
}

void MachineConnection::stopJog()
{
    if (m_session)
        m_session->stopJog();
}

void MachineConnection::refreshOffsets()
{
    report({});
}

bool MachineConnection::beginOperation(const QString &what)
{
    if (isBusy() || m_state != State::Connected)
        return false;
    m_operation = what;
    const auto &status = m_link->lastStatus();
    m_before = Interruption { what, m_target.name(), status ? status->tool : activeTool(),
        status && status->tlo ? status->tlo
            : m_offsets       ? std::optional(m_offsets->tlo())
                              : std::nullopt,
        m_offsets ? m_offsets->knownCurrentMz() : std::nullopt };
    m_interruption.reset(); // a new operation on the machine: the old question is answered by now
    Q_EMIT busyChanged(true, what);
    return true;
}

void MachineConnection::announce(const SessionResult &result)
{
    if (result.tlo) {
        m_offsets = result.tlo;
        Q_EMIT offsetsChanged(*result.tlo, result.tool.value_or(-1));
    }
}

void MachineConnection::updateOperation(const QString &what)
{
    if (m_operation.isEmpty())
        return;
    m_operation = what;
    Q_EMIT busyChanged(true, what);
}

void MachineConnection::endOperation(const SessionResult &result)
{
    announce(result);
    m_operation.clear();
    Q_EMIT busyChanged(false, {});
}

void MachineConnection::disconnectFromMachine()
{
    const bool wasConnected = m_state != State::Disconnected;
    setState(State::Disconnected);
    teardown();
    if (wasConnected)
        Q_EMIT disconnected(tr("as asked."));
}

void MachineConnection::setProbePlans(std::function<ProbePlan(int tool)> plans)
{
    m_probePlans = std::move(plans);
    if (m_session)
        m_session->setProbePlans(m_probePlans);
}

} // namespace Toffee
