// SPDX-License-Identifier: GPL-3.0-or-later
// The window and its files (ui/shell/mainwindowfiles.cpp): edits a crash left behind, a full disk, a FIFO, a
// recovery folder of garbage, a file changed on disk.
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
#include "ui/shell/mainwindow.h"
#include "ui/shell/recoveryprompt.h"
#include "ui/table/exportdialog.h"
#include "ui/table/tooltablepanel.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::answerNextBox;

namespace {

const QString kExample = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

} // namespace

class TestMainWindowFiles : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_mainwindowfiles"_s);
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
};

QTEST_MAIN(TestMainWindowFiles)
#include "tst_mainwindowfiles.moc"
