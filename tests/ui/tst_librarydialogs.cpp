// SPDX-License-Identifier: GPL-3.0-or-later
// The shared library's dialogs with the keyboard, and Machine ▸ History Library… showing the library the
// window works with: Tab reaches each tool's choice in the conflict dialog and then its buttons, and OK in
// History Library… with nothing changed leaves the window on the library --library gave it.
#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardPaths>
#include <QSysInfo>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include "model/document/tooldocument.h"
#include "model/library/historyrecorder.h"
#include "ui/common/appsettings.h"
#include "ui/history/historysettingsdialog.h"
#include "ui/library/conflictdialog.h"
#include "ui/shell/mainwindow.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

ToolConflict conflict(int number)
{
    Tool theirs;
    theirs.number = number;
    theirs.pocket = number;
    theirs.description = u"Tool %1"_s.arg(number);
    theirs.lengthGeometry = 40.0 + number;
    Tool mine = theirs;
    mine.lengthGeometry += 0.1;
    return {
        .number = number, .theirs = theirs, .mine = mine, .theirVersion = 2, .theirStation = u"bench-2"_s
    };
}

void press(QWidget *window, Qt::Key key)
{
    QTest::keyClick(QApplication::focusWidget() ? QApplication::focusWidget() : window, key);
}

} // namespace

class TestLibraryDialogs : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_librarydialogs"_s);
    }

    // The choices sit in the table's cells: Tab must go from one to the next, not move the table's
    // invisible current cell and stay on the first choice.
    void tabReachesEveryToolsChoiceThenTheButtons()
    {
        QList<ToolConflict> conflicts;
        for (int number = 1; number <= 12; ++number)
            conflicts << conflict(number);
        ConflictDialog dialog(conflicts, Units::Millimetre);
        dialog.show();
        QApplication::setActiveWindow(&dialog);
        QVERIFY(QTest::qWaitForWindowActive(&dialog));
        auto *first = dialog.findChild<QComboBox *>(u"conflictChoice1"_s);
        QCOMPARE(QApplication::focusWidget(), first);
        for (int number = 2; number <= 12; ++number) {
            press(&dialog, Qt::Key_Tab);
            auto *choice = dialog.findChild<QComboBox *>(u"conflictChoice%1"_s.arg(number));
            QCOMPARE(QApplication::focusWidget(), choice);
            // Reached below the fold, it is scrolled into view.
            QVERIFY(choice->visibleRegion().boundingRect().height() > 0);
        }
        // The last choice changed with the keyboard, the others kept.
        press(&dialog, Qt::Key_Down);
        QVERIFY(!dialog.keepsMine(12));
        QVERIFY(dialog.keepsMine(11));
        press(&dialog, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), dialog.findChild<QPushButton *>(u"conflictApplyButton"_s));
        press(&dialog, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget()->objectName(), u"conflictLaterButton"_s);
        press(&dialog, Qt::Key_Backtab);
        press(&dialog, Qt::Key_Backtab);
        QCOMPARE(QApplication::focusWidget(), dialog.findChild<QComboBox *>(u"conflictChoice12"_s));
    }

    // Tab follows the rows as they are shown: the library, Browse… beside it, the name, the days.
    void historyLibraryTabFollowsTheRows()
    {
        HistorySettingsDialog dialog;
        dialog.show();
        QApplication::setActiveWindow(&dialog);
        QVERIFY(QTest::qWaitForWindowActive(&dialog));
        auto *path = dialog.findChild<QLineEdit *>(u"libraryPathEdit"_s);
        path->setFocus();
        QCOMPARE(QApplication::focusWidget(), path);
        press(&dialog, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget()->objectName(), u"libraryBrowseButton"_s);
        press(&dialog, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), dialog.findChild<QLineEdit *>(u"machineNameEdit"_s));
        press(&dialog, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), dialog.findChild<QLineEdit *>(u"stationNameEdit"_s));
        press(&dialog, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), dialog.findChild<QSpinBox *>(u"staleDaysSpin"_s));
    }

    // The window was given a library (--library) other than the setting's: the dialog shows that one, and
    // OK with only the machine's name changed keeps the window on it.
    void historyLibraryShowsTheWindowsLibrary()
    {
        QTemporaryDir folder;
        const LibraryLocation setting { .path = folder.filePath(u"setting.sqlite"_s) };
        const LibraryLocation given { .path = folder.filePath(u"given.sqlite"_s) };
        AppSettings().setLibraryLocation(setting.text());
        MainWindow window;
        window.history()->setOutboxLocation({ .path = folder.filePath(u"own.sqlite"_s) });
        window.setLibrary(given);
        window.show();
        QString shown;
        QTimer::singleShot(0, &window, [&] {
            auto *dialog = qobject_cast<HistorySettingsDialog *>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            shown = dialog->findChild<QLineEdit *>(u"libraryPathEdit"_s)->text();
            dialog->findChild<QLineEdit *>(u"machineNameEdit"_s)->setText(u"C1"_s);
            // The station's name, shown empty (the computer's name as its placeholder) until one is set.
            auto *station = dialog->findChild<QLineEdit *>(u"stationNameEdit"_s);
            QVERIFY(station->text().isEmpty());
            QCOMPARE(station->placeholderText(), QSysInfo::machineHostName());
            station->setText(u"  Mill 2   PC "_s);
            dialog->accept();
        });
        window.findChild<QAction *>(u"actionHistorySettings"_s)->trigger();
        QCOMPARE(shown, given.path);
        QCOMPARE(window.history()->location(), given);
        QCOMPARE(AppSettings().libraryLocation(), given.text());
        QCOMPARE(AppSettings().machineName(), u"C1"_s);
        // Who the window now writes as: the name given, in the setting and in the library it opened.
        QCOMPARE(AppSettings().stationName(), u"Mill 2 PC"_s);
        QCOMPARE(window.history()->library()->station(), u"Mill 2 PC"_s);
        MainWindow next; // a window started later writes as it too
        next.history()->setOutboxLocation({ .path = folder.filePath(u"own2.sqlite"_s) });
        next.setLibrary(given);
        QCOMPARE(next.history()->library()->station(), u"Mill 2 PC"_s);
        AppSettings().setStationName({});

        // Without a library given, the setting's is shown, as before.
        HistorySettingsDialog plain;
        QCOMPARE(plain.findChild<QLineEdit *>(u"libraryPathEdit"_s)->text(), given.path);
        AppSettings().setLibraryLocation({});
        AppSettings().setMachineName({});
    }

    // toffee --library with a URL Toffee refuses: the window says so (nobody reads a desktop launcher's
    // stderr) and records into the station's own library.
    void aLibraryThatDoesNotParseIsSaidInTheWindow()
    {
        MainWindow window;
        window.show();
        const auto refused = LibraryLocation::parse(u"postgresql://shop:secret@server/tools"_s);
        QVERIFY(!refused);
        window.refuseLibrary(refused.error().message);
        QCOMPARE(window.history()->location(), LibraryLocation::standard());
        auto *box = window.findChild<QMessageBox *>(u"libraryFailureBox"_s);
        QVERIFY(box && box->isVisible());
        QVERIFY(box->text().contains(u"password file"_s));
        QVERIFY(!box->text().contains(u"secret"_s));
        QVERIFY(box->text().contains(u"own library"_s));
        box->close();
    }
};

QTEST_MAIN(TestLibraryDialogs)
#include "tst_librarydialogs.moc"
