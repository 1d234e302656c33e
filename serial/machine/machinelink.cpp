// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial/machine/machinelink.h"

#include "model/numberformat.h"
#include "serial/transport/linetransport.h"

namespace Toffee {

namespace {

// A machine's words in a message for people: enough to recognise, never pages of it.
QString excerpt(const QString &text)
{
    constexpr qsizetype kMaxChars = 200;
    return text.size() <= kMaxChars ? text : text.first(kMaxChars) + u'\u2026';
}

ReplyKind basicKind(QByteArrayView line)
{
    const QByteArrayView t = line.trimmed();
    if (t == "ok")
        return ReplyKind::Ok;
    if (t.startsWith("error:"))
        return ReplyKind::Error;
    if (t.startsWith("ALARM:"))
        return ReplyKind::Alarm;
    if (t.startsWith('<') && t.endsWith('>'))
        return ReplyKind::Status;
    return ReplyKind::Other;
}

QString basicMessage(QByteArrayView line)
{
    const QByteArrayView t = line.trimmed();
    const qsizetype colon = t.indexOf(':');
    return QString::fromUtf8(colon < 0 ? t : t.sliced(colon + 1).trimmed());
}

} // namespace

ReplyGrammar ReplyGrammar::basic()
{
    return { basicKind,
        [](QByteArrayView, const std::optional<MachineStatus> &) -> std::optional<MachineStatus> {
            return std::nullopt;
        },
        [](QByteArrayView) { return false; }, basicMessage, [](QStringView) { return QString(); }, nullptr };
}

MachineLink::MachineLink(LineTransport *transport, QObject *parent)
    : QObject(parent)
    , m_transport(transport)
{
    // Precise: a coarse timer may fire up to 5 % early, and a limit is a promise to wait that long.
    m_timeout.setSingleShot(true);
    m_timeout.setTimerType(Qt::PreciseTimer);
    m_grace.setSingleShot(true);
    m_grace.setTimerType(Qt::PreciseTimer);
    m_poll.setInterval(kPollIntervalMs);
    m_quiet.setSingleShot(true);
    m_quiet.setTimerType(Qt::PreciseTimer);
    connect(&m_quiet, &QTimer::timeout, this, [this] {
        if (m_current && m_current->end == ReplyEnd::Quiet && m_alarm.isEmpty())
            complete(CommandReply::Status::Ok, {});
    });
    connect(&m_timeout, &QTimer::timeout, this, [this] {
        if (!m_current)
            return;
        const QString command = QString::fromUtf8(m_current->named());
        const QString message
            = tr("The machine did not answer \"%1\" within %2 s. The link was closed, because a "
                 "late answer could be taken for the next command's. Reconnect, and check the "
                 "machine before you go on.%3")
                  .arg(command, formatNumber(m_timeout.interval() / 1000.0, NumberFormat::fixed(1)),
                      floodNote());
        complete(CommandReply::Status::Timeout, message);
        failAll(CommandReply::Status::Timeout, message);
        m_lastError = message;
        m_transport->close();
    });
    connect(&m_grace, &QTimer::timeout, this,
        [this] { complete(CommandReply::Status::Halted, haltedMessage() + floodNote()); });
    connect(&m_poll, &QTimer::timeout, this, &MachineLink::requestStatus);
    connect(m_transport, &LineTransport::lineReceived, this, &MachineLink::handleLine);
    connect(m_transport, &LineTransport::errorOccurred, this,
        [this](const QString &message) { m_lastError = message; });
    connect(m_transport, &LineTransport::closed, this, &MachineLink::handleClosed);
    connect(m_transport, &LineTransport::opened, this, [this] {
        m_lastError.clear();
        m_status.reset();
        m_statusClock.invalidate();
        if (m_poll.interval() > 0)
            m_poll.start();
        Q_EMIT opened();
    });
}

bool MachineLink::isOpen() const
{
    return m_transport->isOpen();
}

void MachineLink::open()
{
    m_transport->open();
}

void MachineLink::close()
{
    m_transport->close();
}

void MachineLink::setPollInterval(int ms)
{
    m_poll.setInterval(ms);
    if (ms <= 0)
        m_poll.stop();
    else if (isOpen())
        m_poll.start();
}

void MachineLink::send(
    const QByteArray &line, int timeoutMs, ReplyHandler handler, ReplyEnd end, qsizetype maxLines)
{
    enqueue({ line, timeoutMs, std::move(handler), end, maxLines, false, {} });
}

void MachineLink::enqueue(Pending pending)
{
    if (!isOpen()) {
        CommandReply reply { CommandReply::Status::LinkLost, pending.named(), {},
            tr("Not connected to the machine; connect first.") };
        QMetaObject::invokeMethod(
            this, [handler = pending.handler, reply] { handler(reply); }, Qt::QueuedConnection);
        return;
    }
    m_queue.append(std::move(pending));
    if (!m_current)
        startNext();
}

void MachineLink::sendQuietly(
    const QByteArray &line, int timeoutMs, ReplyHandler handler, ReplyEnd end, const QByteArray &shownAs)
{
    enqueue({ line, timeoutMs, std::move(handler), end, kMaxReplyLines, true, shownAs });
}

void MachineLink::sendRealtime(char c)
{
    if (isOpen())
        m_transport->writeRealtime(c);
}

void MachineLink::restartLimit(int ms)
{
    if (m_current)
        m_timeout.start(ms);
}

void MachineLink::requestStatus()
{
    if (isOpen())
        m_statusRequested = true;
    sendRealtime('?');
}

void MachineLink::reportStatus(const MachineStatus &status)
{
    m_status = status;
    m_statusClock.start();
    m_statusRequested = false;
    Q_EMIT statusChanged(status);
}

void MachineLink::startNext()
{
    if (m_current || m_queue.isEmpty() || !isOpen())
        return;
    m_current = m_queue.takeFirst();
    m_lines.clear();
    m_droppedLines = 0;
    m_alarm.clear();
    m_scriptRunning = false;
    m_timeout.start(m_timeoutOverride > 0 ? m_timeoutOverride : int(m_current->timeoutMs * m_timeoutScale));
    if (m_current->end == ReplyEnd::Quiet)
        m_quiet.start(int(kQuietMs * m_timeoutScale));
    if (!m_current->quiet)
        Q_EMIT lineSent(m_current->line);
    m_transport->writeLine(m_current->line);
}

void MachineLink::handleLine(const QByteArray &line)
{
    Q_EMIT lineReceived(line);
    const ReplyKind kind = m_grammar.classify(line);
    if (kind == ReplyKind::Status) {
        if (auto status = m_grammar.status(line, m_status)) {
            m_status = *status;
            m_statusClock.start();
            m_statusRequested = false;
            Q_EMIT statusChanged(*status);
        }
        return;
    }
    // Said at once, whether or not a command is waiting: the machine is halted from this line on, not from
    // the next status report (a window would otherwise show "Run" beside a box that says halted).
    if (kind == ReplyKind::Alarm || kind == ReplyKind::HaltError)
        Q_EMIT alarmRaised(m_grammar.message(line));
    if (!m_current)
        return; // stray output, kept for the console only
    handleReplyLine(line, kind);
}

void MachineLink::handleReplyLine(const QByteArray &line, ReplyKind kind)
{
    const ReplyEnd end = m_current->end;
    if (end == ReplyEnd::Quiet && m_quiet.isActive())
        m_quiet.start(); // silence is counted from the last line
    switch (kind) {
    case ReplyKind::Ok:
        if (!m_alarm.isEmpty()) {
            complete(CommandReply::Status::Halted, haltedMessage() + floodNote());
        } else if (end == ReplyEnd::Script && m_scriptRunning) {
            keep(line); // the acknowledgement, or one of the script's own lines' "ok"
        } else {
            complete(CommandReply::Status::Ok, {});
        }
        break;
    case ReplyKind::Error: {
        const QString said = excerpt(m_grammar.message(line));
        const QString meaning = m_grammar.refusalMeaning ? m_grammar.refusalMeaning(said) : QString();
        complete(CommandReply::Status::Refused,
            tr("The machine refused \"%1\": %2").arg(QString::fromUtf8(m_current->named()), said)
                + (meaning.isEmpty() ? QString() : u' ' + meaning));
    } break;
    case ReplyKind::Alarm:
    case ReplyKind::HaltError:
        keep(line);
        if (m_alarm.isEmpty())
            m_alarm = excerpt(m_grammar.message(line));
        m_grace.start(int(kAlarmGraceMs * m_timeoutScale));
        break;
    default:
        keep(line);
        if (end == ReplyEnd::Line && m_alarm.isEmpty()) {
            complete(CommandReply::Status::Ok, {});
        } else if (end == ReplyEnd::Script) {
            if (m_grammar.scriptDone(line) && m_alarm.isEmpty())
                complete(CommandReply::Status::Ok, {});
            else
                m_scriptRunning = true;
        }
    }
}

void MachineLink::complete(CommandReply::Status status, const QString &message)
{
    if (!m_current)
        return;
    m_timeout.stop();
    m_grace.stop();
    m_quiet.stop();
    m_scriptRunning = false;
    Pending done = std::move(*m_current);
    m_current.reset();
    CommandReply reply { status, done.named(), std::move(m_lines), message, m_droppedLines };
    m_lines.clear();
    m_droppedLines = 0;
    m_alarm.clear();
    if (status != CommandReply::Status::Timeout && status != CommandReply::Status::LinkLost)
        QMetaObject::invokeMethod(this, &MachineLink::startNext, Qt::QueuedConnection);
    if (done.handler)
        done.handler(reply);
}

void MachineLink::failAll(CommandReply::Status status, const QString &message)
{
    const QList<Pending> queued = std::exchange(m_queue, {});
    for (const Pending &p : queued) {
        if (p.handler)
            p.handler(CommandReply { status, p.named(), {}, message });
    }
}

void MachineLink::handleClosed()
{
    m_poll.stop();
    const QString reason = m_lastError.isEmpty() ? tr("the link was closed") : m_lastError;
    if (m_current) {
        complete(CommandReply::Status::LinkLost,
            tr("The connection to the machine was lost while it ran \"%1\": %2")
                    .arg(QString::fromUtf8(m_current->named()), reason)
                + floodNote());
    }
    failAll(CommandReply::Status::LinkLost, tr("The connection to the machine was lost: %1").arg(reason));
    Q_EMIT closed(reason);
}

void MachineLink::keep(const QByteArray &line)
{
    if (m_lines.size() >= (m_current ? m_current->maxLines : kMaxReplyLines)) {
        m_lines.removeFirst();
        ++m_droppedLines;
    }
    m_lines.append(line);
}

// The firmware's own words, and what they mean when Toffee knows the line.
QString MachineLink::haltedMessage() const
{
    const QString meaning = m_grammar.haltMeaning(m_alarm);
    const QString said = tr("The machine halted: %1").arg(m_alarm);
    return meaning.isEmpty() ? said : said + u' ' + meaning;
}

QString MachineLink::floodNote() const
{
    if (m_droppedLines == 0)
        return {};
    return u' '
        + tr("Meanwhile it printed %1 lines that were no answer; only the last %2 were kept. A machine that "
             "prints that much is not well: check its firmware and the cable.")
              .arg(m_droppedLines + m_lines.size())
              .arg(m_lines.size());
}

} // namespace Toffee
