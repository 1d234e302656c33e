// SPDX-License-Identifier: GPL-3.0-or-later
// Machine tables shared through a real PostgreSQL server the test starts itself (PgCluster): the stories of
// tst_sharedtables with LISTEN/NOTIFY instead of polling, a role that may only read (a read-only window that
// still follows the others), and each wrong setting named while the station records into its own library.
#include <QAbstractItemView>
#include <QLineEdit>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

#include "tests/support/pgcluster.h"
#include "tests/ui/sharedtablestories.h"
#include "ui/common/appsettings.h"
#include "ui/history/historysettingsdialog.h"
#include "ui/library/librarystatuslabel.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

class TestSharedTablesPg : public QObject
{
    Q_OBJECT

    PgCluster m_cluster;
    QTemporaryDir m_home; // the password file
    int m_databases = 0;

    LibraryLocation location(const QString &user, const QString &database) const
    {
        return LibraryLocation::parse(m_cluster.url(user, database)).value();
    }
    // A database of its own for each story, owned by the role the stations log in as.
    LibraryLocation freshLibrary()
    {
        const QString name = u"shop%1"_s.arg(++m_databases);
        QString error;
        if (!m_cluster.createDatabase(name, u"toffee"_s, &error))
            qFatal("%s", qPrintable(error));
        return location(u"toffee"_s, name);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_sharedtablespg"_s);
        AppSettings().setMachineName(kMachine);
        QString error;
        QVERIFY2(m_cluster.start(&error), qPrintable(error));
        QVERIFY2(m_cluster.createRole(u"toffee"_s, u"s3cret"_s, true, &error), qPrintable(error));
        QVERIFY2(m_cluster.createRole(u"reader"_s, u"r3ad"_s, true, &error), qPrintable(error));
        QVERIFY2(m_cluster.createRole(u"wrongpw"_s, u"Corr3ct-pw"_s, true, &error), qPrintable(error));
        QVERIFY2(m_cluster.writePassFile(m_home.filePath(u"pgpass"_s),
                     { { u"*"_s, u"toffee"_s, u"s3cret"_s }, { u"*"_s, u"reader"_s, u"r3ad"_s },
                         { u"*"_s, u"wrongpw"_s, u"wrong-pw"_s } },
                     &error),
            qPrintable(error));
        qputenv("PGPASSFILE", m_home.filePath(u"pgpass"_s).toLocal8Bit());
    }

    void aTableSavedToTheLibraryOpensOnAnotherStation() { savedTableOpensOnAnotherStation(freshLibrary()); }
    void anEditSavedOnOneStationShowsOnTheOtherWithinASecond() { editShowsOnTheOtherStation(freshLibrary()); }
    void theSecondToSaveTheSameToolSeesBothAndChooses_data()
    {
        QTest::addColumn<bool>("keepMine");
        QTest::newRow("keeps mine") << true;
        QTest::newRow("takes theirs") << false;
    }
    void theSecondToSaveTheSameToolSeesBothAndChooses()
    {
        QFETCH(bool, keepMine);
        sameToolEditedOnBoth(freshLibrary(), keepMine);
    }
    void editsToDifferentToolsBothSaveWithoutAQuestion() { differentToolsEditedOnBoth(freshLibrary()); }
    void aProbeOnOneStationReachesTheOthersTableAndHistory()
    {
        measurementReachesTheOtherStation(freshLibrary());
    }

    void theStatusBarNamesTheSharedLibrary()
    {
        const LibraryLocation at = freshLibrary();
        LibraryStation a(at, u"Station A"_s);
        auto *label = a.window.findChild<LibraryStatusLabel *>(u"libraryStatusLabel"_s);
        QVERIFY(label && label->isVisible());
        QCOMPARE(label->text(), u"Library: "_s + at.displayName());
    }

    void aRoleThatMayOnlyReadGetsAReadOnlyWindowThatStillFollows()
    {
        const LibraryLocation at = freshLibrary();
        LibraryStation a(at, u"Station A"_s);
        QVERIFY(a.window.openFile(kExampleTable));
        a.saveToLibrary(kMachine);
        QString error;
        QVERIFY2(m_cluster.grantReadOnly(u"reader"_s, at.database, &error), qPrintable(error));

        LibraryStation r(location(u"reader"_s, at.database), u"Station R"_s);
        QVERIFY2(r.window.history()->library(), qPrintable(r.window.history()->lastError()));
        r.openMachineTable(kMachine);
        QCOMPARE(r.table(), a.table());
        auto *banner = r.window.findChild<QLabel *>(u"readOnlyBanner"_s);
        QVERIFY(banner && banner->isVisible());
        QVERIFY2(banner->text().contains(u"your role may read this library but not change it"_s),
            qPrintable(banner->text()));
        QVERIFY(r.window.windowTitle().contains(u"(read-only)"_s));
        QVERIFY(r.window.findChild<QLabel *>(u"libraryStatusLabel"_s)->text().endsWith(u"(read-only)"_s));
        QVERIFY(!r.action(u"actionSave"_s)->isEnabled());
        QVERIFY(!r.action(u"actionAddTool"_s)->isEnabled());
        QCOMPARE(r.window.toolTablePanel()->view()->editTriggers(), QAbstractItemView::NoEditTriggers);

        // What the others save still reaches it, and leaves nothing to undo or save.
        a.edit(5, [](Tool &t) { t.description = u"1/8\" O-flute, acrylic only"_s; });
        QVERIFY(!a.save().shown);
        QTRY_COMPARE_WITH_TIMEOUT(r.tool(5).description, u"1/8\" O-flute, acrylic only"_s, kLiveMs);
        QVERIFY(!r.document()->isModified());
        QVERIFY(!r.document()->undoStack()->canUndo());
    }

    // The server refuses the save (the role lost its rights since the table was opened): the operator reads
    // why, the library holds none of the edits, and the table on screen keeps them all.
    void aSaveTheServerRefusesIsSaidAndWritesNothing()
    {
        const LibraryLocation at = freshLibrary();
        LibraryStation a(at, u"Station A"_s);
        QVERIFY(a.window.openFile(kExampleTable));
        a.saveToLibrary(kMachine);
        a.edit(3, [](Tool &t) { t.notes = u"first"_s; });
        a.edit(6, [](Tool &t) { t.notes = u"second"_s; });
        QString error;
        QVERIFY2(
            m_cluster.exec(u"REVOKE UPDATE ON tools FROM toffee"_s, &error, at.database), qPrintable(error));
        QString said;
        answerNextBox(QMessageBox::Ok, &said);
        QVERIFY(!a.save().shown);
        QVERIFY2(said.contains(u"is read-only for toffee"_s), qPrintable(said));
        QVERIFY(said.contains(u"Nothing was written"_s));
        QVERIFY(a.document()->isModified());
        QCOMPARE(a.tool(3).notes, u"first"_s);
        QCOMPARE(a.tool(6).notes, u"second"_s);
        const ToolTable stored = libraryTable(at);
        QVERIFY(stored.find(3)->notes.isEmpty());
        QVERIFY(stored.find(6)->notes.isEmpty());
        QVERIFY2(
            m_cluster.exec(u"GRANT UPDATE ON tools TO toffee"_s, &error, at.database), qPrintable(error));
        QVERIFY(!a.save().shown);
        QVERIFY(!a.document()->isModified());
        QCOMPARE(libraryTable(at), a.table());
    }

    // Machine ▸ History Library… takes a URL as well as a file, and the window goes over to it.
    void theSettingsTakeAPostgresqlUrl()
    {
        const LibraryLocation at = freshLibrary();
        QTemporaryDir own;
        LibraryStation a(LibraryLocation { .path = own.filePath(u"l.sqlite"_s) }, u"Station A"_s);
        answering<HistorySettingsDialog>(
            [&](HistorySettingsDialog *dialog) {
                dialog->findChild<QLineEdit *>(u"libraryPathEdit"_s)
                    ->setText(m_cluster.url(u"toffee"_s, at.database));
                dialog->accept();
            },
            [&] { a.action(u"actionHistorySettings"_s)->trigger(); });
        QCOMPARE(AppSettings().libraryLocation(), at.text());
        QCOMPARE(a.window.history()->location(), at);
        QVERIFY(a.window.history()->library());
        QCOMPARE(
            a.window.findChild<QLabel *>(u"libraryStatusLabel"_s)->text(), u"Library: "_s + at.displayName());
        AppSettings().setLibraryLocation({});
    }

    void eachWrongSettingIsNamedAndTheOwnLibraryRecords_data()
    {
        QTest::addColumn<QString>("user");
        QTest::addColumn<QString>("database");
        QTest::addColumn<QString>("expected");
        QTest::newRow("wrong password") << u"wrongpw"_s << u"postgres"_s << u"password file"_s;
        QTest::newRow("unknown role") << u"ghost"_s << u"postgres"_s << u"password file"_s;
        QTest::newRow("missing database") << u"toffee"_s << u"nosuch"_s << u"has no database \"nosuch\""_s;
    }
    void eachWrongSettingIsNamedAndTheOwnLibraryRecords()
    {
        QFETCH(QString, user);
        QFETCH(QString, database);
        QFETCH(QString, expected);
        LibraryStation a(location(user, database), u"Station A"_s);
        auto *box = a.window.findChild<QMessageBox *>(u"libraryFailureBox"_s);
        QVERIFY(box && box->isVisible());
        QVERIFY2(box->text().contains(expected), qPrintable(box->text()));
        QVERIFY2(box->text().contains(u"own library"_s), qPrintable(box->text()));
        QVERIFY(!box->text().contains(u"wrong-pw"_s) && !box->text().contains(u"Corr3ct-pw"_s));
        QVERIFY2(a.status().contains(expected), qPrintable(a.status()));
        box->close();

        // The window goes on, recording into the station's own library.
        const LibraryLocation own = a.window.history()->outboxLocation();
        QCOMPARE(a.window.history()->location(), own);
        QVERIFY(a.window.history()->isAvailable());
        Recording probe;
        probe.tool = 1;
        probe.tlo = -12.5;
        probe.at = QDateTime::currentDateTimeUtc();
        a.window.history()->record(historyEvent(probe, kMachine));
        QCOMPARE(a.window.history()->pendingCount(), 0);
        auto events = a.window.history()->library()->history({ kMachine, 1, {}, 0 });
        QVERIFY(events && events.value().size() == 1);
        QCOMPARE(events.value().front().tlo, -12.5);
    }
};

QTEST_MAIN(TestSharedTablesPg)
#include "tst_sharedtablespg.moc"
