// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLabel>

namespace Toffee {

class HistoryRecorder;

// The status bar's word on the library: which shared library the station works with, or that it is offline
// and how many changes wait for it. Says once, when it is back, how many were written.
class LibraryStatusLabel final : public QLabel
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LibraryStatusLabel)

public:
    explicit LibraryStatusLabel(HistoryRecorder *recorder, QWidget *parent = nullptr);

    void refresh();

Q_SIGNALS:
    // For the status bar's message area: a shared library is back, and what waited is written.
    void announced(const QString &message);

private:
    void back();

    HistoryRecorder *m_recorder;
    qsizetype m_waitedMost = 0; // the most changes that waited during this outage
};

} // namespace Toffee
