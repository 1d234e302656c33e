// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/machine/consoledock.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QTime>
#include <QVBoxLayout>

#include "model/clock.h"
#include "model/document/tooldocument.h"
#include "serial/machine/consolecheck.h"
#include "serial/machine/machinecontroller.h"
#include "serial/machineconnection.h"
#include "ui/common/appearance.h"

using namespace Qt::StringLiterals;

namespace Toffee {

ConsoleDock::ConsoleDock(MachineConnection *connection, ToolDocument *document, QWidget *parent)
    : QDockWidget(tr("Console"), parent)
    , m_connection(connection)
    , m_document(document)
    , m_log(new QListWidget)
    , m_filter(new QLineEdit)
    , m_command(new QLineEdit)
{
    setObjectName(u"consoleDock"_s);
    m_log->setObjectName(u"consoleLog"_s);
    m_log->setAccessibleName(tr("Lines sent to and received from the machine"));
    m_log->setUniformItemSizes(true);
    useMonospace(m_log);
    m_filter->setObjectName(u"consoleFilter"_s);
    m_filter->setAccessibleName(tr("Filter the console"));
    m_filter->setPlaceholderText(tr("Filter…"));
    m_filter->setClearButtonEnabled(true);
    m_command->setObjectName(u"consoleCommand"_s);
    m_command->setAccessibleName(tr("Command to send to the machine"));
    m_command->setPlaceholderText(tr("Type a command and press Enter; ↑ ↓ for history"));
    // The hint names a line the connected controller takes.
    connect(m_connection, &MachineConnection::stateChanged, this, [this](MachineConnection::State state) {
        const MachineController *controller = m_connection->session();
        m_command->setPlaceholderText(state == MachineConnection::State::Connected && controller
                ? tr("Type a command (e.g. %1) and press Enter; ↑ ↓ for history")
                      .arg(controller->consoleExample())
                : tr("Type a command and press Enter; ↑ ↓ for history"));
    });
    useMonospace(m_command);
    m_command->installEventFilter(this);

    auto *body = new QWidget;
    auto *layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_filter);
    layout->addWidget(m_log, 1);
    layout->addWidget(m_command);
    setWidget(body);

    connect(m_connection, &MachineConnection::consoleLine, this, &ConsoleDock::append);
    connect(m_filter, &QLineEdit::textChanged, this, &ConsoleDock::applyFilter);
    connect(m_command, &QLineEdit::returnPressed, this, [this] {
        const QString text = m_command->text().trimmed();
        m_command->clear();
        sendCommand(text);
    });
}

void ConsoleDock::note(const QString &text)
{
    // Toffee's own words, set apart from what the machine said ("<") and what was sent (">").
    auto *item = new QListWidgetItem(
        Clock::now().toLocalTime().time().toString(u"HH:mm:ss.zzz"_s) + u"  · "_s + text, m_log);
    QFont italic = item->font();
    italic.setItalic(true);
    item->setFont(italic);
    item->setForeground(palette().color(QPalette::PlaceholderText));
    item->setHidden(
        !m_filter->text().isEmpty() && !item->text().contains(m_filter->text(), Qt::CaseInsensitive));
    while (m_log->count() > kMaxLines)
        delete m_log->takeItem(0);
    m_log->scrollToBottom();
}

void ConsoleDock::append(const QByteArray &line, bool outgoing)
{
    // A line is at most 4 KB, but a few thousand of those would still make a heavy list: show their start.
    const QString shown = line.size() <= kMaxLineChars
        ? QString::fromUtf8(line)
        : QString::fromUtf8(line.first(kMaxLineChars)) + tr("… (%1 bytes in all)").arg(line.size());
    const QString text = Clock::now().toLocalTime().time().toString(u"HH:mm:ss.zzz"_s)
        + (outgoing ? u"  > "_s : u"  < "_s) + shown;
    auto *item = new QListWidgetItem(text, m_log);
    if (!outgoing && (line.startsWith("ALARM") || line.startsWith("ERROR") || line.startsWith("error:")))
        item->setForeground(alarmColor(palette()));
    item->setHidden(!m_filter->text().isEmpty() && !text.contains(m_filter->text(), Qt::CaseInsensitive));
    while (m_log->count() > kMaxLines)
        delete m_log->takeItem(0);
    m_log->scrollToBottom();
}

void ConsoleDock::applyFilter()
{
    const QString filter = m_filter->text();
    for (int i = 0; i < m_log->count(); ++i) {
        QListWidgetItem *item = m_log->item(i);
        item->setHidden(!filter.isEmpty() && !item->text().contains(filter, Qt::CaseInsensitive));
    }
}

QStringList ConsoleDock::lines() const
{
    QStringList out;
    for (int i = 0; i < m_log->count(); ++i)
        out << m_log->item(i)->text();
    return out;
}

void ConsoleDock::sendCommand(const QString &command, bool confirm)
{
    if (command.isEmpty())
        return;
    m_history.removeAll(command);
    m_history.append(command);
    m_historyIndex = m_history.size();
    if (!m_connection->link() || m_connection->state() != MachineConnection::State::Connected) {
        note(tr("not connected; connect first"));
        return;
    }
    // The console is no back door: it refuses what the panels refuse, and asks before anything that moves.
    const ConsoleCheck check
        = ConsoleCheck::check(command, m_connection->isHalted(), m_connection->session()->consoleRules());
    if (check.verdict == ConsoleCheck::Verdict::Refuse) {
        note(tr("not sent: %1").arg(check.reason));
        return;
    }
    if (check.verdict == ConsoleCheck::Verdict::Confirm && confirm) {
        QString details = check.reason;
        if (check.setsTlo && m_connection->lastOffsets())
            details += u' ' + tr("The TLO is %1 now.").arg(millimetres(m_connection->lastOffsets()->tlo()));
        if (check.tool && !m_document->table().contains(*check.tool))
            details += u' ' + tr("T%1 is not in the tool table.").arg(*check.tool);
        QMessageBox box(QMessageBox::Question, tr("Send %1?").arg(command),
            details + u"\n\n"_s + tr("Keep hands clear. Send it?"), QMessageBox::Yes | QMessageBox::Cancel,
            this);
        box.setObjectName(u"consoleConfirmation"_s);
        box.setDefaultButton(QMessageBox::Cancel);
        if (box.exec() != QMessageBox::Yes) {
            note(tr("not sent: cancelled"));
            return;
        }
    }
    const bool setsTlo = check.setsTlo;
    const bool measures = check.measures;
    const auto changedTo = check.tool; // M6 T: the status may still show the tool before
    const bool sent = m_connection->sendLine(command.toUtf8(),
        [this, setsTlo, measures, changedTo](const CommandReply &reply, const SessionResult &result) {
            if (!reply.ok()) {
                note(reply.message);
                m_connection->refreshOffsets();
                return;
            }
            if (measures && probed(reply))
                return recordProbe(changedTo ? changedTo : m_connection->activeTool());
            // An offset set here is recorded like one set in the panel: by hand, for the tool in the spindle.
            const auto &tool = result.tool;
            const auto &tlo = result.tlo; // read from the reply once, by the connection
            if (setsTlo && tlo && tool && *tool >= 0) {
                auto recorded = m_document->record(Recording { *tool, tlo->tlo(), TloSource::Manual,
                    tlo->referenceMz, std::nullopt, Clock::now(), RecordingKind::ManualSet, tlo->currentMz });
                note(recorded ? tr("recorded in the table: T%1 TLO %2, set by hand")
                                    .arg(*tool)
                                    .arg(millimetres(tlo->tlo()))
                              : tr("the TLO is set on the machine but not recorded: %1")
                                    .arg(recorded.error().message));
            }
            // A typed command may have changed the tool or its offsets: the strip shows the machine as it is
            // now.
            if (!setsTlo)
                m_connection->refreshOffsets();
        });
    if (!sent)
        note(tr("the machine is busy with %1; wait for it").arg(m_connection->operation()));
}

bool ConsoleDock::probed(const CommandReply &reply) const
{
    const auto probe = m_connection->session() ? m_connection->session()->probeIn(reply.lines) : std::nullopt;
    return probe && probe->triggered;
}

// A probe typed here (M491, M6 T) is recorded like one from the panel: the offsets it left, for the tool in
// the spindle.
void ConsoleDock::recordProbe(std::optional<int> tool)
{
    m_connection->report([this, tool](const SessionResult &r) {
        if (!r.ok() || !r.tlo || !tool || *tool < 0) {
            note(tr("the tool was probed, but its TLO could not be read, so nothing was recorded: %1")
                     .arg(r.message));
            return;
        }
        auto recorded
            = m_document->record(Recording { *tool, r.tlo->tlo(), TloSource::Probe, r.tlo->knownReferenceMz(),
                std::nullopt, Clock::now(), RecordingKind::Probe, r.tlo->knownCurrentMz() });
        note(recorded
                ? tr("recorded in the table: T%1 TLO %2, probed").arg(*tool).arg(millimetres(r.tlo->tlo()))
                : tr("T%1 was probed but not recorded: %2").arg(*tool).arg(recorded.error().message));
    });
}

bool ConsoleDock::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_command && event->type() == QEvent::KeyPress && !m_history.isEmpty()) {
        const int key = static_cast<QKeyEvent *>(event)->key();
        if (key == Qt::Key_Up || key == Qt::Key_Down) {
            m_historyIndex
                = std::clamp<qsizetype>(m_historyIndex + (key == Qt::Key_Up ? -1 : 1), 0, m_history.size());
            m_command->setText(m_historyIndex < m_history.size() ? m_history.at(m_historyIndex) : QString());
            return true;
        }
    }
    return QDockWidget::eventFilter(watched, event);
}

} // namespace Toffee
