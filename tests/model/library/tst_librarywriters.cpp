// SPDX-License-Identifier: GPL-3.0-or-later
// The history library on real SQLite files when the world fails it: nothing is lost to a killed writer, a
// second writer, a lock, the recorder going with events waiting, damage under the recorder or a full disk
// (tests/model/library/libraryevents.h).
#include <csignal>

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include "tests/model/library/libraryevents.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using namespace Toffee::Test;

class TestLibraryWriters : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        // The recorder's spool (Spool::defaultFolder) is under the test's own data folder, not the user's.
        QStandardPaths::setTestModeEnabled(true);
    }

    void aKilledWriterLeavesEveryCommittedEvent()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"l.sqlite"_s);
        QProcess worker;
        worker.start(QStringLiteral(TOFFEE_WORKER), { path, u"Carvera"_s, u"5"_s, u"10000"_s });
        QVERIFY(worker.waitForStarted());
        QByteArray reported;
        while (reported.count('\n') < 300 && worker.waitForReadyRead(20000))
            reported += worker.readAllStandardOutput();
        ::kill(pid_t(worker.processId()), SIGKILL);
        QVERIFY(worker.waitForFinished());
        QCOMPARE(worker.exitStatus(), QProcess::CrashExit); // killed before it wrote all 10,000
        reported += worker.readAllStandardOutput();
        QStringList ids = QString::fromLatin1(reported).split(u'\n', Qt::SkipEmptyParts);
        if (!reported.endsWith('\n'))
            ids.removeLast(); // a line cut by the kill
        QVERIFY(ids.size() >= 300);
        auto library = Library::open({ path });
        QVERIFY2(library, qPrintable(library.error().message));
        const auto events = library.value()->history({ u"Carvera"_s, 5, {}, 0 });
        QVERIFY(events);
        QSet<QString> present;
        for (const HistoryEvent &e : events.value())
            present.insert(e.id);
        for (const QString &id : ids)
            QVERIFY2(present.contains(id), qPrintable(id));
        QVERIFY(events.value().size() < 10000);
    }

    void twoWritersAtOnceLoseNothing()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"l.sqlite"_s);
        QVERIFY(Library::open({ path })); // created before both start
        QProcess a;
        QProcess b;
        a.start(QStringLiteral(TOFFEE_WORKER), { path, u"Carvera"_s, u"1"_s, u"1500"_s });
        b.start(QStringLiteral(TOFFEE_WORKER), { path, u"Mill"_s, u"1"_s, u"1500"_s });
        QVERIFY(a.waitForFinished(120000));
        QVERIFY(b.waitForFinished(120000));
        QCOMPARE(a.exitCode(), 0);
        QCOMPARE(b.exitCode(), 0);
        auto library = Library::open({ path });
        QCOMPARE(library.value()->history({ u"Carvera"_s, 1, {}, 0 }).value().size(), 1500);
        QCOMPARE(library.value()->history({ u"Mill"_s, 1, {}, 0 }).value().size(), 1500);
    }

    void aLockedLibraryKeepsTheEventsAndWritesThemLater()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"l.sqlite"_s);
        HistoryRecorder recorder;
        QVERIFY(recorder.setLocation({ path }, Library::Options { 50 }));
        QSignalSpy down(&recorder, &HistoryRecorder::unavailable);
        QSignalSpy up(&recorder, &HistoryRecorder::available);
        RawConnection other(path, u"raw-lock"_s);
        QVERIFY(other.exec(u"BEGIN IMMEDIATE"_s)); // another program holds the write lock
        recorder.record(makeEvent(7, EventKind::Probe, 0, -1.0));
        recorder.record(makeEvent(7, EventKind::BreakTest, 1, -1.0));
        QCOMPARE(recorder.pendingCount(), 2);
        QCOMPARE(down.size(), 1); // told once, not per event
        QVERIFY(down.front().front().toString().contains(path));
        QVERIFY(!recorder.flush());
        QCOMPARE(down.size(), 1);
        QVERIFY(other.exec(u"ROLLBACK"_s));
        QTRY_COMPARE_WITH_TIMEOUT(up.size(), 1, 3 * HistoryRecorder::kRetryMs); // the retry writes them
        QCOMPARE(recorder.pendingCount(), 0);
        QCOMPARE(recorder.library()->history({}).value().size(), 2);
    }

    // The window closes while the library is locked: what waited is in the spool's files, and the next
    // recorder on that library writes it, once.
    void eventsWaitingWhenTheRecorderGoesAreKeptAndWrittenOnce()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"l.sqlite"_s);
        const QString folder = dir.filePath(u"outbox"_s);
        RawConnection other(path, u"raw-lock-close"_s);
        {
            HistoryRecorder recorder;
            recorder.setSpoolFolder(folder);
            QVERIFY(recorder.setLocation({ path }, Library::Options { 50 }));
            QVERIFY(other.exec(u"BEGIN IMMEDIATE"_s));
            recorder.record(makeEvent(3, EventKind::Probe, 0, -2.0));
            recorder.record(makeEvent(3, EventKind::ManualSet, 1, -2.5));
            QCOMPARE(recorder.pendingCount(), 2);
            // Kept at once, not only when the window closes: a crash now loses nothing either.
            QCOMPARE(Spool(folder).count({ path }), 2);
        }
        QCOMPARE(Spool(folder).count({ path }), 2);
        QVERIFY(other.exec(u"ROLLBACK"_s));
        for (int i = 0; i < 2; ++i) {
            HistoryRecorder recorder;
            recorder.setSpoolFolder(folder);
            QVERIFY(recorder.setLocation({ path }));
            QCOMPARE(recorder.pendingCount(), 0);
            QCOMPARE(recorder.library()->history({}).value().size(), 2);
        }
        QCOMPARE(Spool(folder).count({ path }), 0);
    }

    // Another program drops the events table under the window: the events are kept, and the message says
    // the library is damaged, in Toffee's words.
    void aLibraryDamagedUnderTheRecorderKeepsTheEvents()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"l.sqlite"_s);
        const QString folder = dir.filePath(u"outbox"_s);
        HistoryRecorder recorder;
        recorder.setSpoolFolder(folder);
        QVERIFY(recorder.setLocation({ path }));
        QSignalSpy down(&recorder, &HistoryRecorder::unavailable);
        {
            RawConnection other(path, u"raw-drop"_s);
            QVERIFY(other.exec(u"DROP TABLE events"_s));
        }
        recorder.record(makeEvent(4, EventKind::Probe, 0, -1.0));
        QCOMPARE(down.size(), 1);
        const QString said = down.front().front().toString();
        QVERIFY2(said.contains(u"is damaged: its table \"events\" is missing"_s), qPrintable(said));
        QCOMPARE(Spool(folder).count({ path }), 1);
        QCOMPARE(recorder.pendingCount(), 1);
    }

    void aFullDiskKeepsTheEventsAndWritesThemWhenThereIsRoom()
    {
        Test::FullDisk disk(1024 * 1024);
        const QString path = disk.path(u"l.sqlite"_s);
        HistoryRecorder recorder;
        QVERIFY(recorder.setLocation({ path }));
        recorder.record(makeEvent(1, EventKind::Probe, 0, 0.0)); // the library and its WAL exist
        QCOMPARE(recorder.pendingCount(), 0);
        QSignalSpy down(&recorder, &HistoryRecorder::unavailable);
        disk.fill();
        for (int i = 1; i <= 200; ++i)
            recorder.record(makeEvent(1, EventKind::Probe, i, -i * 0.001));
        QCOMPARE(down.size(), 1);
        QCOMPARE(recorder.pendingCount(), 200); // a failed batch is not half-written: all of it waits
        QVERIFY2(down.front().front().toString().contains(path), qPrintable(down.front().front().toString()));
        disk.free();
        QVERIFY2(recorder.flush(), qPrintable(recorder.lastError()));
        QCOMPARE(recorder.library()->history({}).value().size(), 201);
        QCOMPARE(recorder.pendingCount(), 0);
    }
};

QTEST_GUILESS_MAIN(TestLibraryWriters)
#include "tst_librarywriters.moc"
