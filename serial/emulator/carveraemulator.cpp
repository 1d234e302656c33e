// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/emulator/carveraemulator.h"

#include <cmath>

#include "model/limits.h"
#include "model/numberformat.h"
#include "model/textparsing.h"

namespace Toffee {

namespace {

QByteArray fixed(double v, int decimals = 3)
{
    return numberBytes(v, NumberFormat::fixed(decimals));
}

} // namespace

CarveraEmulator::CarveraEmulator(QObject *parent)
    : QObject(parent)
{
    // The seed's example tools: the first probes at MCS Z -72.300, the second at -105.688.
    m_lengths.insert(1, 77.7);
    m_lengths.insert(2, 44.312);
    m_step.setSingleShot(true);
    connect(&m_step, &QTimer::timeout, this, [this] {
        auto action = std::move(m_stepAction);
        m_stepAction = nullptr;
        if (action)
            action();
    });
}

double CarveraEmulator::toolLength(int tool) const
{
    if (tool < 0)
        return 0.0; // an empty spindle: the nose itself
    return m_lengths.value(tool, 40.0 + (tool % 20) * 2.5);
}

void CarveraEmulator::injectFault(Fault fault, const QByteArray &prefix, double amount)
{
    m_faults.append({ fault, prefix.toUpper(), amount });
}

void CarveraEmulator::halt(int reason)
{
    m_haltReason = reason;
}

QByteArray CarveraEmulator::statusReport() const
{
    const QByteArray state = isHalted() ? "Alarm"
        : m_held                        ? "Hold"
        : m_waitingForOperator          ? "Tool"
        : m_busy                        ? "Run"
                                        : "Idle";
    auto axes = [](double x, double y, double z) -> QByteArray {
        return fixed(x, 4) + ',' + fixed(y, 4) + ',' + fixed(z, 4) + ",0.0000,0.0000";
    };
    QByteArray report = '<' + state + "|MPos:" + axes(m_mpos[0], m_mpos[1], m_mpos[2])
        + "|WPos:" + axes(m_mpos[0] - m_wcs[0], m_mpos[1] - m_wcs[1], m_mpos[2] - m_wcs[2] - m_tlo)
        + "|R:0.0000|G:0|F:0.0,3000.0,100.0|S:0.0,0.0,100.0,0,23.5,24.1" + toolField() + "|W:0.00";
    if (isHalted())
        report += "|H:" + QByteArray::number(m_haltReason);
    return report + "|C:1,0,0,1>";
}

void CarveraEmulator::receiveRealtime(char c)
{
    switch (c) {
    case '?':
        Q_EMIT lineSent(statusReport());
        break;
    case 0x18: // Ctrl-X: abort whatever runs, drop what is queued; the firmware halts even when idle
        m_queue.clear();
        m_step.stop();
        m_stepAction = nullptr;
        m_waitingForOperator = false;
        Q_EMIT lineSent("ERROR: Abort during cycle");
        Q_EMIT lineSent(kHaltLine);
        halt(int(HaltReason::Manual));
        if (m_busy) {
            m_busy = false;
            m_dropOk = m_garble = false;
            Q_EMIT lineSent("ok");
        }
        break;
    case '!':
        m_held = true;
        break;
    case '~':
        m_held = false;
        break;
    default:
        break;
    }
}

void CarveraEmulator::receiveBytes(QByteArrayView bytes)
{
    for (char c : bytes) {
        if (c == '?' || c == 0x18) {
            receiveRealtime(c);
        } else if ((c == '!' || c == '~') && m_input.isEmpty()) {
            receiveRealtime(c);
        } else if (c == '\n' || c == '\r') {
            receiveLine(std::exchange(m_input, {}));
        } else if (m_input.size() < kMaxLineBytes) {
            m_input += c;
        }
    }
}

void CarveraEmulator::receiveLine(const QByteArray &line)
{
    m_queue.append(line);
    if (!m_busy)
        processNext();
}

void CarveraEmulator::processNext()
{
    if (m_busy || m_queue.isEmpty())
        return;
    const QByteArray line = m_queue.takeFirst().trimmed();
    m_busy = true;
    m_printed = 0;
    const QByteArray upper = line.toUpper();
    m_failThisProbe = false;
    for (qsizetype i = 0; i < m_faults.size(); ++i) {
        const PendingFault f = m_faults.at(i);
        if (!f.prefix.isEmpty() && !upper.startsWith(f.prefix))
            continue;
        m_faults.removeAt(i);
        switch (f.fault) {
        case Fault::NoAnswer:
            m_busy = false;
            return; // swallowed; the queue waits for the next line
        case Fault::CloseLink:
            m_busy = false;
            m_queue.clear();
            Q_EMIT linkClosed();
            return;
        case Fault::DropOk:
            m_dropOk = true;
            break;
        case Fault::Garble:
            m_garble = true;
            break;
        case Fault::FailProbe:
            // With a prefix, it is this command's probe that fails (fail-probe@M491.1 leaves M491 alone);
            // without one, the next probing cycle's, whichever command runs it.
            if (f.prefix.isEmpty())
                m_faults.insert(i, f);
            else
                m_failThisProbe = true;
            break;
        case Fault::Delay:
            later(int(f.amount), [this, line] { execute(line); });
            return;
        case Fault::BreakTool:
            breakTool(m_tool, f.amount);
            break;
        }
        break;
    }
    if (m_timing.moveMs > 0)
        later(m_timing.moveMs, [this, line] { execute(line); });
    else
        execute(line);
}

void CarveraEmulator::later(int ms, std::function<void()> step)
{
    m_stepAction = std::move(step);
    m_step.start(ms);
}

void CarveraEmulator::say(const QByteArray &line)
{
    // Garbling hits every line the command prints, and its "ok" only when it prints nothing else.
    const bool garble = m_garble && (line != "ok" || m_printed == 0);
    if (line != "ok")
        ++m_printed;
    if (garble) {
        QByteArray mangled = line;
        for (char &c : mangled) {
            if ((c >= '0' && c <= '9') || c == 'k')
                c = char(0xBF);
        }
        Q_EMIT lineSent(mangled);
        return;
    }
    Q_EMIT lineSent(line);
}

void CarveraEmulator::echo(const QByteArray &line)
{
    say(line);
    say("ok");
}

void CarveraEmulator::finishScript()
{
    if (m_dropOk)
        m_dropOk = false; // the script's end never comes
    else
        say("Done ATC");
    endSilently();
}

void CarveraEmulator::endSilently()
{
    m_garble = false;
    m_dropOk = false;
    m_busy = false;
    if (!m_queue.isEmpty())
        QMetaObject::invokeMethod(this, &CarveraEmulator::processNext, Qt::QueuedConnection);
}

void CarveraEmulator::finish()
{
    if (m_dropOk)
        m_dropOk = false;
    else
        say("ok");
    m_garble = false;
    m_busy = false;
    if (!m_queue.isEmpty())
        QMetaObject::invokeMethod(this, &CarveraEmulator::processNext, Qt::QueuedConnection);
}

} // namespace Toffee
