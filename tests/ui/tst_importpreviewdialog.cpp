// SPDX-License-Identifier: GPL-3.0-or-later
// The preview of a CAM import (ui/importpreviewdialog.cpp): each tool with what happens to it, the counts,
// findable widgets, and the keyboard.
#include <QApplication>
#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QTest>
#include <QTreeWidget>

#include "model/camimport/importpreview.h"
#include "ui/importpreviewdialog.h"

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
        QCOMPARE(row(1), (QStringList { u"T2"_s, u"Changed"_s, u"Flat 2"_s, u"radius 1.000 → 3.000 mm"_s }));
        QCOMPARE(row(2), (QStringList { u"T7"_s, u"New"_s, u"Flat 7"_s, QString() }));
        const QString summary = dialog.findChild<QLabel *>(u"importSummary"_s)->text();
        QVERIFY2(
            summary.contains(u"/tmp/lib.json (Fusion tool library (JSON)): 1 new, 1 changed, 1 unchanged."_s),
            qPrintable(summary));
        QVERIFY(dialog.findChild<QPushButton *>(u"importButton"_s)->isEnabled());
    }

    void everyWidgetIsFindableAndNamed()
    {
        ImportPreviewDialog dialog(preview(), u"lib.json"_s, u"Fusion"_s);
        for (const QString &name : { u"importSummary"_s, u"importToolList"_s, u"importButton"_s,
                 u"importCancelButton"_s, u"importButtons"_s }) {
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
