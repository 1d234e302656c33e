// SPDX-License-Identifier: GPL-3.0-or-later
// Machine tables shared through one SQLite library file: two real windows (offscreen) in one process, each
// its own station, see each other's saves and measurements within a second, and the one whose save meets the
// other's change to the same tool chooses, seeing both. A library file that cannot be written gives a window
// that says so and takes no edit.
#include <memory>

#include <unistd.h>

#include <QAbstractItemView>
#include <QProcess>
#include <QPushButton>
#include <QScopeGuard>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

#include "model/formats/tablefile.h"
#include "tests/ui/sharedtablestories.h"
#include "ui/common/appsettings.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

void leaveWalMode(const QString &path)
{
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(u"QSQLITE"_s, u"journal"_s);
        db.setDatabaseName(path);
        QVERIFY(db.open());
        QSqlQuery query(db);
        QVERIFY(query.exec(u"PRAGMA journal_mode = DELETE"_s));
    }
    QSqlDatabase::removeDatabase(u"journal"_s);
}

} // namespace

class TestSharedTables : public QObject
{
    Q_OBJECT

    std::unique_ptr<QTemporaryDir> m_folder;
    LibraryLocation library() const { return { .path = m_folder->filePath(u"shop.sqlite"_s) }; }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_sharedtables"_s);
        // The setting names another machine: a library table's measurements and history are its own machine's
        // (Mill 1), whatever History Library… says for tables in files.
        AppSettings().setMachineName(u"Carvera"_s);
    }
    void init() { m_folder = std::make_unique<QTemporaryDir>(); }

    void aTableSavedToTheLibraryOpensOnAnotherStation() { savedTableOpensOnAnotherStation(library()); }
    void anEditSavedOnOneStationShowsOnTheOtherWithinASecond() { editShowsOnTheOtherStation(library()); }
    void theSecondToSaveTheSameToolSeesBothAndChooses_data()
    {
        QTest::addColumn<bool>("keepMine");
        QTest::newRow("keeps mine") << true;
        QTest::newRow("takes theirs") << false;
    }
    void theSecondToSaveTheSameToolSeesBothAndChooses()
    {
        QFETCH(bool, keepMine);
        sameToolEditedOnBoth(library(), keepMine);
    }
    void editsToDifferentToolsBothSaveWithoutAQuestion() { differentToolsEditedOnBoth(library()); }
    void aProbeOnOneStationReachesTheOthersTableAndHistory() { measurementReachesTheOtherStation(library()); }

    void offeredMachinesAreTheLibrarysAndNoneIsSaid()
    {
        LibraryStation a(library(), u"Station A"_s);
        QString said;
        answerNextBox(QMessageBox::Ok, &said);
        a.action(u"actionOpenMachineTable"_s)->trigger();
        QVERIFY2(said.contains(u"holds no machine tables yet"_s), qPrintable(said));
        QVERIFY(!a.document()->isLibraryTable());
    }

    void anUnwritableLibraryFileGivesAReadOnlyWindow()
    {
        // A read-only file system: unwritable even for root, as CI runs; elsewhere a file without write
        // rights.
        const bool mounted = ::geteuid() == 0
            && QProcess::execute(
                   u"mount"_s, { u"-t"_s, u"tmpfs"_s, u"-o"_s, u"size=4m"_s, u"tmpfs"_s, m_folder->path() })
                == 0;
        auto unmount = qScopeGuard([&] {
            if (mounted)
                QProcess::execute(u"umount"_s, { m_folder->path() });
        });
        {
            auto made = Library::open(library());
            QVERIFY(made);
            auto example = loadTableFile(kExampleTable);
            QVERIFY(example);
            QVERIFY(made.value()->createTable(kMachine, example.value()));
        }
        if (mounted) {
            // SQLite reads a WAL-mode file on read-only media only with its -shm file beside it, which is
            // gone once the last writer closed it: the file goes back to a rollback journal first, as a copy
            // put on a read-only share would be.
            leaveWalMode(library().path);
            QCOMPARE(QProcess::execute(u"mount"_s, { u"-o"_s, u"remount,ro"_s, m_folder->path() }), 0);
        } else
            QVERIFY(QFile::setPermissions(library().path, QFileDevice::ReadOwner | QFileDevice::ReadOther));

        LibraryStation r(library(), u"Station R"_s);
        QVERIFY2(r.window.history()->library(), qPrintable(r.window.history()->lastError()));
        QVERIFY(r.window.history()->library()->isReadOnly());
        r.openMachineTable(kMachine);
        QCOMPARE(r.document()->libraryMachine(), kMachine);
        QCOMPARE(r.table().size(), 6);
        auto *banner = r.window.findChild<QLabel *>(u"readOnlyBanner"_s);
        QVERIFY(banner && banner->isVisible());
        QVERIFY(banner->text().startsWith(u"Read-only"_s));
        QVERIFY(r.window.windowTitle().contains(u"(read-only)"_s));
        QVERIFY(!r.action(u"actionSave"_s)->isEnabled());
        QVERIFY(!r.action(u"actionAddTool"_s)->isEnabled());
        QVERIFY(!r.action(u"actionRemoveTool"_s)->isEnabled());
        QCOMPARE(r.window.toolTablePanel()->view()->editTriggers(), QAbstractItemView::NoEditTriggers);
        // Connected, nothing is measured into a table that can never be saved: the machine is not moved.
        r.window.connection()->connectTo(ConnectionTarget {});
        QTRY_VERIFY(r.window.connection()->canOperate());
        QApplication::processEvents();
        QVERIFY(!r.action(u"actionProbe"_s)->isEnabled());
        QVERIFY(!r.action(u"actionBreakTest"_s)->isEnabled());
        QVERIFY(!r.action(u"actionNewCutter"_s)->isEnabled());
        QVERIFY(!r.action(u"actionMeasureRack"_s)->isEnabled());
        auto *probe = r.window.findChild<QPushButton *>(u"probeButton"_s);
        QVERIFY(probe && !probe->isEnabled());
        QVERIFY(probe->parentWidget()->parentWidget()->toolTip().contains(u"read-only here"_s));
        // A file table opened after it is editable and measurable again.
        QVERIFY(r.window.openFile(kExampleTable));
        QVERIFY(!banner->isVisible());
        QVERIFY(r.action(u"actionSave"_s)->isEnabled());
        QTRY_VERIFY(r.action(u"actionProbe"_s)->isEnabled());
        QVERIFY(probe->isEnabled());
    }
};

QTEST_MAIN(TestSharedTables)
#include "tst_sharedtables.moc"
