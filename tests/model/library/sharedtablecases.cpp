// SPDX-License-Identifier: GPL-3.0-or-later
#include "tests/model/library/sharedtablecases.h"

using namespace Qt::StringLiterals;

namespace Toffee::Test {

void SharedTableCases::aTableIsCreatedOnceAndReadBackWithVersions()
{
    const LibraryLocation where = freshLocation();
    auto a = station(where, u"A"_s);
    QVERIFY(a);
    QCOMPARE(a->tableMachines().value(), QStringList());
    auto created = a->createTable(u"C1"_s, threeTools());
    QVERIFY2(created, qPrintable(created.error().message));
    QCOMPARE(created.value().table(), threeTools());
    QCOMPARE(created.value().rows.size(), 3);
    QCOMPARE(created.value().rows.at(1).version, 1);
    QCOMPARE(created.value().rows.at(1).updatedBy, u"A"_s);
    auto again = a->createTable(u"C1"_s, ToolTable());
    QVERIFY(!again);
    QVERIFY2(again.error().message.contains(u"already has a tool table for C1"_s),
        qPrintable(again.error().message));
    QCOMPARE(a->readTable(u"C1"_s).value().table(), threeTools()); // the refused one changed nothing
    QCOMPARE(a->tableMachines().value(), QStringList { u"C1"_s });
    QVERIFY(!a->readTable(u"C2"_s));
}

void SharedTableCases::twoStationsEditingTheSameToolConflictAndDifferentToolsBothSave()
{
    const LibraryLocation where = freshLocation();
    auto a = station(where, u"A"_s);
    auto b = station(where, u"B"_s);
    QVERIFY(a && b);
    QVERIFY(a->createTable(u"C1"_s, threeTools()));
    // Both read version 1 of every tool. A changes T1; B changes T1 differently and T2.
    auto byA = a->writeTools(u"C1"_s, { { 1, tool(1, u"6 mm flat, reground"_s, 29.5), 1 } });
    QVERIFY2(byA, qPrintable(byA.error().message));
    QCOMPARE(byA.value().written.value(1), 2);
    QVERIFY(byA.value().conflicts.isEmpty());
    auto byB = b->writeTools(
        u"C1"_s, { { 1, tool(1, u"6 mm flat"_s, 31.0), 1 }, { 2, tool(2, u"3 mm ball"_s, 24.0), 1 } });
    QVERIFY2(byB, qPrintable(byB.error().message));
    QCOMPARE(byB.value().written.keys(), QList<int> { 2 }); // everything else saves
    QCOMPARE(byB.value().conflicts.size(), 1);
    const ToolConflict conflict = byB.value().conflicts.first();
    QCOMPARE(conflict.number, 1);
    QCOMPARE(conflict.theirs->lengthGeometry, 29.5); // the refused one sees both values
    QCOMPARE(conflict.mine->lengthGeometry, 31.0);
    QCOMPARE(conflict.theirVersion, 2);
    QCOMPARE(conflict.theirStation, u"A"_s);
    const StoredTable now = a->readTable(u"C1"_s).value();
    QCOMPARE(now.row(1)->tool->lengthGeometry, 29.5); // A's change was not lost
    QCOMPARE(now.row(2)->tool->lengthGeometry, 24.0);
    // A change to other fields than A's, made over the same version, merges in the library itself (an outbox
    // replayed long after it was made).
    Tool worn = tool(1, u"6 mm flat"_s, 30);
    worn.lengthWear = -0.03;
    auto merged = b->writeTools(u"C1"_s, { { 1, worn, 1, tool(1, u"6 mm flat"_s, 30) } });
    QVERIFY(merged && merged.value().conflicts.isEmpty());
    QCOMPARE(merged.value().merged.value(1)->lengthGeometry, 29.5); // A's
    QCOMPARE(merged.value().merged.value(1)->lengthWear, -0.03); // B's
    QCOMPARE(merged.value().written.value(1), 3);
    const ToolConflict again
        = b->writeTools(u"C1"_s, { { 1, conflict.mine, 1, tool(1, u"6 mm flat"_s, 30) } })
              .value()
              .conflicts.value(0);
    QCOMPARE(again.theirVersion, 3);
    // B keeps its own after seeing theirs: written over the version it saw.
    auto mine = b->writeTools(u"C1"_s, { { 1, conflict.mine, again.theirVersion } });
    QVERIFY(mine && mine.value().conflicts.isEmpty());
    QCOMPARE(a->readTable(u"C1"_s).value().row(1)->tool->lengthGeometry, 31.0);
    QCOMPARE(a->readTable(u"C1"_s).value().row(1)->version, 4);
}

void SharedTableCases::aRemovalAndATwiceAddedToolConflictToo()
{
    const LibraryLocation where = freshLocation();
    auto a = station(where, u"A"_s);
    auto b = station(where, u"B"_s);
    QVERIFY(a && b && a->createTable(u"C1"_s, threeTools()));
    QVERIFY(a->writeTools(u"C1"_s, { { 3, std::nullopt, 1 }, { 9, tool(9, u"A's T9"_s, 10), 0 } }));
    auto byB = b->writeTools(
        u"C1"_s, { { 3, tool(3, u"drill, sharpened"_s, 39), 1 }, { 9, tool(9, u"B's T9"_s, 11), 0 } });
    QVERIFY(byB);
    QCOMPARE(byB.value().conflicts.size(), 2);
    QCOMPARE(byB.value().conflicts.at(0).theirs, std::nullopt); // A removed it
    QCOMPARE(byB.value().conflicts.at(1).theirs->description, u"A's T9"_s);
    const StoredTable now = b->readTable(u"C1"_s).value();
    QVERIFY(!now.table().contains(3));
    QCOMPARE(now.row(3)->version, 2); // the removal has a version
    // The same change made on both sides is no conflict.
    auto same = b->writeTools(u"C1"_s, { { 9, tool(9, u"A's T9"_s, 10), 0 } });
    QVERIFY(same && same.value().conflicts.isEmpty());
}

void SharedTableCases::aMeasurementUpdatesItsToolOnceHoweverOftenItIsWritten()
{
    const LibraryLocation where = freshLocation();
    auto a = station(where, u"A"_s);
    QVERIFY(a && a->createTable(u"C1"_s, threeTools()));
    const HistoryEvent measured = probe(u"C1"_s, 2, -31.25);
    QCOMPARE(a->append({ measured }).value(), 1);
    StoredTable now = a->readTable(u"C1"_s).value();
    QCOMPARE(now.row(2)->tool->measuredTlo, -31.25);
    QCOMPARE(now.row(2)->tool->referenceMz, -72.5);
    QCOMPARE(now.row(2)->version, 2);
    // Written again after an unclear failure: neither a second event nor a second version.
    QCOMPARE(a->append({ measured }).value(), 0);
    QCOMPARE(a->readTable(u"C1"_s).value().row(2)->version, 2);
    QCOMPARE(a->history({ u"C1"_s, 2, {}, 0 }).value().size(), 1);
    HistoryEvent broken = probe(u"C1"_s, 2, -31.25);
    broken.kind = EventKind::BreakTest;
    broken.failed = true;
    broken.at = measured.at.addSecs(1); // the newest, whatever the clock's resolution
    QVERIFY(a->append({ broken }));
    QVERIFY(a->readTable(u"C1"_s).value().row(2)->tool->breakTestFailed);
    const auto newest = a->history({ u"C1"_s, std::nullopt, {}, 1 }); // LIMIT is bound, as every value
    QVERIFY(newest && newest.value().size() == 1 && newest.value().first().kind == EventKind::BreakTest);
    // A machine whose table is a file only gets the event.
    QCOMPARE(a->append({ probe(u"Mill"_s, 1, -5.0) }).value(), 1);
    QVERIFY(!a->readTable(u"Mill"_s));
}

// Station A's probe waited in its outbox (the library was busy) while station B probed the same tool later:
// when A's reaches the library, the history keeps both and the table keeps the newest, B's. A measurement
// dated in the future (a clock set wrong) is kept in the history and orders nothing.
void SharedTableCases::aLateMeasurementNeverOverwritesANewerOne()
{
    const LibraryLocation where = freshLocation();
    auto a = station(where, u"A"_s);
    auto b = station(where, u"B"_s);
    QVERIFY(a && b && a->createTable(u"C1"_s, threeTools()));
    HistoryEvent older = probe(u"C1"_s, 1, 43.04);
    HistoryEvent newer = probe(u"C1"_s, 1, 15.34);
    older.at = newer.at.addSecs(-600);
    QCOMPARE(b->append({ newer }).value(), 1);
    QCOMPARE(a->append({ older }).value(), 1);
    QCOMPARE(a->readTable(u"C1"_s).value().row(1)->tool->measuredTlo, 15.34);
    QCOMPARE(a->history({ u"C1"_s, 1, {}, 0 }).value().size(), 2);
    // A break test older than the TLO in the table says nothing of that TLO either.
    HistoryEvent oldTest = probe(u"C1"_s, 1, 43.04);
    oldTest.kind = EventKind::BreakTest;
    oldTest.failed = true;
    oldTest.at = older.at.addSecs(60);
    QCOMPARE(a->append({ oldTest }).value(), 1);
    QVERIFY(!a->readTable(u"C1"_s).value().row(1)->tool->breakTestFailed);
    // One dated in 2100 does not take the table over: the next real measurement still does.
    HistoryEvent future = probe(u"C1"_s, 1, 99.0);
    future.at = QDateTime(QDate(2100, 1, 1), QTime(0, 0), Qt::UTC);
    QCOMPARE(a->append({ future }).value(), 1);
    QCOMPARE(a->readTable(u"C1"_s).value().row(1)->tool->measuredTlo, 15.34);
    HistoryEvent latest = probe(u"C1"_s, 1, 15.32);
    latest.at = newer.at.addSecs(60);
    QCOMPARE(b->append({ latest }).value(), 1);
    QCOMPARE(a->readTable(u"C1"_s).value().row(1)->tool->measuredTlo, 15.32);
}

void SharedTableCases::documentsMergeFieldsAndAskOnlyForTheSameField()
{
    const LibraryLocation where = freshLocation();
    auto a = station(where, u"A"_s);
    auto b = station(where, u"B"_s);
    QVERIFY(a && b && a->createTable(u"C1"_s, threeTools()));
    ToolDocument docA;
    ToolDocument docB;
    docA.openLibraryTable(a->readTable(u"C1"_s).value());
    docB.openLibraryTable(b->readTable(u"C1"_s).value());
    Tool t1 = *docA.table().find(1);
    t1.description = u"6 mm flat, AlTiN"_s;
    QVERIFY(docA.editTool(1, t1));
    Tool t1b = *docB.table().find(1);
    t1b.lengthWear = -0.02;
    QVERIFY(docB.editTool(1, t1b));
    const ToolWrites writesA = docA.libraryWrites();
    QCOMPARE(writesA.writes.size(), 1);
    auto savedA = a->writeTools(writesA.machine, writesA.writes);
    docA.markWritten(writesA, savedA.value());
    QVERIFY(!docA.isModified());
    // B hears of it: different fields of T1 merge, and B's edit is still to be saved.
    QVERIFY(docB.takeRemote(b->readTable(u"C1"_s).value()).isEmpty());
    QCOMPARE(docB.table().find(1)->description, u"6 mm flat, AlTiN"_s);
    QCOMPARE(docB.table().find(1)->lengthWear, -0.02);
    const ToolWrites writesB = docB.libraryWrites();
    auto savedB = b->writeTools(writesB.machine, writesB.writes);
    QVERIFY(savedB && savedB.value().conflicts.isEmpty());
    docB.markWritten(writesB, savedB.value());
    QVERIFY(!docB.isModified());
    const Tool stored = *a->readTable(u"C1"_s).value().row(1)->tool;
    QCOMPARE(stored.description, u"6 mm flat, AlTiN"_s);
    QCOMPARE(stored.lengthWear, -0.02);
    // The same field on both: B is asked, keeps its own, and Save writes it over A's.
    Tool again = *docA.table().find(3);
    again.lengthGeometry = 41;
    QVERIFY(docA.editTool(3, again));
    docA.markWritten(docA.libraryWrites(), a->writeTools(u"C1"_s, docA.libraryWrites().writes).value());
    again.lengthGeometry = 42;
    QVERIFY(docB.editTool(3, again));
    const QList<ToolConflict> asked = docB.takeRemote(b->readTable(u"C1"_s).value());
    QCOMPARE(asked.size(), 1);
    QCOMPARE(asked.first().theirs->lengthGeometry, 41.0);
    docB.resolveConflict(asked.first(), true);
    auto kept = b->writeTools(u"C1"_s, docB.libraryWrites().writes);
    QVERIFY(kept && kept.value().conflicts.isEmpty());
    QCOMPARE(a->readTable(u"C1"_s).value().row(3)->tool->lengthGeometry, 42.0);
    // B saves before it heard of A's change to another field of T2: the library merges, and B's table shows
    // what was written, saved.
    Tool t2 = *docA.table().find(2);
    t2.radiusWear = 0.01;
    QVERIFY(docA.editTool(2, t2));
    QVERIFY(a->writeTools(u"C1"_s, docA.libraryWrites().writes));
    Tool t2b = *docB.table().find(2);
    t2b.notes = u"for aluminium"_s;
    QVERIFY(docB.editTool(2, t2b));
    const ToolWrites late = docB.libraryWrites();
    auto written = b->writeTools(late.machine, late.writes);
    QVERIFY(written && written.value().merged.contains(2));
    docB.markWritten(late, written.value());
    QCOMPARE(docB.table().find(2)->radiusWear, 0.01);
    QCOMPARE(docB.table().find(2)->notes, u"for aluminium"_s);
    QVERIFY(!docB.isModified());
}

void SharedTableCases::anotherStationsWriteIsSeenByTheWatcher()
{
    const LibraryLocation where = freshLocation();
    auto a = station(where, u"A"_s);
    auto b = station(where, u"B"_s);
    QVERIFY(a && b && a->createTable(u"C1"_s, threeTools()));
    LibraryWatcher watcher(b.get());
    QSignalSpy changed(&watcher, &LibraryWatcher::changed);
    QElapsedTimer clock;
    clock.start();
    QCOMPARE(a->append({ probe(u"C1"_s, 1, -30.0) }).value(), 1);
    QVERIFY(changed.wait(2000));
    const qint64 latency = clock.elapsed();
    qInfo("station A's probe reached station B's watcher in %lld ms", latency);
    QVERIFY2(latency < 1000, "within a second, as the issue asks");
    const QString machine = changed.first().first().toString();
    QVERIFY(machine.isEmpty() || machine == u"C1"_s);
    QCOMPARE(b->readTable(u"C1"_s).value().row(1)->tool->measuredTlo, -30.0);
}

} // namespace Toffee::Test
