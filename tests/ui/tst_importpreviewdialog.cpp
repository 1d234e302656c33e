// SPDX-License-Identifier: GPL-3.0-or-later
// The preview of a CAM import (ui/table/importpreviewdialog.cpp): each tool with what happens to it, the
// counts, findable widgets, and the keyboard.
#include <QApplication>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTest>
#include <QTreeWidget>

#include "model/camimport/importpreview.h"
#include "ui/table/importpreviewdialog.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

CamTool camTool(int number, double diameter)
{
    CamTool tool;
    tool.number = number;
    tool.diameter = diameter;
    tool.description = u"Flat %1"_s.arg(number);
    return tool;
}

// T1 as the library has it, T2 with another radius; the library adds T7.
ImportPreview preview(const QList<CamTool> &tools = { camTool(1, 2.0), camTool(2, 6.0), camTool(7, 4.0) })
{
    Tool t1;
    t1.number = 1;
    t1.description = u"Flat 1"_s;
    t1.radiusGeometry = 1.0;
    Tool t2 = t1;
    t2.number = 2;
    t2.description = u"Flat 2"_s;
    auto table = ToolTable::fromTools({ t1, t2 }, Units::Millimetre);
    return ImportPreview::build(table.value(), CamLibrary { u"lib.json"_s, CamFormat::FusionJson, tools })
        .value();
}

} // namespace

class TestImportPreviewDialog : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void showsEachToolWithWhatHappensToIt()
    {
        ImportPreviewDialog dialog(preview(), u"/tmp/lib.json"_s, u"Fusion tool library (JSON)"_s);
        auto *list = dialog.findChild<QTreeWidget *>(u"importToolList"_s);
        QVERIFY(list);
        QCOMPARE(list->topLevelItemCount(), 3);
        const auto row = [list](int i) {
            QStringList texts;
            for (int c = 0; c < ImportPreviewDialog::ColumnCount; ++c)
                texts << list->topLevelItem(i)->text(c);
            return texts;
        };
        QCOMPARE(row(0), (QStringList { u"T1"_s, u"Unchanged"_s, u"Flat 1"_s, QString() }));
        // T2 was 2 mm across and the library's is 6 mm: another cutter, said on its row.
        QCOMPARE(row(1),
            (QStringList { u"T2"_s, u"Changed"_s, u"Flat 2"_s,
                u"radius 1.000 → 3.000 mm\na new cutter (diameter 2.000 → 6.000 mm): the old cutter's "
                u"length, wear and break mark end; measure it before it cuts"_s }));
        QCOMPARE(row(2),
            (QStringList { u"T7"_s, u"New"_s, u"Flat 7"_s,
                u"pocket 7; no tool length yet (0 in the table): measure it before use"_s }));
        const QString summary = dialog.findChild<QLabel *>(u"importSummary"_s)->text();
        QVERIFY2(summary.contains(
                     u"/tmp/lib.json (Fusion tool library (JSON)): 1 new, 1 changed, 1 unchanged; a new "
                     u"cutter in 1 (measure before use). "_s)
                && summary.contains(u"that tool's TLO, length, wear and break mark end"_s),
            qPrintable(summary));
        QVERIFY(dialog.findChild<QPushButton *>(u"importButton"_s)->isEnabled());
    }

    void showsTheSelectedToolsChangesWholeWithoutAMouse()
    {
        CamTool long2 = camTool(2, 6.0);
        long2.description = u"6 mm three-flute carbide end mill for aluminium, long reach, ZrN coated"_s;
        long2.fluteLength = 22;
        long2.overallLength = 75;
        long2.lengthOffset = 12;
        ImportPreviewDialog dialog(
            preview({ camTool(1, 2.0), long2, camTool(7, 4.0) }), u"lib.json"_s, u"Fusion"_s);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto *list = dialog.findChild<QTreeWidget *>(u"importToolList"_s);
        auto *details = dialog.findChild<QPlainTextEdit *>(u"importDetails"_s);
        QVERIFY(details);
        QVERIFY(!details->accessibleName().isEmpty());
        QVERIFY(details->isReadOnly());
        QTRY_COMPARE(QApplication::focusWidget(), list);
        QCOMPARE(details->toPlainText(),
            u"T1 (Unchanged): Flat 1\nThe table already has this tool as the library describes it."_s);

        QTest::keyClick(list, Qt::Key_Down);
        const QStringList expected {
            u"T2 (Changed): "_s + long2.description,
            u"• description “Flat 2” → “"_s + long2.description + u"”"_s, u"• radius 1.000 → 3.000 mm"_s,
            u"• CAM lengths added to the notes (flute length 22 mm, overall length 75 mm)"_s,
            u"• a new cutter (diameter 2.000 → 6.000 mm): the old cutter's length, wear and break mark end; "
            u"measure it before it cuts"_s,
            u"• the library gives length offset H12; Toffee always uses H = T (H2), so it is not imported"_s
        };
        QCOMPARE(details->toPlainText(), expected.join(u'\n'));
        // In the list each change is on a line of its own, in a column as wide as the longest.
        QCOMPARE(list->topLevelItem(1)->text(ImportPreviewDialog::FieldsColumn).count(u'\n'), 4);
        const QFontMetrics metrics(list->font());
        for (const QString &line :
            list->topLevelItem(1)->text(ImportPreviewDialog::FieldsColumn).split(u'\n'))
            QVERIFY2(metrics.horizontalAdvance(line) < list->columnWidth(ImportPreviewDialog::FieldsColumn),
                qPrintable(line));
        QVERIFY(list->visualItemRect(list->topLevelItem(1)).height() >= 4 * metrics.height());

        QTest::keyClick(list, Qt::Key_Down);
        QVERIFY2(details->toPlainText().startsWith(u"T7 (New): Flat 7\n• pocket 7"_s),
            qPrintable(details->toPlainText()));

        // Tab goes from the list to the details, then to Import; Return there still imports.
        QTest::keyClick(list, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), details);
        QTest::keyClick(details, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), dialog.findChild<QPushButton *>(u"importButton"_s));
    }

    void fitsItsContentsRatherThanEmptySpace()
    {
        ImportPreviewDialog dialog(preview(), u"lib.json"_s, u"Fusion"_s);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto *list = dialog.findChild<QTreeWidget *>(u"importToolList"_s);
        // Three rows: the list has room for them and little more.
        const QTreeWidgetItem *last = list->topLevelItem(2);
        const int rowsBottom = list->visualItemRect(last).bottom();
        QVERIFY2(rowsBottom > 0 && rowsBottom < list->viewport()->height(),
            qPrintable(u"%1 of %2"_s.arg(rowsBottom).arg(list->viewport()->height())));
        QVERIFY2(list->viewport()->height() - rowsBottom < 3 * list->visualItemRect(last).height(),
            qPrintable(u"%1 of %2"_s.arg(rowsBottom).arg(list->viewport()->height())));
        // Every change is shown whole in its column: none is elided.
        const int changes = list->columnWidth(ImportPreviewDialog::FieldsColumn);
        const QFontMetrics metrics(list->font());
        for (int i = 0; i < list->topLevelItemCount(); ++i) {
            for (const QString &line :
                list->topLevelItem(i)->text(ImportPreviewDialog::FieldsColumn).split(u'\n'))
                QVERIFY2(metrics.horizontalAdvance(line) < changes, qPrintable(line));
        }
    }

    void everyWidgetIsFindableAndNamed()
    {
        ImportPreviewDialog dialog(preview(), u"lib.json"_s, u"Fusion"_s);
        for (const QString &name : { u"importSummary"_s, u"importToolList"_s, u"importDetails"_s,
                 u"importButton"_s, u"importCancelButton"_s, u"importButtons"_s }) {
            auto *widget = dialog.findChild<QWidget *>(name);
            QVERIFY2(widget, qPrintable(name));
            QVERIFY2(!widget->accessibleName().isEmpty(), qPrintable(name));
        }
        QVERIFY(!dialog.accessibleName().isEmpty());
    }

    void theKeyboardImportsAndCancels_data()
    {
        QTest::addColumn<int>("key");
        QTest::addColumn<int>("result");
        QTest::newRow("Return imports") << int(Qt::Key_Return) << int(QDialog::Accepted);
        QTest::newRow("Escape cancels") << int(Qt::Key_Escape) << int(QDialog::Rejected);
    }
    void theKeyboardImportsAndCancels()
    {
        QFETCH(int, key);
        QFETCH(int, result);
        ImportPreviewDialog dialog(preview(), u"lib.json"_s, u"Fusion"_s);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QTRY_COMPARE(QApplication::focusWidget(), dialog.findChild<QTreeWidget *>(u"importToolList"_s));
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Down); // the list takes the arrows
        QTest::keyClick(QApplication::focusWidget(), Qt::Key(key));
        QCOMPARE(dialog.result(), result);
        QVERIFY(!dialog.isVisible());
    }

    void nothingToImportWhenEveryToolIsUnchanged()
    {
        ImportPreviewDialog dialog(preview({ camTool(1, 2.0) }), u"lib.json"_s, u"Fusion"_s);
        QVERIFY(!dialog.findChild<QPushButton *>(u"importButton"_s)->isEnabled());
        QVERIFY(
            dialog.findChild<QLabel *>(u"importSummary"_s)->text().contains(u"already has these tools"_s));
    }
};

QTEST_MAIN(TestImportPreviewDialog)
#include "tst_importpreviewdialog.moc"
