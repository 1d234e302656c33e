// SPDX-License-Identifier: GPL-3.0-or-later
// AutoSave: a copy of the unsaved edits exists exactly while there are unsaved edits, a living session's copy
// is never offered, and what a dead session left is found, loaded, claimed once and discarded.
#include <sys/stat.h>

#include <QDir>
#include <QElapsedTimer>
#include <QLockFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "model/document/autosave.h"
#include "model/document/tooldocument.h"
#include "tests/support/fulldisk.h"
#include "tests/support/testtables.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestAutoSave : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString recovery() const { return m_dir.filePath(u"recovery"_s); }
    // A saved table to start from (a failure to write it fails the test that opens it).
    QString saved(const QString &name = u"tools.json"_s) const
    {
        const QString path = m_dir.filePath(name);
        (void)saveTableFile(path, Test::awkwardTable(), TableFormat::Json);
        return path;
    }

private Q_SLOTS:
    void cleanup() { QDir(recovery()).removeRecursively(); }

    void writesACopyAMomentAfterAnEdit()
    {
        ToolDocument document;
        QVERIFY(document.open(saved()).ok());
        AutoSave autoSave(&document, recovery());
        autoSave.setDelay(20);
        QVERIFY(!QFileInfo::exists(autoSave.tablePath()));
        QVERIFY(document.addTool(Test::tool(40, 12.5)).ok());
        QTRY_VERIFY(QFileInfo::exists(autoSave.tablePath()));
        const auto copy = loadTableFile(autoSave.tablePath());
        QVERIFY2(copy.ok(), qPrintable(copy.error().text()));
        QCOMPARE(copy.value(), document.table());
    }

    void aLivingSessionIsNeverOffered()
    {
        ToolDocument document;
        AutoSave autoSave(&document, recovery());
        QVERIFY(document.addTool(Test::tool(1)).ok());
        QVERIFY(autoSave.saveNow().ok());
        QVERIFY(QFileInfo::exists(autoSave.tablePath()));
        QVERIFY(AutoSave::findRecoverable(recovery()).isEmpty());
    }

    void theCopyGoesWhenNothingIsUnsaved()
    {
        ToolDocument document;
        QVERIFY(document.open(saved()).ok());
        AutoSave autoSave(&document, recovery());
        QVERIFY(document.addTool(Test::tool(41)).ok());
        QVERIFY(autoSave.saveNow().ok());
        QVERIFY(QFileInfo::exists(autoSave.tablePath()));
        document.undoStack()->undo(); // back to the saved state
        QVERIFY(!QFileInfo::exists(autoSave.tablePath()));

        QVERIFY(document.addTool(Test::tool(42)).ok());
        QVERIFY(autoSave.saveNow().ok());
        QVERIFY(document.save().ok());
        QVERIFY(!QFileInfo::exists(autoSave.tablePath()));
        QVERIFY(document.addTool(Test::tool(43)).ok()); // edits after a save are protected again
        QVERIFY(autoSave.saveNow().ok());
        QVERIFY(QFileInfo::exists(autoSave.tablePath()));
    }

    void aNormalExitLeavesNothing()
    {
        ToolDocument document;
        {
            AutoSave autoSave(&document, recovery());
            QVERIFY(document.addTool(Test::tool(1)).ok());
            QVERIFY(autoSave.saveNow().ok());
            QVERIFY(!QDir(recovery()).isEmpty());
        } // the window closed, the operator having chosen to discard
        QVERIFY(document.isModified());
        QVERIFY(QDir(recovery()).isEmpty());
    }

    void findsClaimsAndDiscardsWhatADeadSessionLeft()
    {
        // What a killed Toffee leaves: the copy and where it belongs, and a lock no living process holds.
        QDir().mkpath(recovery());
        const ToolTable edits = Test::awkwardTable();
        QVERIFY(saveTableFile(recovery() + u"/99999-dead.json"_s, edits, TableFormat::Json).ok());
        QFile info(recovery() + u"/99999-dead.info"_s);
        QVERIFY(info.open(QIODevice::WriteOnly));
        info.write(R"({"original_path": "/somewhere/tools.tbl", "original_format": "tbl"})");
        info.close();

        const auto sessions = AutoSave::findRecoverable(recovery());
        QCOMPARE(sessions.size(), 1);
        const AutoSave::Session &session = sessions.first();
        QCOMPARE(session.originalPath, u"/somewhere/tools.tbl"_s);
        QCOMPARE(session.originalFormat, TableFormat::LinuxCnc);
        QVERIFY(session.savedAt.isValid());
        const auto loaded = AutoSave::load(session);
        QVERIFY(loaded.ok());
        QCOMPARE(loaded.value(), edits);

        // Claimed: a second Toffee starting now is not offered the same copy.
        QVERIFY(AutoSave::findRecoverable(recovery()).isEmpty());
        AutoSave::discard(session);
        QVERIFY(QDir(recovery()).isEmpty());
    }

    void aCopyDeclinedNowIsOfferedAgainLater()
    {
        QDir().mkpath(recovery());
        QVERIFY(saveTableFile(recovery() + u"/1-later.json"_s, Test::awkwardTable(), TableFormat::Json).ok());
        QCOMPARE(AutoSave::findRecoverable(recovery()).size(), 1); // released as the list goes
        const auto again = AutoSave::findRecoverable(recovery());
        QCOMPARE(again.size(), 1);
        QVERIFY(again.first().originalPath.isEmpty()); // no .info: a table never saved
    }

    void sweepsWhatASessionLeftBeforeItsFirstCopy()
    {
        // Killed between taking its lock and writing its first copy: a lock (of a process now gone) and an
        // .info. A living session in the same state keeps its files.
        QDir().mkpath(recovery());
        {
            QLockFile dead(recovery() + u"/1-dead.lock"_s);
            QVERIFY(dead.tryLock(0));
            QFile lockFile(recovery() + u"/1-dead.lock"_s);
            QVERIFY(lockFile.open(QIODevice::ReadOnly));
            const QByteArray owner = lockFile.readAll().replace(
                QByteArray::number(QCoreApplication::applicationPid()), "999999999"); // no such process
            lockFile.close();
            dead.unlock();
            QVERIFY(lockFile.open(QIODevice::WriteOnly));
            lockFile.write(owner);
        }
        QFile info(recovery() + u"/1-dead.info"_s);
        QVERIFY(info.open(QIODevice::WriteOnly));
        info.close();
        QLockFile alive(recovery() + u"/2-alive.lock"_s);
        alive.setStaleLockTime(0);
        QVERIFY(alive.tryLock(0));

        QVERIFY(AutoSave::findRecoverable(recovery()).isEmpty());
        QCOMPARE(QDir(recovery()).entryList(QDir::Files), QStringList { u"2-alive.lock"_s });
    }

    void reportsACopyItCannotWrite()
    {
        // The recovery folder's place is taken by a file: no copy can be written, and the window must hear.
        const QString blocked = saved(u"blocked"_s);
        ToolDocument document;
        AutoSave autoSave(&document, blocked + u"/recovery"_s);
        autoSave.setDelay(0);
        QSignalSpy failed(&autoSave, &AutoSave::failed);
        QVERIFY(document.addTool(Test::tool(1)).ok());
        QTRY_COMPARE(failed.size(), 1);
        QVERIFY2(failed.first().first().toString().contains(u"folder for unsaved edits"_s),
            qPrintable(failed.first().first().toString()));
        QVERIFY(!autoSave.saveNow().ok());
    }

    void quarantinesWhatItCannotTrust_data()
    {
        QTest::addColumn<QString>("garbage");
        QTest::newRow(".info a link to /dev/zero") << u"info-zero"_s;
        QTest::newRow(".info a FIFO") << u"info-fifo"_s;
        QTest::newRow(".info not JSON") << u"info-garbled"_s;
        QTest::newRow(".info with a 1 MB path") << u"info-long-path"_s;
        QTest::newRow(".info with a relative path") << u"info-relative"_s;
        QTest::newRow(".info with a path through ..") << u"info-dotdot"_s;
        QTest::newRow(".info with a key twice") << u"info-twice"_s;
        QTest::newRow("copy a link to /dev/zero") << u"copy-zero"_s;
        QTest::newRow("copy a FIFO") << u"copy-fifo"_s;
        QTest::newRow("lock a FIFO") << u"lock-fifo"_s;
        QTest::newRow("lock a folder") << u"lock-folder"_s;
        QTest::newRow("copy a folder") << u"copy-folder"_s;
        QTest::newRow(".info a folder") << u"info-folder"_s;
    }
    void quarantinesWhatItCannotTrust()
    {
        // Beside a good copy, one that is garbage: the good one is offered, the garbage is moved aside (never
        // offered again, never deleted), and nothing blocks or reads without end.
        QFETCH(QString, garbage);
        QDir().mkpath(recovery());
        const QString good = recovery() + u"/1-good.json"_s;
        QVERIFY(saveTableFile(good, Test::awkwardTable(), TableFormat::Json).ok());
        const QString bad = recovery() + u"/2-bad"_s;
        const auto fifo = [](const QString &path) {
            return ::mkfifo(QFile::encodeName(path).constData(), 0600) == 0;
        };
        const auto write = [](const QString &path, const QByteArray &data) {
            QFile file(path);
            return file.open(QIODevice::WriteOnly) && file.write(data) == data.size();
        };
        if (garbage.startsWith(u"copy"))
            QVERIFY(garbage == u"copy-zero" ? QFile::link(u"/dev/zero"_s, bad + u".json"_s)
                                            : fifo(bad + u".json"_s));
        else
            QVERIFY(saveTableFile(bad + u".json"_s, Test::awkwardTable(), TableFormat::Json).ok());
        if (garbage == u"info-zero")
            QVERIFY(QFile::link(u"/dev/zero"_s, bad + u".info"_s));
        else if (garbage == u"info-fifo")
            QVERIFY(fifo(bad + u".info"_s));
        else if (garbage == u"info-garbled")
            QVERIFY(write(bad + u".info"_s, "\x01\x02{{{"));
        else if (garbage == u"info-long-path")
            QVERIFY(write(bad + u".info"_s,
                "{\"original_path\": \"/" + QByteArray(1 << 20, 'a') + "\", \"original_format\": \"json\"}"));
        else if (garbage == u"info-relative")
            QVERIFY(write(bad + u".info"_s, R"({"original_path": "tools.json", "original_format": "json"})"));
        else if (garbage == u"info-dotdot")
            QVERIFY(write(
                bad + u".info"_s, R"({"original_path": "/tmp/../etc/passwd", "original_format": "json"})"));
        else if (garbage == u"info-twice") // which path is meant? QJsonDocument would take the second
            QVERIFY(write(bad + u".info"_s,
                R"({"original_path": "/tmp/a.json", "original_path": "/tmp/b.json", "original_format": "json"})"));
        else if (garbage == u"lock-fifo")
            QVERIFY(fifo(bad + u".lock"_s));
        else if (garbage == u"lock-folder")
            QVERIFY(QDir().mkpath(bad + u".lock"_s));
        else if (garbage == u"info-folder")
            QVERIFY(QDir().mkpath(bad + u".info"_s));

        QElapsedTimer clock;
        clock.start();
        QStringList quarantined;
        const auto sessions = AutoSave::findRecoverable(recovery(), &quarantined);
        QVERIFY(clock.elapsed() < 5000);
        QCOMPARE(sessions.size(), 1);
        QCOMPARE(sessions.first().tablePath, good);
        QCOMPARE(quarantined, QStringList { u"2-bad"_s });
        const QStringList aside
            = QDir(AutoSave::quarantineDirectory(recovery())).entryList(QDir::Files | QDir::System);
        QVERIFY2(std::any_of(aside.cbegin(), aside.cend(),
                     [](const QString &f) { return f.endsWith(u"-2-bad.json"_s); }),
            qPrintable(aside.join(u' ')));
        QVERIFY(!QFileInfo::exists(bad + u".json"_s) && !QFileInfo(bad + u".json"_s).isSymLink());
        QVERIFY(!QFileInfo::exists(bad + u".info"_s) && !QFileInfo::exists(bad + u".lock"_s));
        AutoSave::discard(sessions.first());
        // Next start: nothing more to offer, nothing more to say.
        quarantined.clear();
        QVERIFY(AutoSave::findRecoverable(recovery(), &quarantined).isEmpty());
        QVERIFY(quarantined.isEmpty());
    }

    void aFullDiskKeepsTheLastGoodCopy()
    {
        Test::FullDisk disk(512 * 1024);
        ToolDocument document;
        AutoSave autoSave(&document, disk.path(u"recovery"_s));
        QVERIFY(document.addTool(Test::tool(1)).ok());
        QVERIFY(autoSave.saveNow().ok());
        const ToolTable first = document.table();
        disk.fill();
        for (int i = 2; i < 3000; ++i)
            QVERIFY(document.addTool(Test::tool(i, 10.0, u"a description long enough to need room"_s)).ok());
        const auto saved = autoSave.saveNow();
        QVERIFY(!saved.ok());
        QVERIFY2(saved.error().text().contains(disk.reason()), qPrintable(saved.error().text()));
        const auto copy = loadTableFile(autoSave.tablePath());
        QVERIFY2(copy.ok(), qPrintable(copy.error().text()));
        QCOMPARE(copy.value(), first);
    }

    void neverDeletesWhatItCannotMoveAside()
    {
        // The quarantine folder cannot be made (a file has its name, or an earlier `sudo toffee` left it
        // unwritable): a broken copy stays exactly where it is, and is named as left alone.
        QDir().mkpath(recovery());
        QFile blocker(AutoSave::quarantineDirectory(recovery()));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        const QString good = recovery() + u"/1-good.json"_s;
        QVERIFY(saveTableFile(good, Test::awkwardTable(), TableFormat::Json).ok());
        const QString bad = recovery() + u"/2-bad.json"_s;
        QVERIFY(saveTableFile(bad, Test::awkwardTable(), TableFormat::Json).ok());
        QFile info(recovery() + u"/2-bad.info"_s);
        QVERIFY(info.open(QIODevice::WriteOnly));
        info.write(R"({"original_path": "relative/tools.json", "original_format": "json"})");
        info.close();
        QStringList quarantined;
        QStringList unmovable;
        const auto sessions = AutoSave::findRecoverable(recovery(), &quarantined, &unmovable);
        QCOMPARE(sessions.size(), 1);
        QVERIFY(quarantined.isEmpty());
        QCOMPARE(unmovable, QStringList { u"2-bad"_s });
        QVERIFY(loadTableFile(bad).ok()); // whole, where it was
        QVERIFY(QFileInfo::exists(recovery() + u"/2-bad.info"_s));
        QVERIFY(!AutoSave::quarantine(sessions.first()));
        QVERIFY(QFileInfo::exists(good));
    }
};

QTEST_GUILESS_MAIN(TestAutoSave)
#include "tst_autosave.moc"
