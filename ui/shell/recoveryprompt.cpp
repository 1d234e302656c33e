// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/recoveryprompt.h"

#include <QFileInfo>
#include <QFontMetrics>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>

#include "model/document/autosave.h"
#include "model/document/tooldocument.h"
#include "ui/shell/mainwindow.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

enum class Choice { Recover, Discard, Later };

Choice ask(MainWindow *window, const AutoSave::Session &session, const ToolTable &edits)
{
    const QString when = QLocale().toString(session.savedAt, QLocale::ShortFormat);
    // However long a path the copy names, the prompt stays a prompt.
    const QString original
        = QFontMetrics(window->font()).elidedText(session.originalPath, Qt::ElideMiddle, 560);
    QMessageBox box(QMessageBox::Question, MainWindow::tr("Recover Unsaved Edits"),
        session.originalPath.isEmpty()
            ? MainWindow::tr("Toffee stopped before a new table was saved. Its last copy is from %1.")
                  .arg(when)
            : MainWindow::tr("Toffee stopped before the edits to %1 were saved. Their last copy is from %2.")
                  .arg(original, when),
        QMessageBox::NoButton, window);
    box.setInformativeText(
        MainWindow::tr("The copy holds %1 tools. Recover puts it on top of the file as it is "
                       "on disk, unsaved: review it, then save; Undo shows the file as it "
                       "was. Discard deletes the copy; Later keeps it for the next start.")
            .arg(edits.size()));
    QPushButton *recover = box.addButton(MainWindow::tr("&Recover"), QMessageBox::AcceptRole);
    recover->setObjectName(u"recoverButton"_s);
    QPushButton *discard = box.addButton(QMessageBox::Discard);
    discard->setObjectName(u"discardButton"_s);
    QPushButton *later = box.addButton(MainWindow::tr("&Later"), QMessageBox::RejectRole);
    later->setObjectName(u"laterButton"_s);
    box.setDefaultButton(recover);
    box.setEscapeButton(later);
    box.exec();
    return box.clickedButton() == recover ? Choice::Recover
        : box.clickedButton() == discard  ? Choice::Discard
                                          : Choice::Later;
}

} // namespace

bool offerRecovery(MainWindow *window)
{
    AutoSave *autoSave = window->autoSave();
    const QString directory = autoSave->directory();
    // A recovery copy is input like any other: what cannot be read is moved aside (never offered again,
    // never deleted), and the operator is told once, however many there were.
    QStringList quarantined;
    QStringList unmovable;
    QList<std::pair<AutoSave::Session, ToolTable>> recoverable;
    for (const AutoSave::Session &session : AutoSave::findRecoverable(directory, &quarantined, &unmovable)) {
        auto edits = AutoSave::load(session);
        if (!edits) {
            (AutoSave::quarantine(session) ? quarantined : unmovable)
                .append(QFileInfo(session.tablePath).completeBaseName());
            continue;
        }
        recoverable.append({ session, edits.takeValue() });
    }
    if (!quarantined.isEmpty() || !unmovable.isEmpty()) {
        QStringList where;
        if (!quarantined.isEmpty())
            where << MainWindow::tr("Copies moved to %2, never to be offered again: %1.")
                         .arg(quarantined.size())
                         .arg(AutoSave::quarantineDirectory(directory));
        if (!unmovable.isEmpty())
            where << MainWindow::tr(
                "Copies that could not be moved to %2 and were left, untouched, in %3 (look at "
                "them there, or remove them by hand): %1.")
                         .arg(unmovable.size())
                         .arg(AutoSave::quarantineDirectory(directory), directory);
        QMessageBox box(QMessageBox::Warning, MainWindow::tr("Recover Unsaved Edits"),
            MainWindow::tr("Some copies of unsaved edits could not be read (%1 in all), so they cannot be "
                           "recovered.")
                .arg(quarantined.size() + unmovable.size()),
            QMessageBox::Ok, window);
        box.setInformativeText(where.join(u' ') + u' ' + MainWindow::tr("Nothing else was changed."));
        box.exec();
    }
    for (auto &[session, edits] : recoverable) {
        switch (ask(window, session, edits)) {
        case Choice::Later:
            return false;
        case Choice::Discard:
            AutoSave::discard(session);
            continue;
        case Choice::Recover:
            break;
        }
        const QString notice
            = window->document()->recoverEdits(edits, session.originalPath, session.originalFormat);
        // The old copy goes only once this session's own copy holds the edits.
        if (autoSave->saveNow())
            AutoSave::discard(session);
        window->statusBar()->showMessage(MainWindow::tr("Recovered unsaved edits: review them, then save."));
        if (!notice.isEmpty())
            QMessageBox::information(window, MainWindow::tr("Recover Unsaved Edits"), notice);
        return true;
    }
    return false;
}

} // namespace Toffee
