// SPDX-License-Identifier: GPL-3.0-or-later
#include "consoledock.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QListWidget>
#include <QTime>
#include <QVBoxLayout>

#include "appearance.h"
#include "machineconnection.h"

using namespace Qt::StringLiterals;

namespace Toffee {

ConsoleDock::ConsoleDock(MachineConnection *connection, QWidget *parent)
    : QDockWidget(tr("Console"), parent)
    , m_connection(connection)
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
    m_command->setPlaceholderText(tr("Type a command (e.g. M493.4) and press Enter; ↑ ↓ for history"));
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

void ConsoleDock::append(const QByteArray &line, bool outgoing)
{
    // A line is at most 4 KB, but a few thousand of those would still make a heavy list: show their start.
    const QString shown = line.size() <= kMaxLineChars
        ? QString::fromUtf8(line)
        : QString::fromUtf8(line.first(kMaxLineChars)) + tr("… (%1 bytes in all)").arg(line.size());
    const QString text
        = QTime::currentTime().toString(u"HH:mm:ss.zzz"_s) + (outgoing ? u"  > "_s : u"  < "_s) + shown;
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

void ConsoleDock::sendCommand(const QString &command)
{
    if (command.isEmpty())
        return;
    m_history.removeAll(command);
    m_history.append(command);
    m_historyIndex = m_history.size();
    if (!m_connection->link() || m_connection->state() != MachineConnection::State::Connected) {
        append(tr("not connected; connect first").toUtf8(), false);
        return;
    }
    if (!m_connection->beginOperation(command)) {
        append(tr("the machine is busy with %1; wait for it").arg(m_connection->operation()).toUtf8(), false);
        return;
    }
    m_connection->link()->send(
        command.toUtf8(), MachineLink::kMotionTimeoutMs, [this](const CommandReply &reply) {
            m_connection->endOperation(SessionResult {});
            if (!reply.ok())
                append(reply.message.toUtf8(), false);
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
