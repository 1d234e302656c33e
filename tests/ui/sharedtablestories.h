// SPDX-License-Identifier: GPL-3.0-or-later
// Two stations of a shop on one library, as operators live them: the same stories on an SQLite file
// (tst_sharedtables) and on a PostgreSQL server (tst_sharedtablespg).
#pragma once

#include <QElapsedTimer>
#include <QLabel>
#include <QMessageBox>
#include <QUndoStack>

#include "model/library/library.h"
#include "serial/machineconnection.h"
#include "tests/support/librarystation.h"
#include "tests/support/messageboxes.h"
#include "tests/support/station.h"
#include "ui/history/historydock.h"

namespace Toffee::Test {

using namespace Qt::StringLiterals;

inline const QString kMachine = QStringLiteral("Mill 1"); // the history's machine name as well (AppSettings)
constexpr int kLiveMs = 1000; // the "within a second"

// What the library holds now, read as a third program would.
inline ToolTable libraryTable(const LibraryLocation &at)
{
    auto library = Library::open(at);
    if (!library)
        qFatal("the library does not open: %s", qPrintable(library.error().message));
    auto stored = library.value()->readTable(kMachine);
    if (!stored)
        qFatal("the table cannot be read: %s", qPrintable(stored.error().message));
    return stored.value().table();
}

// Station A puts the example table in the library as Mill 1's; station B opens it.
inline void startShop(LibraryStation &a, LibraryStation &b)
{
    QVERIFY(a.window.openFile(kExampleTable));
    a.saveToLibrary(kMachine);
    QVERIFY(a.document()->isLibraryTable());
    QCOMPARE(a.document()->libraryMachine(), kMachine);
    QVERIFY(!a.document()->isModified());
    QStringList listed;
    b.openMachineTable(kMachine, &listed);
    QVERIFY(listed.contains(kMachine));
    QCOMPARE(b.document()->libraryMachine(), kMachine);
    QCOMPARE(b.table(), a.table());
}

inline void savedTableOpensOnAnotherStation(const LibraryLocation &at)
{
    LibraryStation a(at, u"Station A"_s), b(at, u"Station B"_s);
    startShop(a, b);
    if (QTest::currentTestFailed())
        return;
    QVERIFY(a.window.windowTitle().startsWith(kMachine + u" — "_s + at.displayName()));
    QVERIFY(b.window.windowTitle().startsWith(kMachine + u" — "_s));
    QCOMPARE(libraryTable(at), a.table());
    // A second table of that name is refused, and the table on screen stays the library's.
    QString refusal;
    answerNextBox(QMessageBox::Ok, &refusal);
    b.saveToLibrary(kMachine);
    QVERIFY2(refusal.contains(kMachine), qPrintable(refusal));
    QCOMPARE(b.document()->libraryMachine(), kMachine);
}

inline void editShowsOnTheOtherStation(const LibraryLocation &at)
{
    LibraryStation a(at, u"Station A"_s), b(at, u"Station B"_s);
    startShop(a, b);
    if (QTest::currentTestFailed())
        return;
    a.edit(1, [](Tool &t) { t.description = u"Reference, reground"_s; });
    QVERIFY(a.window.isWindowModified());
    QElapsedTimer latency;
    QVERIFY(!a.save().shown);
    latency.start();
    QVERIFY(!a.document()->isModified());
    QTRY_COMPARE_WITH_TIMEOUT(b.tool(1).description, u"Reference, reground"_s, kLiveMs);
    qInfo("station to station: %lld ms", qint64(latency.elapsed()));
    // No question, nothing unsaved: B had no edit to T1. Undo stops at the update: undoing it would put A's
    // old description back, and B's next Save would write it over A's without a question.
    QVERIFY(!QApplication::activeModalWidget());
    QVERIFY(!b.document()->isModified());
    QVERIFY(!b.document()->undoStack()->canUndo());
    // The same with an edit of B's waiting: it stays, to be saved, and Undo cannot reach past A's change.
    b.edit(1, [](Tool &t) { t.notes = u"B's note"_s; });
    a.edit(1, [](Tool &t) { t.description = u"Reference, reground twice"_s; });
    QVERIFY(!a.save().shown);
    QTRY_COMPARE_WITH_TIMEOUT(b.tool(1).description, u"Reference, reground twice"_s, kLiveMs);
    QCOMPARE(b.tool(1).notes, u"B's note"_s);
    QVERIFY(b.document()->isModified());
    QVERIFY(!b.document()->undoStack()->canUndo());
    QVERIFY(!b.save().shown);
    QCOMPARE(libraryTable(at).find(1)->description, u"Reference, reground twice"_s);
    QCOMPARE(libraryTable(at).find(1)->notes, u"B's note"_s);
}

inline void sameToolEditedOnBoth(const LibraryLocation &at, bool keepMine)
{
    LibraryStation a(at, u"Station A"_s), b(at, u"Station B"_s);
    startShop(a, b);
    if (QTest::currentTestFailed())
        return;
    a.edit(2, [](Tool &t) { t.lengthGeometry = 70.5; });
    b.edit(2, [](Tool &t) { t.lengthGeometry = 72.25; });
    QVERIFY(!a.save().shown);
    // B hears of it at once, keeps its own edit, and is told what Save will ask.
    QTRY_VERIFY_WITH_TIMEOUT(b.status().contains(u"T2 was changed on Station A"_s), kLiveMs);
    QVERIFY(b.status().contains(u"Save to choose"_s));
    QCOMPARE(b.tool(2).lengthGeometry, 72.25);
    const ConflictsSeen seen = b.save({ { 2, keepMine } });
    QVERIFY(seen.shown);
    QCOMPARE(seen.tools, QList<int> { 2 });
    QVERIFY2(seen.theirs.front().contains(u"Station A"_s), qPrintable(seen.theirs.front()));
    QVERIFY2(seen.theirs.front().contains(u"70.500 mm"_s), qPrintable(seen.theirs.front()));
    QVERIFY2(seen.mine.front().contains(u"72.250 mm"_s), qPrintable(seen.mine.front()));
    QVERIFY(seen.mine.front().contains(u"6 mm flat end mill"_s)); // the description says which tool
    const double chosen = keepMine ? 72.25 : 70.5;
    QCOMPARE(b.tool(2).lengthGeometry, chosen);
    QVERIFY(!b.document()->isModified());
    QCOMPARE(libraryTable(at).find(2)->lengthGeometry, chosen);
    QTRY_COMPARE_WITH_TIMEOUT(a.tool(2).lengthGeometry, chosen, kLiveMs);
    QCOMPARE(a.table(), b.table());
}

inline void differentToolsEditedOnBoth(const LibraryLocation &at)
{
    LibraryStation a(at, u"Station A"_s), b(at, u"Station B"_s);
    startShop(a, b);
    if (QTest::currentTestFailed())
        return;
    a.edit(3, [](Tool &t) { t.notes = u"Chipped, ground back"_s; });
    b.edit(4, [](Tool &t) { t.lengthWear = -0.05; });
    QVERIFY(!a.save().shown);
    QVERIFY(!b.save().shown); // whether or not B heard of A's save first
    QVERIFY(!a.document()->isModified());
    QVERIFY(!b.document()->isModified());
    const ToolTable stored = libraryTable(at);
    QCOMPARE(stored.find(3)->notes, u"Chipped, ground back"_s);
    QCOMPARE(stored.find(4)->lengthWear, -0.05);
    QTRY_COMPARE_WITH_TIMEOUT(a.table(), stored, kLiveMs);
    QTRY_COMPARE_WITH_TIMEOUT(b.table(), stored, kLiveMs);
}

// A probes T1 on its machine: the measurement goes into the library with its event, and B's table and B's
// history of T1 show it without anyone saving.
inline void measurementReachesTheOtherStation(const LibraryLocation &at)
{
    LibraryStation a(at, u"Station A"_s), b(at, u"Station B"_s);
    startShop(a, b);
    if (QTest::currentTestFailed())
        return;
    b.window.toolTablePanel()->selectTool(1);
    b.window.historyDock()->raise();
    QTRY_VERIFY(b.window.historyDock()->isVisible());
    const qsizetype before = b.window.historyDock()->events().size();
    a.window.connection()->connectTo(ConnectionTarget {});
    QTRY_VERIFY(a.window.connection()->state() == MachineConnection::State::Connected);
    QTRY_VERIFY(a.window.connection()->canOperate());
    answerNextBox(QMessageBox::Yes);
    a.action(u"actionProbe"_s)->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!a.window.connection()->isBusy(), 10000);
    QElapsedTimer latency;
    latency.start();
    const QDateTime probed = a.tool(1).measuredAt;
    QVERIFY(probed > QDateTime::currentDateTimeUtc().addSecs(-60));
    QTRY_COMPARE_WITH_TIMEOUT(b.tool(1).measuredAt, probed, kLiveMs);
    qInfo("probe to the other station's table: %lld ms", qint64(latency.elapsed()));
    QCOMPARE(b.tool(1).measuredTlo, a.tool(1).measuredTlo);
    QTRY_COMPARE_WITH_TIMEOUT(b.window.historyDock()->events().size(), before + 1, kLiveMs);
    // The probe is in the library with its event: A has nothing left to save, B nothing to merge.
    QTRY_VERIFY(!a.document()->isModified());
    QVERIFY(!b.document()->isModified());
    QCOMPARE(libraryTable(at).find(1)->measuredAt, probed);
}

} // namespace Toffee::Test
