// SPDX-License-Identifier: GPL-3.0-or-later
// File ▸ Import of CAM libraries in the window (ui/shell/mainwindowfiles.cpp): through the preview into the
// table as one undo step, Cancel, and a malformed library refused with its place.
#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QLineEdit>
#include <QPushButton>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>
#include <QUndoStack>

#include "model/document/tooldocument.h"
#include "model/document/tooltablemodel.h"
#include "tests/support/camfiles.h"
#include "tests/support/messageboxes.h"
#include "ui/shell/mainwindow.h"
#include "ui/table/importpreviewdialog.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using Toffee::Test::answerNextBox;

namespace {

const QString kExample = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

// The example's T2 at 8 mm instead of 6, its T3 as it is, and a new T12.
QByteArray library()
{
    return Test::zipArchive({ { "tools.json",
        Test::fusionLibrary(
            { Test::fusionTool(2, "6 mm flat end mill, 3 flutes", "millimeters", R"("DC": 8)"),
                Test::fusionTool(3, "2 mm ball nose", "millimeters", R"("DC": 2)"),
                Test::fusionTool(12, "10 mm roughing", "millimeters", R"("DC": 10, "LCF": 30)") }) } });
}

// Once the preview is up: its rows in `rows`, then a click on `button`.
void answerPreview(const QString &button, QStringList *rows, int attempts = 500)
{
    QTimer::singleShot(10, [=] {
        auto *dialog = qobject_cast<ImportPreviewDialog *>(QApplication::activeModalWidget());
        if (!dialog) {
            if (attempts > 0)
                answerPreview(button, rows, attempts - 1);
            return;
        }
        auto *list = dialog->findChild<QTreeWidget *>(u"importToolList"_s);
        for (int i = 0; list && i < list->topLevelItemCount(); ++i)
            *rows << list->topLevelItem(i)->text(0) + u' ' + list->topLevelItem(i)->text(1) + u' '
                    + list->topLevelItem(i)->text(3);
        dialog->findChild<QPushButton *>(button)->click();
    });
}

// Once the file dialog is up: its title and filters in `seen`, then `path` chosen in it.
void answerFileDialog(const QString &path, QString *seen, int attempts = 500)
{
    QTimer::singleShot(10, [=] {
        auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
        if (!dialog) {
            if (attempts > 0)
                answerFileDialog(path, seen, attempts - 1);
            return;
        }
        *seen = dialog->windowTitle() + u'\n' + dialog->nameFilters().join(u'\n');
        // The file's path typed into the name field and Enter, as a person without a mouse does.
        auto *name = dialog->findChild<QLineEdit *>(u"fileNameEdit"_s);
        QVERIFY(name);
        name->setText(path);
        QTest::keyClick(name, Qt::Key_Return);
    });
}

// What the table on screen shows in `column` for tool `number`.
QString shown(QTableView *view, int number, int column)
{
    QAbstractItemModel *model = view->model();
    for (int row = 0; row < model->rowCount(); ++row) {
        if (model->index(row, ToolTableModel::NumberColumn).data(ToolTableModel::ToolNumberRole).toInt()
            == number)
            return model->index(row, column).data().toString();
    }
    return {};
}

} // namespace

class TestMainWindowImport : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_mainwindowimport"_s);
    }

    void importsALibraryThroughThePreviewAndUndoRestoresIt()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"shop.tools"_s);
        QVERIFY(Test::writeFile(path, library()));
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(kExample));
        const ToolTable before = window.document()->table();
        auto *view = window.findChild<QTableView *>(u"toolTable"_s);
        QVERIFY(view);

        QStringList rows;
        answerPreview(u"importButton"_s, &rows);
        QVERIFY(window.importFile(path));
        QCOMPARE(rows,
            (QStringList {
                u"T2 Changed radius 3.000 → 4.000 mm\na new cutter (diameter 6.000 → 8.000 mm): the old "
                u"cutter's TLO 9.652 mm, its length, wear and break mark end; measure it before it cuts"_s,
                u"T3 Unchanged "_s,
                u"T12 New pocket 12; no tool length yet (0 in the table): measure it before use"_s }));
        QCOMPARE(view->model()->rowCount(), 7);
        QCOMPARE(shown(view, 2, ToolTableModel::RadiusGeometryColumn), u"4.000"_s);
        // T2 is now an 8 mm cutter: the 6 mm cutter's TLO is not its own.
        QCOMPARE(shown(view, 2, ToolTableModel::MeasuredTloColumn), u"not measured"_s);
        // Nor its length (71.488, the 6 mm cutter's), which G43 would apply on LinuxCNC or FANUC.
        QCOMPARE(shown(view, 2, ToolTableModel::LengthGeometryColumn), u"0.000"_s);
        QCOMPARE(shown(view, 12, ToolTableModel::DescriptionColumn), u"10 mm roughing"_s);
        QCOMPARE(shown(view, 12, ToolTableModel::LengthGeometryColumn), u"0.000"_s);
        QCOMPARE(window.document()->table().find(2)->measuredTlo, std::nullopt);
        QVERIFY2(window.statusBar()->currentMessage().contains(
                     u"1 new, 1 changed, 1 unchanged; a new cutter in 1 (measure before use)"_s),
            qPrintable(window.statusBar()->currentMessage()));

        auto *undo = window.findChild<QAction *>(u"actionUndo"_s);
        QVERIFY(undo && undo->isEnabled());
        QVERIFY2(undo->text().contains(u"Import tools from shop.tools"_s), qPrintable(undo->text()));
        undo->trigger();
        QCOMPARE(window.document()->table(), before);
        QCOMPARE(view->model()->rowCount(), 6);
        QCOMPARE(shown(view, 2, ToolTableModel::RadiusGeometryColumn), u"3.000"_s);
    }

    void theMenusImportToolsActionTakesALibrary()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"shop.tools"_s);
        QVERIFY(Test::writeFile(path, library()));
        MainWindow window;
        QVERIFY(window.openFile(kExample));
        auto *action = window.findChild<QAction *>(u"actionImport"_s);
        QVERIFY(action);
        QCOMPARE(action->text(), u"Import &Tools…"_s);
        QCOMPARE(action->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_I));
        QVERIFY(action->isEnabled());
        QString seen;
        QStringList rows;
        answerFileDialog(path, &seen);
        answerPreview(u"importButton"_s, &rows);
        action->trigger();
        QVERIFY2(seen.startsWith(u"Import Tools\n"_s) && seen.contains(u"*.tools"_s), qPrintable(seen));
        QCOMPARE(rows.size(), 3);
        QCOMPARE(window.document()->table().find(12)->description, u"10 mm roughing"_s);
        QCOMPARE(window.document()->table().find(12)->pocket, 12);
    }

    void cancelLeavesTheTableAsItWas()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"shop.tools"_s);
        QVERIFY(Test::writeFile(path, library()));
        MainWindow window;
        QVERIFY(window.openFile(kExample));
        const ToolTable before = window.document()->table();
        QStringList rows;
        answerPreview(u"importCancelButton"_s, &rows);
        QVERIFY(!window.importFile(path));
        QCOMPARE(rows.size(), 3);
        QCOMPARE(window.document()->table(), before);
        QVERIFY(!window.document()->undoStack()->canUndo());
    }

    void aMalformedLibraryIsRefusedWithItsPlace_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("contents");
        QTest::addColumn<QString>("place");
        QTest::newRow("hsmlib, nc number abc")
            << u"lib.hsmlib"_s
            << Test::hsmLibrary(Test::hsmTool(1).replace(u"nc number=\"1\""_s, u"nc number=\"abc\""_s))
            << u"lib.hsmlib: line 5: tool 1: its nc number is \"abc\", not a tool number."_s;
        QTest::newRow("zip without tools.json")
            << u"lib.tools"_s << Test::zipArchive({ { "readme.txt", "x" } })
            << u"lib.tools: the archive holds no tools.json"_s;
    }
    void aMalformedLibraryIsRefusedWithItsPlace()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, contents);
        QFETCH(QString, place);
        QTemporaryDir dir;
        const QString path = dir.filePath(name);
        QVERIFY(Test::writeFile(path, contents));
        MainWindow window;
        QVERIFY(window.openFile(kExample));
        const ToolTable before = window.document()->table();
        QString text;
        answerNextBox(QMessageBox::Ok, &text);
        QVERIFY(!window.importFile(path));
        QVERIFY2(text.contains(dir.filePath(place)), qPrintable(text));
        QVERIFY2(text.contains(u"Nothing was imported."_s), qPrintable(text));
        QCOMPARE(window.document()->table(), before);
        QVERIFY(!window.document()->undoStack()->canUndo());
    }

    void aToffeeTableIsStillMergedWithoutAPreview()
    {
        MainWindow window;
        window.document()->newTable();
        QVERIFY(window.importFile(kExample));
        QCOMPARE(window.document()->table().size(), 6);
    }
};

QTEST_MAIN(TestMainWindowImport)
#include "tst_mainwindowimport.moc"
