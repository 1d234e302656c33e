// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/library/librarystatuslabel.h"

#include "model/library/historyrecorder.h"

using namespace Qt::StringLiterals;

namespace Toffee {

LibraryStatusLabel::LibraryStatusLabel(HistoryRecorder *recorder, QWidget *parent)
    : QLabel(parent)
    , m_recorder(recorder)
{
    setObjectName(u"libraryStatusLabel"_s);
    setAccessibleName(tr("Library status"));
    setTextFormat(Qt::PlainText);
    connect(recorder, &HistoryRecorder::unavailable, this, &LibraryStatusLabel::refresh);
    connect(recorder, &HistoryRecorder::pendingChanged, this, &LibraryStatusLabel::refresh);
    connect(recorder, &HistoryRecorder::usesChanged, this, &LibraryStatusLabel::refresh);
    connect(recorder, &HistoryRecorder::available, this, &LibraryStatusLabel::back);
    refresh();
}

void LibraryStatusLabel::refresh()
{
    const qsizetype waiting = m_recorder->pendingCount();
    const bool shared = m_recorder->location().isShared();
    if (!m_recorder->isAvailable()) {
        m_waitedMost = std::max(m_waitedMost, waiting);
        const Library *library = m_recorder->library();
        if (shared && library && library->isReadOnly()) // up, but this role may not write
            setText(waiting == 1 ? tr("Library read-only — 1 change kept on this station")
                                 : tr("Library read-only — %1 changes kept on this station").arg(waiting));
        else if (shared)
            setText(waiting == 1 ? tr("Library offline — 1 change waiting")
                                 : tr("Library offline — %1 changes waiting").arg(waiting));
        else
            setText(waiting == 1 ? tr("Library cannot be written — 1 change waiting")
                                 : tr("Library cannot be written — %1 changes waiting").arg(waiting));
        setToolTip(m_recorder->lastError());
        // The one state in the status bar that asks for attention: written in the palette's warning colour.
        setStyleSheet(u"QLabel { color: palette(bright-text); background: #b3261e; padding: 0 6px; }"_s);
        show();
        return;
    }
    setStyleSheet({});
    setToolTip({});
    if (!shared) {
        hide();
        return;
    }
    const Library *library = m_recorder->library();
    const QString name = m_recorder->location().displayName();
    setText(library && library->isReadOnly() ? tr("Library: %1 (read-only)").arg(name)
                                             : tr("Library: %1").arg(name));
    show();
}

void LibraryStatusLabel::back()
{
    const qsizetype written = std::exchange(m_waitedMost, 0);
    refresh();
    if (!m_recorder->location().isShared())
        return; // the window says it of its own file, in its words for measurements
    Q_EMIT announced(written == 0 ? tr("Library back: nothing was waiting")
            : written == 1        ? tr("Library back: 1 change written")
                                  : tr("Library back: %1 changes written").arg(written));
}

} // namespace Toffee
