// SPDX-License-Identifier: GPL-3.0-or-later

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QAbstractTextDocumentLayout>
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
#include <QScrollBar>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>

#include "model/document/tooldocument.h"
#include "model/document/tooltablemodel.h"
#include "model/modules.h"
#include "tests/support/messageboxes.h"
#include "tests/support/testtables.h"
#include "ui/common/appsettings.h"
#include "ui/shell/guidedialog.h"
#include "ui/shell/mainwindow.h"
#include "ui/table/exportdialog.h"
#include "ui/table/tooltablepanel.h"

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

    // Help ▸ About Toffee says the project's version, the one --version and the package say.
    void theAboutBoxSaysTheVersion()
    {
        MainWindow window;
        QString text;
        QTimer::singleShot(0, &window, [&text] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            QVERIFY(box && box->objectName() == u"aboutBox"_s);
            text = box->text();
            box->accept();
        });
        window.findChild<QAction *>(u"actionAbout"_s)->trigger();
        QCOMPARE(text, u"Toffee "_s + QStringLiteral(TOFFEE_VERSION));
    }

    // A TLO's marks are never cut off: set by hand and failed its break test, T1's cell shows the whole of
    // "6.500 (by hand) — BROKEN?", whether the mark comes while the table is on screen or is already in the
    // file opened before the window is (the firmware window's screenshot showed "BROKE…").
    void aTlosMarksAreNeverCutOff_data()
    {
        QTest::addColumn<bool>("inTheFile");
        QTest::newRow("recorded on screen") << false;
        QTest::newRow("in the file opened") << true;
    }
    void aTlosMarksAreNeverCutOff()
    {
        QFETCH(bool, inTheFile);
        QTemporaryDir dir;
        const QString path = dir.filePath(u"marked.json"_s);
        QVERIFY(QFile::copy(kExample, path));
        MainWindow window;
        QVERIFY(window.openFile(path));
        Tool t1 = *window.document()->table().find(1);
        t1.measuredTlo = 6.5;
        t1.tloSource = TloSource::Manual;
        t1.breakTestFailed = true;
        if (inTheFile) {
            QVERIFY(window.document()->editTool(1, t1).ok());
            QVERIFY(window.document()->save().ok());
            QVERIFY(window.openFile(path)); // filled again while the window is not yet shown
        }
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        if (!inTheFile)
            QVERIFY(window.document()->editTool(1, t1).ok());
        auto *view = window.findChild<QTableView *>(u"toolTable"_s);
        QModelIndex cell;
        for (int row = 0; row < view->model()->rowCount() && !cell.isValid(); ++row) {
            if (view->model()->index(row, ToolTableModel::NumberColumn).data().toInt() == 1)
                cell = view->model()->index(row, ToolTableModel::MeasuredTloColumn);
        }
        QCOMPARE(cell.data().toString(), u"6.500 (by hand) — BROKEN?"_s);
        // The text's own width and two characters of room: the item's size hint alone left "BROKE…".
        const int needed = view->fontMetrics().horizontalAdvance(cell.data().toString())
            + 2 * view->fontMetrics().averageCharWidth();
        QTRY_VERIFY2(view->columnWidth(ToolTableModel::MeasuredTloColumn) >= needed,
            qPrintable(u"%1 < %2"_s.arg(view->columnWidth(ToolTableModel::MeasuredTloColumn)).arg(needed)));
    }

    // F1 opens the user's guide, found beside the program as installed (the build tree has it where the
    // package puts it), rendered with its screenshots; a link to a page not installed says so; a missing
    // guide is a message with where it was looked for, never an empty window.
    void f1OpensTheUsersGuide()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTest::keyClick(&window, Qt::Key_F1);
        GuideDialog *guide = nullptr;
        QTRY_VERIFY((guide = window.findChild<GuideDialog *>(u"guideDialog"_s)) && guide->isVisible());
        QVERIFY(guide->loaded());
        QTextBrowser *browser = guide->browser();
        QVERIFY(browser->toPlainText().contains(u"Toffee — the user's guide"_s));
        QVERIFY(browser->toPlainText().contains(u"Break tests, and what to do after one"_s));
        const QVariant image = browser->document()->resource(
            QTextDocument::ImageResource, QUrl(u"screenshots/window-light.png"_s));
        QVERIFY2(
            image.isValid() && !image.value<QImage>().isNull(), "the guide's first screenshot is not shown");
        QVERIFY(guidePath().endsWith(u"/share/doc/toffee/guide/GUIDE.md"_s));
        const QString folder = qEnvironmentVariable("TOFFEE_SCREENSHOTS");
        if (!folder.isEmpty())
            QVERIFY(guide->grab().save(folder + u"/guide.png"_s));
        // Every chapter is there and reached by scrolling, each one further down than the one before; with
        // TOFFEE_SCREENSHOTS set, each page is saved as the reader sees it (docs/screenshots/guide-N.png).
        const QStringList chapters { u"1. First start"_s, u"2. Reaching the machine"_s,
            u"3. Probing a tool, and the reference"_s, u"4. Break tests, and what to do after one"_s,
            u"5. Restoring a known TLO"_s, u"6. New cutters and tool life"_s,
            u"7. Checking a job, and preparing it"_s, u"8. Tools from your CAM program"_s,
            u"9. The Carvera's rack"_s, u"10. A shop's library"_s };
        guide->resize(900, 700);
        int previous = -1;
        for (qsizetype i = 0; i < chapters.size(); ++i) {
            const QTextCursor heading = browser->document()->find(chapters.at(i));
            QVERIFY2(!heading.isNull(), qPrintable(chapters.at(i)));
            const int top
                = int(browser->document()->documentLayout()->blockBoundingRect(heading.block()).top());
            QVERIFY2(top > previous, qPrintable(chapters.at(i)));
            previous = top;
            const int before = browser->verticalScrollBar()->value();
            browser->verticalScrollBar()->setValue(top);
            // The last chapters share the last page: one picture of it.
            if (!folder.isEmpty() && (i == 0 || browser->verticalScrollBar()->value() != before))
                QVERIFY(guide->grab().save(folder + u"/guide-%1.png"_s.arg(i + 1)));
        }
        QVERIFY(browser->verticalScrollBar()->value() > 0);
        Q_EMIT browser->anchorClicked(QUrl(u"WINDOW.md"_s));
        auto *note = guide->findChild<QLabel *>(u"guideNote"_s);
        QTRY_VERIFY(note->isVisible());
        QVERIFY(note->text().contains(u"WINDOW.md is not installed with Toffee"_s));
        guide->close();

        GuideDialog missing(u"/nonexistent/GUIDE.md"_s);
        QVERIFY(!missing.loaded());
    }

    // View ▸ Language: kept for the next start, each language named in itself, the choice shown checked.
    void theLanguageIsASettingOfTheWindow()
    {
        AppSettings().setLanguage({});
        {
            MainWindow window;
            auto *system = window.findChild<QAction *>(u"actionLanguageSystem"_s);
            auto *german = window.findChild<QAction *>(u"actionLanguageGerman"_s);
            QVERIFY(system && german);
            QVERIFY(system->isChecked());
            QCOMPARE(german->text(), u"Deutsch"_s);
            german->trigger();
            QCOMPARE(AppSettings().language(), u"de"_s);
            QVERIFY(window.statusBar()->currentMessage().contains(u"Deutsch from its next start"_s));
        }
        MainWindow next;
        QVERIFY(next.findChild<QAction *>(u"actionLanguageGerman"_s)->isChecked());
        next.findChild<QAction *>(u"actionLanguageSystem"_s)->trigger();
        QVERIFY(AppSettings().language().isEmpty());
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
        window.findChild<QAction *>(u"actionRemoveTool"_s)->trigger(); // nothing measured: no question
        QCOMPARE(window.document()->table().size(), 6);
        QVERIFY(!window.document()->table().contains(7));

        // T1 holds a measured TLO: Delete asks, naming it; Cancel keeps it, Remove removes it, Undo brings it
        // back.
        QVERIFY(window.document()->table().find(1)->measuredTlo.has_value());
        window.toolTablePanel()->view()->selectRow(0);
        QCOMPARE(window.toolTablePanel()->selectedToolNumbers(), QList<int> { 1 });
        QString question;
        answerNextBox(QMessageBox::Cancel, &question);
        window.findChild<QAction *>(u"actionRemoveTool"_s)->trigger();
        QVERIFY2(question.contains(u"T1 has a measured TLO"_s), qPrintable(question));
        QVERIFY(window.document()->table().contains(1));
        answerNextBox(QMessageBox::NoButton, &question, u"removeToolsButton"_s);
        window.findChild<QAction *>(u"actionRemoveTool"_s)->trigger();
        QVERIFY(!window.document()->table().contains(1));
        window.findChild<QAction *>(u"actionUndo"_s)->trigger();
        QVERIFY(window.document()->table().find(1)->measuredTlo.has_value());
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
            // No key of its own beyond its label's mnemonic (Alt and the underlined letter: the halted
            // strip's Unlock, in every language), which no other control has (claimed above).
            QVERIFY2(b->shortcut().isEmpty() || b->shortcut() == QKeySequence::mnemonic(b->text()),
                qPrintable(button));
        }
        QCOMPARE(window.findChild<QAbstractButton *>(u"unlockButton"_s)->shortcut(),
            QKeySequence(Qt::ALT | Qt::Key_U));
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
