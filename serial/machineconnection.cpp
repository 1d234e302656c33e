// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/machineconnection.h"

#include "serial/emulatortransport.h"
#include "serial/serialporttransport.h"

namespace Toffee {

MachineConnection::MachineConnection(QObject *parent)
    : QObject(parent)
{ }

MachineConnection::~MachineConnection()
{
    // Whoever started a command may be gone already (the window closes): drop pending handlers unheard,
    // the link before the transport, so that closing the port calls none of them.
    const QSignalBlocker blocker(this);
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
    m_session.reset();
    m_link.reset();
    m_transport.reset();
}

void MachineConnection::connectTo(const ConnectionTarget &target)
{
    teardown();
    if (target.emulator)
        m_transport = std::make_unique<EmulatorTransport>();
    else
        m_transport = std::make_unique<SerialPortTransport>(target.port, target.baud);
    m_link = std::make_unique<MachineLink>(m_transport.get());
    m_session = std::make_unique<MachineSession>(m_link.get());
    connect(m_link.get(), &MachineLink::statusChanged, this, [this](const MachineStatus &status) {
        setHalt(status.isAlarm(), status.haltReason);
        Q_EMIT statusChanged(status);
    });
    connect(m_link.get(), &MachineLink::alarmRaised, this, [this](const QString &message) {
        // The alarm line comes before the status that says "Alarm": the window stops offering motion now,
        // not a status report later (when a broken-tool box already says halted).
        setHalt(true, m_haltReason);
        Q_EMIT alarmRaised(message);
    });
    connect(m_link.get(), &MachineLink::lineSent, this,
        [this](const QByteArray &l) { Q_EMIT consoleLine(l, true); });
    connect(m_link.get(), &MachineLink::lineReceived, this, [this](const QByteArray &l) {
        if (classifyReply(l) != ReplyKind::Status) // four a second would drown the console
            Q_EMIT consoleLine(l, false);
    });
    connect(m_link.get(), &MachineLink::closed, this, [this](const QString &reason) {
        if (m_state == State::Connected) {
            setState(State::Disconnected);
            Q_EMIT disconnected(reason);
        }
    });
    setState(State::Connecting);
    m_session->connectToMachine([this](const SessionResult &result) {
        m_connectResult = result;
        if (!result.ok()) {
            setState(State::Disconnected);
            Q_EMIT connectFailed(result.message);
            return;
        }
        setState(State::Connected);
        if (result.status) {
            setHalt(result.status->isAlarm(), result.status->haltReason);
            Q_EMIT statusChanged(*result.status);
        }
        if (result.tlo) {
            m_offsets = result.tlo;
            Q_EMIT offsetsChanged(*result.tlo, result.tool.value_or(-1));
        }
    });
}

void MachineConnection::setHalt(bool halted, std::optional<int> reason)
{
    m_haltReason = halted ? reason : std::nullopt;
    if (m_halted == halted)
        return;
    m_halted = halted;
    Q_EMIT haltedChanged(halted);
}

bool MachineConnection::canOperate() const
{
    return m_state == State::Connected && !isBusy() && !m_halted;
}

void MachineConnection::refreshOffsets()
{
    if (m_state != State::Connected || m_halted || !beginOperation(tr("Reading the offsets…")))
        return;
    m_session->report([this](const SessionResult &r) { endOperation(r); });
}

bool MachineConnection::beginOperation(const QString &what)
{
    if (isBusy() || m_state != State::Connected)
        return false;
    m_operation = what;
    Q_EMIT busyChanged(true, what);
    return true;
}

void MachineConnection::endOperation(const SessionResult &result)
{
    if (result.tlo) {
        m_offsets = result.tlo;
        Q_EMIT offsetsChanged(*result.tlo, result.tool.value_or(-1));
    }
    m_operation.clear();
    Q_EMIT busyChanged(false, {});
}

void MachineConnection::disconnectFromMachine()
{
    const bool wasConnected = m_state != State::Disconnected;
    setState(State::Disconnected);
    teardown();
    if (wasConnected)
        Q_EMIT disconnected(tr("Disconnected."));
}

} // namespace Toffee
