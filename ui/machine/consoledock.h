// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDockWidget>
#include <QStringList>

#include <optional>

class QLineEdit;
class QListWidget;

namespace Toffee {

struct CommandReply;
class MachineConnection;
class ToolDocument;

// Every line sent and received, with its time, filterable; and a line to type a command by hand, with
// history.
class ConsoleDock final : public QDockWidget
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ConsoleDock)

public:
    ConsoleDock(MachineConnection *connection, ToolDocument *document, QWidget *parent = nullptr);

    // Checked first (ConsoleCheck): refused with the reason, or sent after a question when it moves the
    // machine (`confirm` false skips the question, for tests).
    void sendCommand(const QString &command, bool confirm = true);
    [[nodiscard]] QStringList lines() const;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void append(const QByteArray &line, bool outgoing);
    void note(const QString &text);
    void applyFilter();
    [[nodiscard]] bool probed(const CommandReply &reply) const;
    void recordProbe(std::optional<int> tool);

    static constexpr int kMaxLines = 5000;
    static constexpr qsizetype kMaxLineChars = 500;
    MachineConnection *m_connection;
    ToolDocument *m_document;
    QListWidget *m_log;
    QLineEdit *m_filter;
    QLineEdit *m_command;
    QStringList m_history;
    qsizetype m_historyIndex = 0;
};

} // namespace Toffee
