// SPDX-License-Identifier: GPL-3.0-or-later
#include <QAbstractItemModelTester>
#include <QLocale>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QTest>

#include "tests/support/testtables.h"

#include "model/document/tooltablemodel.h"
#include "model/timetext.h"

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

    void saysWhatWasNeverMeasuredSetByHandOrBroken()
    {
        ToolTableModel model;
        model.resetTable(Test::awkwardTable());
        auto tlo = [&model](int number, int role = Qt::DisplayRole) {
            return model.index(model.rowOfTool(number), ToolTableModel::MeasuredTloColumn).data(role);
        };
        QCOMPARE(tlo(0).toString(), u"not measured"_s); // not an empty cell that could pass for zero
        QVERIFY(!tlo(0, Qt::EditRole).isValid());
        QCOMPARE(tlo(1).toString(), u"0.000"_s);
        QCOMPARE(tlo(2).toString(), u"-33.388 (by hand) — BROKEN?"_s);
        QVERIFY(tlo(2, Qt::ToolTipRole).toString().contains(u"set on the machine by hand"_s));
        QVERIFY(tlo(2, Qt::ToolTipRole).toString().contains(u"failed its last break test"_s));
        // The broken tool's whole row stands out; the others do not.
        const QModelIndex brokenRow = model.index(model.rowOfTool(2), ToolTableModel::DescriptionColumn);
        QVERIFY(brokenRow.data(Qt::BackgroundRole).isValid());
        QVERIFY(!model.index(model.rowOfTool(1), ToolTableModel::DescriptionColumn)
                     .data(Qt::BackgroundRole)
                     .isValid());
        // The filter finds broken tools by what it shows.
        QSortFilterProxyModel proxy;
        proxy.setSourceModel(&model);
        proxy.setFilterKeyColumn(-1);
        proxy.setFilterCaseSensitivity(Qt::CaseInsensitive);
        proxy.setFilterFixedString(u"broken?"_s);
        QCOMPARE(proxy.rowCount(), 1);
    }

    void warnsOfTwoToolsInOnePocket()
    {
        ToolTableModel model;
        QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        QSignalSpy shared(&model, &ToolTableModel::pocketShared);
        auto inOwnPocket = [](int number) {
            Tool t = Test::tool(number);
            t.pocket = number;
            return t;
        };
        QVERIFY(model.insertTool(inOwnPocket(1)).ok());
        QVERIFY(model.insertTool(inOwnPocket(2)).ok());
        QCOMPARE(shared.count(), 0);
        Tool three = Test::tool(3);
        three.pocket = 2;
        QVERIFY(model.insertTool(three).ok()); // accepted, with a word
        QCOMPARE(shared.count(), 1);
        QCOMPARE(shared.at(0).at(0).toInt(), 3);
        QCOMPARE(shared.at(0).at(1).toInt(), 2);
        QCOMPARE(shared.at(0).at(2).value<QList<int>>(), QList<int> { 2 });
        auto pocket = [&model](int number, int role) {
            return model.index(model.rowOfTool(number), ToolTableModel::PocketColumn).data(role);
        };
        QVERIFY(pocket(2, Qt::ToolTipRole).toString().contains(u"also holds T3"_s));
        QVERIFY(pocket(2, Qt::ForegroundRole).isValid());
        QVERIFY(!pocket(1, Qt::ForegroundRole).isValid());
        // Moving T3 to its own pocket clears both.
        three.pocket = 3;
        QVERIFY(model.replaceTool(3, three).ok());
        QVERIFY(!pocket(2, Qt::ForegroundRole).isValid());
        QCOMPARE(shared.count(), 1);
        // Pocket 0 is a random changer's spindle: never "shared".
        Tool a = Test::tool(10);
        a.pocket = 0;
        Tool b = Test::tool(11);
        b.pocket = 0;
        QVERIFY(model.insertTool(a).ok());
        QVERIFY(model.insertTool(b).ok());
        QCOMPARE(shared.count(), 1);
        // Removing a tool keeps the count right.
        three.pocket = 1;
        QVERIFY(model.replaceTool(3, three).ok());
        QCOMPARE(shared.count(), 2);
        QVERIFY(model.removeTool(1));
        QVERIFY(!pocket(3, Qt::ForegroundRole).isValid());
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

    void showsWhenAToolWasMeasuredAsAnAgeAndMarksItStale()
    {
        const QDateTime now = QDateTime::currentDateTimeUtc();
        QCOMPARE(ageText(now.addSecs(-20), now), u"just now"_s);
        QCOMPARE(ageText(now.addSecs(-12 * 60), now), u"12 min ago"_s);
        QCOMPARE(ageText(now.addSecs(-3 * 3600 - 59), now), u"3 h ago"_s);
        QCOMPARE(ageText(now.addDays(-9), now), u"9 days ago"_s);
        Tool fresh { 1, 1, {}, 10, 0, 1, 0, -1.0, now.addSecs(-3 * 3600), {}, {} };
        Tool old { 2, 2, {}, 10, 0, 1, 0, -2.0, now.addDays(-8), {}, {} };
        Tool never { 3, 3, {}, 10, 0, 1, 0, {}, {}, {}, {} };
        ToolTableModel model;
        model.resetTable(ToolTable::fromTools({ fresh, old, never }, Units::Millimetre).takeValue());
        auto cell = [&model](int row, int role = Qt::DisplayRole) {
            return model.index(row, ToolTableModel::MeasuredAtColumn).data(role);
        };
        QCOMPARE(cell(0).toString(), u"3 h ago"_s);
        QCOMPARE(cell(1).toString(), u"8 days ago (stale)"_s);
        QVERIFY(cell(1, Qt::ForegroundRole).isValid());
        QVERIFY(!cell(0, Qt::ForegroundRole).isValid());
        QVERIFY(!cell(2).isValid()); // never measured: no age
        QCOMPARE(cell(1, Qt::ToolTipRole).toString(), // the full date, on hovering
            QLocale().toString(old.measuredAt.toLocalTime(), QLocale::LongFormat));
        QCOMPARE(cell(1, ToolTableModel::SortRole).toDateTime(), old.measuredAt);
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        model.setStaleAfterDays(10); // the setting: eight days is fresh again
        QCOMPARE(changed.size(), 1);
        QCOMPARE(cell(1).toString(), u"8 days ago"_s);
    }

    void showsEachToolsCuttingTime()
    {
        QCOMPARE(durationText(42), u"42 s"_s);
        QCOMPARE(durationText(25 * 60 + 10), u"25 min"_s);
        QCOMPARE(durationText(3 * 3600 + 5 * 60), u"3 h 05 min"_s);
        ToolTableModel model;
        model.resetTable(
            ToolTable::fromTools({ Test::tool(4), Test::tool(5) }, Units::Millimetre).takeValue());
        model.setUsedLife({ { model.table().tools().front().number, UsedLife { 754.5, 3 } } });
        const QModelIndex life = model.index(0, ToolTableModel::ToolLifeColumn);
        QCOMPARE(life.data().toString(), u"13 min"_s);
        QCOMPARE(life.data(ToolTableModel::SortRole).toDouble(), 754.5);
        QVERIFY(!model.index(1, ToolTableModel::ToolLifeColumn).data().isValid()); // none recorded
        QVERIFY(!life.data(Qt::ForegroundRole).isValid()); // no limit, no warning

        // The limit is what is typed into the column.
        QVERIFY(model.flags(life) & Qt::ItemIsEditable);
        QVERIFY(model.setData(life, u"13.5 min, 10 uses"_s));
        QCOMPARE(model.table().at(0).lifeLimitMinutes, std::optional(13.5));
        QCOMPARE(model.table().at(0).lifeLimitUses, std::optional(10));
        QCOMPARE(life.data(Qt::EditRole).toString(), u"13.5 min, 10 uses"_s);
        QCOMPARE(life.data().toString(), u"13 min of 13.5 min · 3 of 10 uses"_s);
        // 754.5 s of 810 s is 93 %: near its limit, said in orange and in words.
        QCOMPARE(life.data(Qt::ForegroundRole).value<QColor>(), QColor(0xb0, 0x50, 0x00));
        QVERIFY2(life.data(Qt::ToolTipRole).toString().contains(u"near its limit"_s),
            qPrintable(life.data(Qt::ToolTipRole).toString()));
        QVERIFY(model.setData(life, u"12 min"_s));
        QCOMPARE(model.table().at(0).lifeLimitUses, std::nullopt);
        QCOMPARE(life.data(Qt::ForegroundRole).value<QColor>(), QColor(0xc0, 0x1c, 0x28));
        QVERIFY(life.data(Qt::ToolTipRole).toString().contains(u"past its limit"_s));
        QVERIFY(model.setData(life, u"40 uses"_s));
        QCOMPARE(life.data().toString(), u"13 min · 3 of 40 uses"_s);
        QVERIFY(!life.data(Qt::ForegroundRole).isValid());
        // What is no life is refused, saying what to type; the limit stays.
        QSignalSpy rejected(&model, &ToolTableModel::editRejected);
        for (const QString &bad : { u"soon"_s, u"-5 min"_s, u"2.5 uses"_s, u"90 h"_s, u"0 min"_s })
            QVERIFY2(!model.setData(life, bad), qPrintable(bad));
        QCOMPARE(rejected.size(), 5);
        QVERIFY(rejected.constLast().at(0).toString().contains(u"\"40 uses\""_s));
        QCOMPARE(model.table().at(0).lifeLimitUses, std::optional(40));
        QVERIFY(model.setData(life, QString()));
        QCOMPARE(model.table().at(0).lifeLimitUses, std::nullopt);
    }

    void headersAreTranslatable()
    {
        ToolTableModel model;
        QCOMPARE(model.headerData(ToolTableModel::TotalLengthColumn, Qt::Horizontal).toString(),
            u"Total length"_s);
        QCOMPARE(model.columnCount(), int(ToolTableModel::ColumnCount));
        QCOMPARE(model.rowCount(model.index(0, 0)), 0);
        // Issue 30: the column holds TLOs set by hand too (marked so), so its name no longer says "Measured".
        QCOMPARE(model.headerData(ToolTableModel::MeasuredTloColumn, Qt::Horizontal).toString(), u"TLO"_s);
        QVERIFY(model.headerData(ToolTableModel::MeasuredTloColumn, Qt::Horizontal, Qt::ToolTipRole)
                    .toString()
                    .contains(u"set by hand"_s));
    }
};

QTEST_GUILESS_MAIN(TestToolTableModel)
#include "tst_tooltablemodel.moc"
