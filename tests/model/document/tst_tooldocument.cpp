// SPDX-License-Identifier: GPL-3.0-or-later
#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "model/document/tooldocument.h"
#include "tests/support/testtables.h"

using namespace Toffee;
using Toffee::Test::tool;
using namespace Qt::StringLiterals;

class TestToolDocument : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void addRemoveAndEditUndoAndRedo()
    {
        ToolDocument doc;
        QAbstractItemModelTester tester(doc.model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
        QVERIFY(doc.addTool(tool(1)).ok());
        QVERIFY(doc.addTool(tool(2)).ok());
        QVERIFY(doc.editTool(2, tool(5, 20)).ok());
        doc.removeTools({ 1 });
        QCOMPARE(doc.table().size(), 1);
        QCOMPARE(doc.table().at(0).number, 5);

        doc.undoStack()->undo(); // remove
        QVERIFY(doc.table().contains(1));
        doc.undoStack()->undo(); // edit
        QCOMPARE(doc.table().find(2)->lengthGeometry, 10.0);
        QVERIFY(!doc.table().contains(5));
        doc.undoStack()->undo(); // add T2
        doc.undoStack()->undo(); // add T1
        QVERIFY(doc.table().isEmpty());
        QVERIFY(!doc.isModified());

        while (doc.undoStack()->canRedo())
            doc.undoStack()->redo();
        QCOMPARE(doc.table().size(), 1);
        QCOMPARE(doc.table().at(0).lengthGeometry, 20.0);
    }

    void aRefusedEditIsNotAnUndoStep()
    {
        ToolDocument doc;
        QVERIFY(doc.addTool(tool(1)).ok());
        QVERIFY(doc.addTool(tool(2)).ok());
        const int steps = doc.undoStack()->count();
        QVERIFY(!doc.addTool(tool(1)).ok());
        QVERIFY(!doc.editTool(1, tool(2)).ok());
        QVERIFY(!doc.editTool(1, tool(1, 1e9)).ok());
        QCOMPARE(doc.undoStack()->count(), steps);
    }

    void anEditFromAViewIsOneUndoStep()
    {
        ToolDocument doc;
        QVERIFY(doc.addTool(tool(3)).ok());
        ToolTableModel *model = doc.model();
        QVERIFY(model->setData(model->index(0, ToolTableModel::LengthWearColumn), u"-0.05"_s));
        QCOMPARE(doc.table().at(0).lengthWear, -0.05);
        QCOMPARE(doc.undoStack()->undoText(), u"Edit tool T3"_s);
        doc.undoStack()->undo();
        QCOMPARE(doc.table().at(0).lengthWear, 0.0);
        QVERIFY(!model->setData(model->index(0, ToolTableModel::LengthWearColumn), u"500"_s));
        QCOMPARE(doc.undoStack()->index(), 1);
    }

    void tracksUnsavedChanges()
    {
        QTemporaryDir dir;
        ToolDocument doc;
        QSignalSpy modified(&doc, &ToolDocument::modifiedChanged);
        QVERIFY(!doc.isModified());
        QVERIFY(doc.addTool(tool(1)).ok());
        QVERIFY(doc.isModified());
        QVERIFY(!doc.save().ok()); // untitled: Save As first
        const QString path = dir.filePath(u"t.json"_s);
        QVERIFY(doc.saveAs(path, TableFormat::Json).ok());
        QVERIFY(!doc.isModified());
        QCOMPARE(doc.filePath(), path);
        doc.undoStack()->undo();
        QVERIFY(doc.isModified()); // undoing past the save is a change too
        doc.undoStack()->redo();
        QVERIFY(!doc.isModified());
        QCOMPARE(modified.size(), 4);
    }

    void openingReplacesTheTableAndForgetsUndo()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"a.csv"_s);
        QVERIFY(saveTableFile(path, Test::awkwardTable(), TableFormat::Csv).ok());
        ToolDocument doc;
        QVERIFY(doc.addTool(tool(42)).ok());
        QVERIFY(doc.open(path).ok());
        QCOMPARE(doc.table(), Test::awkwardTable());
        QCOMPARE(doc.fileFormat(), TableFormat::Csv);
        QVERIFY(!doc.undoStack()->canUndo());
        QVERIFY(!doc.isModified());
    }

    void aFailedOpenKeepsTheTable()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"bad.tbl"_s);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("T1 P1\nT1 P2\n");
        f.close();
        ToolDocument doc;
        QVERIFY(doc.addTool(tool(42)).ok());
        const auto r = doc.open(path);
        QVERIFY(!r.ok());
        QCOMPARE(r.error().line, 2);
        QCOMPARE(doc.table().size(), 1);
        QVERIFY(doc.table().contains(42));
        QVERIFY(doc.undoStack()->canUndo());
    }

    void recoveredEditsAreOneUnsavedStepOnTopOfTheFile_data()
    {
        QTest::addColumn<QString>("original"); // "saved", "missing", "garbled" or "none"
        QTest::addColumn<QString>("notice"); // a fragment of what the operator is told; empty: nothing
        QTest::newRow("the file loads") << u"saved"_s << QString();
        QTest::newRow("the file is gone") << u"missing"_s << u"no longer exists"_s;
        QTest::newRow("the file does not load") << u"garbled"_s << u"does not load"_s;
        QTest::newRow("a table never saved") << u"none"_s << QString();
    }
    void recoveredEditsAreOneUnsavedStepOnTopOfTheFile()
    {
        QFETCH(QString, original);
        QFETCH(QString, notice);
        QTemporaryDir dir;
        const QString path = original == u"none" ? QString() : dir.filePath(u"tools.csv"_s);
        const ToolTable onDisk = Test::awkwardTable();
        if (original == u"saved")
            QVERIFY(saveTableFile(path, onDisk, TableFormat::Csv).ok());
        if (original == u"garbled") {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("number,pocket\n1,1\n1,2\n");
        }
        ToolTable edits = onDisk;
        QVERIFY(edits.insert(tool(77, 5.5)).ok());
        QVERIFY(edits.remove(2));

        ToolDocument doc;
        const QString told = doc.recoverEdits(edits, path, TableFormat::Csv);
        QCOMPARE(told.isEmpty(), notice.isEmpty());
        QVERIFY2(told.contains(notice), qPrintable(told));
        QCOMPARE(doc.table(), edits);
        QVERIFY(doc.isModified()); // the operator reviews, then saves
        QCOMPARE(doc.undoStack()->count(), 1);
        // Saving goes back to the file, except one Toffee cannot read, which is never saved over.
        QCOMPARE(doc.filePath(), original == u"garbled" ? QString() : path);
        doc.undoStack()->undo();
        QCOMPARE(doc.table(), original == u"saved" ? onDisk : ToolTable(edits.units()));
    }

    void importMergesAsOneUndoStep()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"more.tbl"_s);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("T2 P2 Z99\nT7 P7 Z7\n");
        f.close();
        ToolDocument doc;
        QVERIFY(doc.addTool(tool(1)).ok());
        QVERIFY(doc.addTool(tool(2)).ok());
        const auto count = doc.importFrom(path);
        QVERIFY2(count.ok(), qPrintable(count.error().text()));
        QCOMPARE(count.value(), 2);
        QCOMPARE(doc.table().size(), 3);
        QCOMPARE(doc.table().find(2)->lengthGeometry, 99.0);
        doc.undoStack()->undo();
        QCOMPARE(doc.table().size(), 2);
        QCOMPARE(doc.table().find(2)->lengthGeometry, 10.0);
    }

    void importRefusesOtherUnitsAndChangesNothing()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"inch.json"_s);
        QVERIFY(saveTableFile(path, Test::awkwardTable(Units::Inch), TableFormat::Json).ok());
        ToolDocument doc;
        QVERIFY(doc.addTool(tool(1)).ok());
        const ToolTable before = doc.table();
        const int steps = doc.undoStack()->count();
        const auto r = doc.importFrom(path);
        QVERIFY(!r.ok());
        QVERIFY(r.error().message.contains(u"does not convert units"_s));
        QCOMPARE(doc.table(), before);
        QCOMPARE(doc.undoStack()->count(), steps);
    }

    void aReplacedTableIsOneUndoStep()
    {
        ToolDocument doc;
        QAbstractItemModelTester tester(doc.model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
        QVERIFY(doc.addTool(tool(1)).ok());
        QVERIFY(doc.addTool(tool(2)).ok());
        doc.undoStack()->setClean();
        const ToolTable before = doc.table();
        ToolTable after = before;
        Tool changed = *after.find(2);
        changed.radiusGeometry = 3.0;
        QVERIFY(after.replace(2, changed).ok());
        QVERIFY(after.insert(tool(9)).ok());

        QVERIFY(doc.replaceTable(after, u"Import 2 tools from lib.json"_s));
        QCOMPARE(doc.undoStack()->count(), 3);
        QCOMPARE(doc.undoStack()->undoText(), u"Import 2 tools from lib.json"_s);
        QCOMPARE(doc.table(), after);
        QCOMPARE(doc.model()->rowCount(), 3);
        QVERIFY(doc.isModified());
        doc.undoStack()->undo();
        QCOMPARE(doc.table(), before);
        QCOMPARE(doc.model()->rowCount(), 2);
        QVERIFY(!doc.isModified());
        doc.undoStack()->redo();
        QCOMPARE(doc.table(), after);

        QVERIFY(!doc.replaceTable(after, u"nothing"_s));
        QCOMPARE(doc.undoStack()->count(), 3);
    }

    void aBrokenToolStaysMarkedUntilItIsProbed()
    {
        ToolDocument doc;
        const QDateTime at(QDate(2026, 11, 23), QTime(9, 0), Qt::UTC);
        QVERIFY(doc.recordMeasurement(2, -33.388, at).ok());
        QVERIFY(doc.recordMeasurement(2, -30.488, at.addSecs(60), TloSource::Manual).ok());
        QCOMPARE(doc.table().find(2)->tloSource, TloSource::Manual);
        QCOMPARE(*doc.table().find(2)->measuredTlo, -30.488);
        QCOMPARE(doc.undoStack()->undoText(), u"Set T2 TLO by hand"_s);

        QVERIFY(doc.recordBreakTest(2, true).ok());
        QVERIFY(doc.table().find(2)->breakTestFailed);
        // Setting the offset by hand is not measuring: the mark stays.
        QVERIFY(doc.recordMeasurement(2, -33.0, at.addSecs(120), TloSource::Manual).ok());
        QVERIFY(doc.table().find(2)->breakTestFailed);
        // A probe is: the mark goes, and the TLO is measured again.
        QVERIFY(doc.recordMeasurement(2, -33.388, at.addSecs(180)).ok());
        QVERIFY(!doc.table().find(2)->breakTestFailed);
        QCOMPARE(doc.table().find(2)->tloSource, TloSource::Probe);
        // Each was one undo step; undoing the probe brings the mark back.
        doc.undoStack()->undo();
        QVERIFY(doc.table().find(2)->breakTestFailed);
        // A passed test on an unmarked tool is no step at all.
        doc.undoStack()->redo();
        const int steps = doc.undoStack()->count();
        QVERIFY(doc.recordBreakTest(2, false).ok());
        QCOMPARE(doc.undoStack()->count(), steps);
        // A tool the table lacks is added, marked.
        QVERIFY(doc.recordBreakTest(7, true).ok());
        QVERIFY(doc.table().find(7)->breakTestFailed);
        QVERIFY(!doc.table().find(7)->measuredTlo);
    }

    void afterSavingAsTblTheWindowShowsWhatTheFileHolds()
    {
        QTemporaryDir dir;
        ToolDocument doc;
        QVERIFY(doc.open(QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json")).ok());
        QVERIFY(doc.recordBreakTest(2, true).ok());
        const ToolTable full = doc.table();
        QVERIFY(full.find(2)->measuredTlo);
        const QString path = dir.filePath(u"tools.tbl"_s);
        QVERIFY(doc.saveAs(path, TableFormat::LinuxCnc).ok());
        // Exactly what a reader of the file gets, saved and not modified: no TLO, no mark on screen.
        const auto onDisk = loadTableFile(path);
        QVERIFY(onDisk.ok());
        QCOMPARE(doc.table(), onDisk.value());
        QVERIFY(!doc.table().find(2)->measuredTlo);
        QVERIFY(!doc.table().find(2)->breakTestFailed);
        QVERIFY(!doc.isModified());
        QCOMPARE(doc.filePath(), path);
        // Undo brings back everything the file could not hold, as an unsaved change.
        doc.undoStack()->undo();
        QCOMPARE(doc.table(), full);
        QVERIFY(doc.isModified());
        // A format that loses nothing saves as it is, with no extra step.
        const int steps = doc.undoStack()->count();
        QVERIFY(doc.saveAs(dir.filePath(u"tools.json"_s), TableFormat::Json).ok());
        QCOMPARE(doc.undoStack()->count(), steps);
        QCOMPARE(doc.table(), full);
    }

    void newToolTakesTheNextFreeNumber()
    {
        ToolDocument doc;
        QVERIFY(doc.addTool(tool(1)).ok());
        QVERIFY(doc.addTool(tool(3)).ok());
        QCOMPARE(doc.newTool().number, 2);
        QCOMPARE(doc.newTool().pocket, 2);
    }
};

QTEST_GUILESS_MAIN(TestToolDocument)
#include "tst_tooldocument.moc"
