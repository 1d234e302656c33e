// SPDX-License-Identifier: GPL-3.0-or-later
#include <sys/stat.h>

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QHash>
#include <QHeaderView>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>

#include "model/document/autosave.h"
#include "model/document/tooldocument.h"
#include "model/document/tooltablemodel.h"
#include "tests/support/fulldisk.h"
#include "tests/support/messageboxes.h"
#include "tests/support/testtables.h"
#include "ui/exportdialog.h"
#include "ui/mainwindow.h"
#include "ui/recoveryprompt.h"
#include "ui/tooltablepanel.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::answerNextBox;

namespace {

const QString kExample = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

} // namespace

class TestMainWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_mainwindow"_s);
    }

    void opensATableAndShowsIt()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(kExample));
        auto *view = window.findChild<QTableView *>(u"toolTable"_s);
        QVERIFY(view);
        QCOMPARE(view->model()->rowCount(), 6);
        QVERIFY(window.windowTitle().startsWith(u"example.json"_s));
        QCOMPARE(window.findChild<QLabel *>(u"toolCountLabel"_s)->text(), u"6 tools"_s);
    }

    void editsACellByKeyboardAndUndoes()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(kExample));
        auto *view = window.findChild<QTableView *>(u"toolTable"_s);
        view->setFocus();
        view->setCurrentIndex(view->model()->index(1, ToolTableModel::LengthWearColumn));
        QTest::keyClick(view, Qt::Key_F2);
        auto *editor = view->findChild<QLineEdit *>(u"cellEditor"_s);
        QVERIFY(editor);
        editor->selectAll();
        QTest::keyClicks(editor, u"-0.05"_s);
        QTest::keyClick(editor, Qt::Key_Return); // the delegate commits on the next event-loop turn
        QTRY_COMPARE(window.document()->table().find(2)->lengthWear, -0.05);
        QVERIFY(window.isWindowModified());

        window.findChild<QAction *>(u"actionUndo"_s)->trigger();
        QCOMPARE(window.document()->table().find(2)->lengthWear, 0.0);
        QVERIFY(!window.isWindowModified());
    }

    void addsAndRemovesTools()
    {
        MainWindow window;
        window.show();
        QVERIFY(window.openFile(kExample));
        window.findChild<QAction *>(u"actionAddTool"_s)->trigger();
        QCOMPARE(window.document()->table().size(), 7);
        QVERIFY(window.document()->table().contains(7));
        QCOMPARE(window.toolTablePanel()->selectedToolNumbers(), QList<int> { 7 });
        window.findChild<QAction *>(u"actionRemoveTool"_s)->trigger();
        QCOMPARE(window.document()->table().size(), 6);
        QVERIFY(!window.document()->table().contains(7));
    }

    void filtersTheTable()
    {
        MainWindow window;
        window.show();
        QVERIFY(window.openFile(kExample));
        auto *filter = window.findChild<QLineEdit *>(u"toolFilter"_s);
        QTest::keyClicks(filter, u"drill"_s);
        auto *view = window.findChild<QTableView *>(u"toolTable"_s);
        QCOMPARE(view->model()->rowCount(), 1);
        QCOMPARE(view->model()->index(0, 0).data().toInt(), 6);
    }

    void aBadValueIsRefusedWithAMessage()
    {
        MainWindow window;
        window.show();
        QVERIFY(window.openFile(kExample));
        auto *view = window.findChild<QTableView *>(u"toolTable"_s);
        QString text;
        answerNextBox(QMessageBox::Ok, &text);
        QVERIFY(!view->model()->setData(view->model()->index(0, ToolTableModel::LengthWearColumn), u"250"_s));
        QVERIFY2(text.contains(u"out of range"_s), qPrintable(text));
        QCOMPARE(window.document()->table().find(1)->lengthWear, 0.0);
    }

    void unsavedChangesPromptBeforeClosing()
    {
        MainWindow window;
        window.show();
        QVERIFY(window.openFile(kExample));
        window.findChild<QAction *>(u"actionAddTool"_s)->trigger();
        QString text;
        answerNextBox(QMessageBox::Cancel, &text);
        QVERIFY(!window.close());
        QVERIFY(text.contains(u"not saved"_s));
        QVERIFY(window.isVisible());
        answerNextBox(QMessageBox::Discard);
        QVERIFY(window.close());
    }

    void offersTheEditsADeadToffeeLeft_data()
    {
        QTest::addColumn<QString>("answer");
        QTest::newRow("recover") << u"recover"_s;
        QTest::newRow("discard") << u"discard"_s;
        QTest::newRow("later") << u"later"_s;
    }
    void offersTheEditsADeadToffeeLeft()
    {
        QFETCH(QString, answer);
        QTemporaryDir dir;
        const QString table = dir.filePath(u"tools.json"_s);
        QVERIFY(QFile::copy(kExample, table));
        const auto contents = [&table] {
            QFile f(table);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        const QByteArray onDisk = contents();
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));

        // What a Toffee killed while editing tools.json leaves: its copy, and where the edits belong.
        const QString recovery = window.autoSave()->directory();
        QDir(recovery).removeRecursively();
        QVERIFY(QDir().mkpath(recovery));
        const ToolTable original = loadTableFile(table).value();
        ToolTable edits = original;
        Tool added;
        added.number = 77;
        added.lengthGeometry = 12.5;
        QVERIFY(edits.insert(added).ok());
        const QString copy = recovery + u"/4242-dead.json"_s;
        QVERIFY(saveTableFile(copy, edits, TableFormat::Json).ok());
        QFile info(recovery + u"/4242-dead.info"_s);
        QVERIFY(info.open(QIODevice::WriteOnly));
        info.write(
            QJsonDocument(QJsonObject { { u"original_path"_s, table }, { u"original_format"_s, u"json"_s } })
                .toJson());
        info.close();

        QString text;
        answerNextBox(QMessageBox::NoButton, &text, answer + u"Button"_s);
        const bool recovered = offerRecovery(&window);
        QVERIFY2(text.contains(table) && text.contains(u"holds 7 tools"_s), qPrintable(text));
        QCOMPARE(recovered, answer == u"recover");
        QCOMPARE(QFileInfo::exists(copy), answer == u"later"); // Later keeps it for the next start
        if (answer == u"later")
            QCOMPARE(AutoSave::findRecoverable(recovery).size(), 1);
        if (answer != u"recover") {
            QVERIFY(window.document()->table().isEmpty());
            QVERIFY(!window.isWindowModified());
            return;
        }
        QCOMPARE(window.document()->table(), edits);
        QCOMPARE(window.document()->filePath(), table);
        QVERIFY(window.isWindowModified()); // recovered, not saved: the operator reviews, then saves
        QVERIFY(window.statusBar()->currentMessage().contains(u"Recovered unsaved edits"_s));
        QVERIFY(QFileInfo::exists(window.autoSave()->tablePath())); // and they are protected again at once
        window.findChild<QAction *>(u"actionUndo"_s)->trigger();
        QCOMPARE(window.document()->table(), original);
        QCOMPARE(contents(), onDisk);
        window.document()->undoStack()->setClean(); // nothing to ask about on closing
    }

    void aSaveOnAFullDiskSaysSoAndKeepsTheFile()
    {
        // The operator edits a table on a disk that has filled up, and presses Save: the window says why it
        // could not, the file is as it was, and the edits are still there, unsaved.
        Test::FullDisk disk;
        const QString path = disk.path(u"tools.json"_s);
        QVERIFY(QFile::copy(kExample, path));
        QFile::setPermissions(path, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        const QByteArray before = [&path] {
            QFile f(path);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        }();
        MainWindow window;
        window.show();
        QVERIFY(window.openFile(path));
        disk.fill();
        for (int i = 0; i < 40; ++i) // more than the bytes a full disk could hold of it
            window.findChild<QAction *>(u"actionAddTool"_s)->trigger();
        QString text;
        answerNextBox(QMessageBox::Ok, &text);
        window.findChild<QAction *>(u"actionSave"_s)->trigger();
        QVERIFY2(text.contains(disk.reason()) && text.contains(u"old file is unchanged"_s), qPrintable(text));
        QVERIFY(!window.statusBar()->currentMessage().startsWith(u"Saved"_s));
        QVERIFY(window.isWindowModified());
        QCOMPARE(window.document()->table().size(), 46);
        QFile after(path);
        QVERIFY(after.open(QIODevice::ReadOnly));
        QCOMPARE(after.readAll(), before);
        window.document()->undoStack()->setClean();
    }

    void aFifoInTheTablesPlaceIsRefusedAtOnce()
    {
        // `toffee f.json` with a FIFO once blocked before any window appeared.
        QTemporaryDir dir;
        const QString path = dir.filePath(u"f.json"_s);
        QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
        MainWindow window;
        window.show();
        QString text;
        answerNextBox(QMessageBox::Ok, &text);
        QElapsedTimer clock;
        clock.start();
        QVERIFY(!window.openFile(path));
        QVERIFY(clock.elapsed() < 5000);
        QVERIFY2(text.contains(u"named pipe (FIFO)"_s) && text.contains(path), qPrintable(text));
        QVERIFY(window.document()->table().isEmpty());
    }

    void aRecoveryFolderFullOfGarbageIsToldOnce()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QString recovery = window.autoSave()->directory();
        QDir(recovery).removeRecursively();
        QVERIFY(QDir().mkpath(recovery));
        // 50 copies a crash or another program garbled, and one good copy whose edits belong to /dev/zero.
        for (int i = 0; i < 50; ++i) {
            QFile garbled(recovery + u"/%1-garbled.json"_s.arg(1000 + i));
            QVERIFY(garbled.open(QIODevice::WriteOnly));
            garbled.write("{\"format\": \"toffee-tool-table\", \"version\": 1, \"tools\": [{\"num");
        }
        ToolTable edits;
        QVERIFY(edits.insert(Test::tool(5)).ok());
        QVERIFY(saveTableFile(recovery + u"/7-device.json"_s, edits, TableFormat::Json).ok());
        QFile info(recovery + u"/7-device.info"_s);
        QVERIFY(info.open(QIODevice::WriteOnly));
        info.write(R"({"original_path": "/dev/zero", "original_format": "json"})");
        info.close();

        // One warning for all fifty, then the good copy's question: Recover.
        QString warning;
        QString question;
        QString notice;
        answerNextBox(QMessageBox::Ok, &warning);
        QTimer::singleShot(300, [&] {
            answerNextBox(QMessageBox::NoButton, &question, u"recoverButton"_s);
            QTimer::singleShot(300, [&] { answerNextBox(QMessageBox::Ok, &notice); });
        });
        QVERIFY(offerRecovery(&window));
        QVERIFY2(
            warning.contains(u"(50 in all)"_s) && warning.contains(u"quarantine"_s), qPrintable(warning));
        QVERIFY2(question.contains(u"/dev/zero"_s), qPrintable(question));
        // /dev/zero is no table: the edits become a new table, never saved over a device.
        QVERIFY2(notice.contains(u"does not load"_s), qPrintable(notice));
        QCOMPARE(window.document()->table(), edits);
        QVERIFY(window.document()->filePath().isEmpty());
        QCOMPARE(QDir(AutoSave::quarantineDirectory(recovery)).entryList(QDir::Files).size(), 50);

        // The next start has nothing to say.
        bool asked = false;
        QTimer::singleShot(0, [&asked] {
            if (auto *box = QApplication::activeModalWidget()) {
                asked = true;
                box->close();
            }
        });
        QVERIFY(!offerRecovery(&window));
        QVERIFY(!asked);
        window.document()->undoStack()->setClean();
    }

    void noticesAChangeOnDiskAndReloads()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"tools.json"_s);
        QVERIFY(QFile::copy(kExample, path));
        QFile::setPermissions(path, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        MainWindow window;
        window.show();
        QVERIFY(window.openFile(path));
        window.findChild<QAction *>(u"actionAddTool"_s)->trigger();
        window.findChild<QAction *>(u"actionSave"_s)->trigger();
        QTest::qWait(400); // Toffee's own save is not a change from outside: no question, nothing reloaded
        QVERIFY(!QApplication::activeModalWidget());
        QCOMPARE(window.document()->table().size(), 7);

        QString text;
        answerNextBox(QMessageBox::Yes, &text);
        QFile other(path); // another program rewrites the table
        QVERIFY(other.open(QIODevice::WriteOnly | QIODevice::Truncate));
        other.write(
            R"({"format": "toffee-tool-table", "version": 1, "units": "mm", "tools": [{"number": 42}]})");
        other.close();
        QTRY_VERIFY_WITH_TIMEOUT(text.contains(u"changed by another program"_s), 5000);
        QTRY_COMPARE(window.document()->table().size(), 1);
        QVERIFY(window.document()->table().contains(42));
    }

    void exportsForAControllerWithAPreview()
    {
        MainWindow window;
        window.show();
        QVERIFY(window.openFile(kExample));
        QTemporaryDir dir;
        const QString path = dir.filePath(u"offsets.nc"_s);
        QTimer::singleShot(0, [&] {
            auto *dialog = qobject_cast<ExportDialog *>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            dialog->selectDialect(u"fanuc"_s);
            auto *preview = dialog->findChild<QPlainTextEdit *>(u"exportPreview"_s);
            QVERIFY(preview->toPlainText().contains(u"G10 L10 P2 R71.488"_s));
            // The operator picks T3 only: the program writes T3 and nothing else.
            auto *tool = dialog->findChild<QComboBox *>(u"exportToolCombo"_s);
            tool->setCurrentIndex(tool->findData(3));
            QCOMPARE(preview->toPlainText().count(u"G10 L10 P"_s), 1);
            QVERIFY(preview->toPlainText().contains(u"G10 L10 P3 "_s));
            tool->setCurrentIndex(0);
            dialog->selectDialect(u"fagor"_s);
            QVERIFY(!dialog->findChild<QPushButton *>(u"exportSaveButton"_s)->isEnabled());
            QVERIFY(dialog->findChild<QLabel *>(u"exportProblem"_s)->text().contains(u"FAGOR"_s));
            dialog->selectDialect(u"linuxcnc"_s);
            QVERIFY(dialog->saveTo(path));
            dialog->accept();
        });
        window.findChild<QAction *>(u"actionExportProgram"_s)->trigger();
        QFile saved(path);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QVERIFY(saved.readAll().contains("G10 L1 P3 Z41.230 R1.000\n"));
    }

    void machineActionsWaitForAConnection()
    {
        MainWindow window;
        window.show();
        QVERIFY(!window.findChild<QAction *>(u"actionProbe"_s)->isEnabled());
        QVERIFY(!window.findChild<QAction *>(u"actionBreakTest"_s)->isEnabled());
        window.findChild<QAction *>(u"actionProbe"_s)->trigger(); // even forced: no question, nothing sent
        QVERIFY(!QApplication::activeModalWidget());
    }

    void everyControlHasAnAccessibleName()
    {
        MainWindow window;
        window.show();
        QStringList nameless;
        const auto widgets = window.findChildren<QWidget *>();
        for (QWidget *w : widgets) {
            const bool control = qobject_cast<QAbstractButton *>(w) || qobject_cast<QLineEdit *>(w)
                || qobject_cast<QComboBox *>(w) || qobject_cast<QAbstractSpinBox *>(w)
                || qobject_cast<QAbstractItemView *>(w);
            if (!control || w->objectName().startsWith(u"qt_"_s) || !w->isVisibleTo(&window)
                || qobject_cast<QHeaderView *>(w)) // a header belongs to its table
                continue;
            if (qobject_cast<QLineEdit *>(w) && qobject_cast<QAbstractSpinBox *>(w->parentWidget()))
                continue; // a spin box's own editor: the spin box carries the name
            if (qobject_cast<QLineEdit *>(w) && qobject_cast<QComboBox *>(w->parentWidget()))
                continue;
            auto *button = qobject_cast<QAbstractButton *>(w);
            const QString name
                = w->accessibleName().isEmpty() && button ? button->text() : w->accessibleName();
            const auto *toolButton = qobject_cast<QToolButton *>(w);
            if (name.isEmpty() && !(toolButton && toolButton->defaultAction()))
                nameless << QString::fromLatin1(w->metaObject()->className()) + u' ' + w->objectName();
        }
        QVERIFY2(nameless.isEmpty(), qPrintable(nameless.join(u", "_s)));
    }

    void toolbarActionsHaveIconsThatRender()
    {
        MainWindow window;
        for (const char *name : { "actionNew", "actionOpen", "actionSave", "actionAddTool",
                 "actionRemoveTool", "actionUndo", "actionRedo", "actionProbe", "actionBreakTest",
                 "actionUnlock", "actionStop", "actionConnect" }) {
            auto *action = window.findChild<QAction *>(QString::fromLatin1(name));
            QVERIFY2(action, name);
            QVERIFY2(!action->icon().pixmap(24, 24).isNull(), name); // the SVG icon engine is there
        }
        QVERIFY(!window.windowIcon().pixmap(64, 64).isNull());
    }

    void everyKeyDoesOneThingAndEveryCommandHasOneKey()
    {
        // Probe once answered to F5 and Ctrl+P, Unlock to Ctrl+Shift+U and Ctrl+Shift+L.
        MainWindow window;
        QHash<QString, QString> owner; // key sequence -> who has it
        const auto claim = [&owner](const QKeySequence &key, const QString &who) {
            if (key.isEmpty())
                return;
            const QString k = key.toString();
            QVERIFY2(!owner.contains(k), qPrintable(k + u" for "_s + who + u" and "_s + owner.value(k)));
            owner.insert(k, who);
        };
        for (const QAction *action : window.findChildren<QAction *>())
            claim(action->shortcut(), action->objectName());
        for (const QAbstractButton *button : window.findChildren<QAbstractButton *>()) {
            if (!button->objectName().startsWith(u"qt_"_s))
                claim(button->shortcut(), button->objectName());
        }
        QCOMPARE(owner.value(QKeySequence(Qt::Key_F5).toString()), u"actionProbe"_s);
        QCOMPARE(owner.value(QKeySequence(Qt::Key_F6).toString()), u"actionBreakTest"_s);
        QCOMPARE(owner.value(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_U).toString()), u"actionUnlock"_s);
        for (const QString &button : { u"probeButton"_s, u"unlockButton"_s, u"runBreakTestButton"_s }) {
            auto *b = window.findChild<QAbstractButton *>(button);
            QVERIFY2(b, qPrintable(button));
            QVERIFY2(b->shortcut().isEmpty(), qPrintable(button));
        }
    }

    void everyActionHasAShortcutAndAName()
    {
        MainWindow window;
        const auto actions = window.findChildren<QAction *>();
        int named = 0;
        for (const QAction *action : actions) {
            if (action->objectName().startsWith(u"action"_s)) {
                ++named;
                QVERIFY2(!action->shortcut().isEmpty(), qPrintable(action->objectName()));
            }
        }
        QVERIFY(named >= 12);
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
