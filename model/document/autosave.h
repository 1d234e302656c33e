// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include <QDateTime>
#include <QObject>
#include <QTimer>

#include "model/formats/tablefile.h"
#include "model/result.h"

class QLockFile;

namespace Toffee {

class ToolDocument;

// Keeps a copy of a document's unsaved edits where they outlive the application: a moment after an edit the
// table is written (through QSaveFile, in Toffee JSON, which holds everything) into `directory`, beside a
// lock that says a living process owns it. Saving, or undoing back to the saved state, removes the copy, and
// so does a normal exit, even one that discards the edits. A copy that is left belonged to a process that
// died.
class AutoSave final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(AutoSave)

public:
    // A copy left by a process that died, claimed (its lock held) so that no other Toffee offers it too.
    struct Session
    {
        QString tablePath; // the copy
        QString originalPath; // the file the edits were made to; empty for a table never saved
        TableFormat originalFormat = TableFormat::Json;
        QDateTime savedAt; // when the copy was last written
        std::shared_ptr<QLockFile> lock; // released when the last copy of the Session goes
    };

    static constexpr int kDefaultDelayMs = 2000;

    AutoSave(ToolDocument *document, const QString &directory, QObject *parent = nullptr);
    ~AutoSave() override;

    // <application data>/recovery
    [[nodiscard]] static QString defaultDirectory();
    [[nodiscard]] QString directory() const { return m_directory; }
    // Where this session's copy goes; it exists only while there are unsaved edits.
    [[nodiscard]] QString tablePath() const;
    // How long after an edit the copy is written: the first edit since the last write starts the clock,
    // so a steady stream of edits is still written every `milliseconds`.
    void setDelay(int milliseconds) { m_timer.setInterval(milliseconds); }
    // Writes the copy now (or removes it when there is nothing unsaved).
    Result<void> saveNow();

    // The copies that processes which died left in `directory`, newest first, each claimed. What a process
    // that died before its first copy left (a lock, an .info) is removed. The folder is input like any other:
    // a copy, .info or lock that is not a plain regular file, an .info that is too large or does not say
    // where the edits belong, is moved into quarantineDirectory() (never offered again) and its name added to
    // `*quarantined`. Nothing is ever deleted: a session whose files cannot be moved (the quarantine folder
    // cannot be made, a move fails) is left as it is, named in `*unmovable`.
    [[nodiscard]] static QList<Session> findRecoverable(
        const QString &directory, QStringList *quarantined = nullptr, QStringList *unmovable = nullptr);
    [[nodiscard]] static Result<ToolTable> load(const Session &session);
    // Deletes a recovered or unwanted copy.
    static void discard(const Session &session);
    // Moves a copy that cannot be recovered, with its .info, out of the way: into quarantineDirectory(),
    // where it is never offered again but stays for someone to look at.
    // False when they could not be moved: they are then left where they were.
    static bool quarantine(const Session &session);
    [[nodiscard]] static QString quarantineDirectory(const QString &directory);

    static constexpr qint64 kMaxInfoBytes = 64 * 1024;
    static constexpr qsizetype kMaxPathChars = 4096; // PATH_MAX

Q_SIGNALS:
    // A copy that could not be written: the edits are not protected until one is, or the table is saved.
    void failed(const QString &message);

private:
    void documentChanged();
    void removeCopy();
    [[nodiscard]] QString path(const char *suffix) const;

    ToolDocument *m_document;
    QString m_directory;
    QString m_id;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
};

} // namespace Toffee
