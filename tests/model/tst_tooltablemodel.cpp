// SPDX-License-Identifier: GPL-3.0-or-later
#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QTest>

#include "testtables.h"

#include "tooltablemodel.h"

using namespace Toffee;
using Toffee::Test::tool;
using namespace Qt::StringLiterals;

namespace {

ToolTable threeTools()
{
    return ToolTable::fromTools(
        { tool(2, 71.488, u"end mill"_s), tool(10, 41.25, u"ball nose"_s), tool(9, 45.0, u"V-bit"_s) },
        Units::Millimetre)
        .takeValue();
}

} // namespace

class TestToolTableModel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void passesTheModelTesterThroughEveryChange()
    {
        ToolTableModel model;
        QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        model.resetTable(threeTools());
        QVERIFY(model.insertTool(tool(5, 1)).ok());
        QVERIFY(model.replaceTool(5, tool(50, 2)).ok()); // moves the row
        QVERIFY(model.replaceTool(50, tool(1, 2)).ok()); // moves it to the top
        QVERIFY(model.replaceTool(1, tool(1, 3)).ok());
        QVERIFY(model.removeTool(9));
        QVERIFY(model.setData(model.index(0, ToolTableModel::LengthWearColumn), u"-0.05"_s));
        model.resetTable(ToolTable());
        QCOMPARE(model.rowCount(), 0);
    }

    void showsTotalLengthAsGeometryPlusWear()
    {
        ToolTableModel model;
        Tool t = tool(1, 100.0);
        t.lengthWear = -0.1;
        model.resetTable(ToolTable::fromTools({ t }, Units::Millimetre).takeValue());
        QCOMPARE(model.index(0, ToolTableModel::TotalLengthColumn).data().toString(), u"99.900"_s);
        QCOMPARE(model.index(0, ToolTableModel::TotalLengthColumn).data(Qt::EditRole).toDouble(), 99.9);
        QVERIFY(!(model.flags(model.index(0, ToolTableModel::TotalLengthColumn)) & Qt::ItemIsEditable));
        QVERIFY(model.flags(model.index(0, ToolTableModel::LengthWearColumn)) & Qt::ItemIsEditable);
        QVERIFY(!(model.flags(model.index(0, ToolTableModel::MeasuredTloColumn)) & Qt::ItemIsEditable));
    }

    void acceptsATypedValueAndADecimalComma()
    {
        ToolTableModel model;
        model.resetTable(threeTools());
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        QVERIFY(model.setData(model.index(0, ToolTableModel::LengthGeometryColumn), u"72,5"_s));
        QCOMPARE(model.table().find(2)->lengthGeometry, 72.5);
        QCOMPARE(changed.size(), 1);
        QVERIFY(model.setData(model.index(0, ToolTableModel::DescriptionColumn), u"  roughing  "_s));
        QCOMPARE(model.table().find(2)->description, u"roughing"_s);
    }

    void refusesABadEditWithAMessageAndKeepsTheTable_data()
    {
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QString>("message");
        QTest::newRow("not a number")
            << int(ToolTableModel::LengthGeometryColumn) << u"abc"_s << u"not a number"_s;
        QTest::newRow("wear out of range")
            << int(ToolTableModel::LengthWearColumn) << u"150"_s << u"out of range"_s;
        QTest::newRow("duplicate number")
            << int(ToolTableModel::NumberColumn) << u"10"_s << u"already in the table"_s;
        QTest::newRow("fractional number")
            << int(ToolTableModel::NumberColumn) << u"2.5"_s << u"whole number"_s;
        QTest::newRow("pocket out of range")
            << int(ToolTableModel::PocketColumn) << u"-3"_s << u"pocket -3"_s;
        QTest::newRow("empty length")
            << int(ToolTableModel::LengthGeometryColumn) << QString() << u"not a number"_s;
    }
    void refusesABadEditWithAMessageAndKeepsTheTable()
    {
        QFETCH(int, column);
        QFETCH(QString, typed);
        QFETCH(QString, message);
        ToolTableModel model;
        model.resetTable(threeTools());
        const ToolTable before = model.table();
        QSignalSpy rejected(&model, &ToolTableModel::editRejected);
        QVERIFY(!model.setData(model.index(0, column), typed));
        QCOMPARE(rejected.size(), 1);
        QVERIFY2(rejected.front().front().toString().contains(message),
            qPrintable(rejected.front().front().toString()));
        QCOMPARE(model.table(), before);
    }

    void handsAnEditToTheHandlerInsteadOfApplyingIt()
    {
        ToolTableModel model;
        model.resetTable(threeTools());
        Tool seenBefore;
        Tool seenAfter;
        int calls = 0;
        model.setEditHandler([&](const Tool &before, const Tool &after) {
            seenBefore = before;
            seenAfter = after;
            ++calls;
        });
        QVERIFY(model.setData(model.index(0, ToolTableModel::LengthWearColumn), u"-0.1"_s));
        QCOMPARE(calls, 1);
        QCOMPARE(seenBefore.lengthWear, 0.0);
        QCOMPARE(seenAfter.lengthWear, -0.1);
        QCOMPARE(model.table().find(2)->lengthWear, 0.0); // the handler decides; the model did not apply it
        QVERIFY(
            model.setData(model.index(0, ToolTableModel::LengthWearColumn), u"0"_s)); // no change: no call
        QCOMPARE(calls, 1);
    }

    void sortsNumbersAsNumbersThroughAProxy()
    {
        ToolTableModel model;
        model.resetTable(threeTools());
        QSortFilterProxyModel proxy;
        QAbstractItemModelTester tester(&proxy, QAbstractItemModelTester::FailureReportingMode::QtTest);
        proxy.setSourceModel(&model);
        proxy.setSortRole(ToolTableModel::SortRole);
        proxy.sort(ToolTableModel::NumberColumn, Qt::DescendingOrder);
        QCOMPARE(proxy.index(0, 0).data().toInt(), 10); // "10" < "9" as text; 10 > 9 as a number
        QCOMPARE(proxy.index(1, 0).data().toInt(), 9);
        proxy.sort(ToolTableModel::LengthGeometryColumn, Qt::AscendingOrder);
        QCOMPARE(proxy.index(0, 0).data().toInt(), 10);
        QCOMPARE(proxy.index(2, 0).data().toInt(), 2);
    }

    void filtersOnAnyColumn()
    {
        ToolTableModel model;
        model.resetTable(threeTools());
        QSortFilterProxyModel proxy;
        proxy.setSourceModel(&model);
        proxy.setFilterKeyColumn(-1);
        proxy.setFilterCaseSensitivity(Qt::CaseInsensitive);
        proxy.setFilterFixedString(u"BALL"_s);
        QCOMPARE(proxy.rowCount(), 1);
        QCOMPARE(proxy.index(0, 0).data(ToolTableModel::ToolNumberRole).toInt(), 10);
    }

    void headersAreTranslatable()
    {
        ToolTableModel model;
        QCOMPARE(model.headerData(ToolTableModel::TotalLengthColumn, Qt::Horizontal).toString(),
            u"Total length"_s);
        QCOMPARE(model.columnCount(), int(ToolTableModel::ColumnCount));
        QCOMPARE(model.rowCount(model.index(0, 0)), 0);
    }
};

QTEST_GUILESS_MAIN(TestToolTableModel)
#include "tst_tooltablemodel.moc"
