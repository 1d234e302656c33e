// SPDX-License-Identifier: GPL-3.0-or-later
// The history library on real SQLite files: what it keeps, what it reads back, what it brings up to date and
// what it refuses. That nothing is lost to a killed writer, a second writer, a lock or a full disk:
// tst_librarywriters.
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
#include <QTimeZone>

#include "tests/model/library/libraryevents.h"

using namespace Toffee;
using namespace Qt::StringLiterals;
using namespace Toffee::Test;

class TestLibrary : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        // The recorder's spool (Spool::defaultFolder) is under the test's own data folder, not the user's.
        QStandardPaths::setTestModeEnabled(true);
    }

    void recordsEveryKindWithEveryField()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"new/folder/library.sqlite"_s);
        auto library = Library::open({ path });
        QVERIFY2(library, qPrintable(library.error().message));
        QList<HistoryEvent> events;
        for (EventKind kind : { EventKind::Probe, EventKind::BreakTest, EventKind::ManualSet,
                 EventKind::Restore, EventKind::Import }) {
            HistoryEvent e = makeEvent(3, kind, int(events.size()), -33.388 + double(events.size()));
            e.referenceMz = -72.3;
            e.currentMz = -105.688;
            e.tolerance = 0.05;
            e.oldTlo = -33.388;
            e.newTlo = -33.901;
            e.failed = kind == EventKind::BreakTest;
            events.append(e);
        }
        HistoryEvent bare = makeEvent(4, EventKind::ManualSet, 10, 1.5); // what the machine did not report
        events.append(bare);
        QCOMPARE(library.value()->append(events).value(), 6);
        const auto read = library.value()->history({});
        QVERIFY(read);
        QCOMPARE(read.value(), events);
        QCOMPARE(read.value().last().referenceMz, std::nullopt);
        QCOMPARE(read.value().last().failed, std::nullopt);
        // Another program reads the same rows by the documented names (docs/LIBRARY.md).
        library.value().reset();
        RawConnection raw(path, u"raw-read"_s);
        QCOMPARE(raw.value(u"SELECT version FROM toffee_schema"_s).toInt(), Library::kSchemaVersion);
        QCOMPARE(
            raw.value(u"SELECT count(*) FROM events WHERE kind = 'break_test' AND failed = 1"_s).toInt(), 1);
        QCOMPARE(raw.value(u"SELECT measured_at FROM events WHERE tool = 4"_s).toString(),
            u"2026-11-23T08:10:00.125Z"_s);
        QCOMPARE(raw.value(u"SELECT name FROM machines"_s).toString(), u"Carvera"_s);
    }

    void readsOneToolSinceATimeAndTheNewestFew()
    {
        QTemporaryDir dir;
        auto library = Library::open({ dir.filePath(u"l.sqlite"_s) });
        QVERIFY(library);
        QList<HistoryEvent> events;
        for (int i = 0; i < 20; ++i)
            events.append(makeEvent(1 + i % 2, EventKind::Probe, i, -i * 0.01));
        HistoryEvent other = makeEvent(1, EventKind::Probe, 5, 9.0);
        other.machine = u"Mill"_s;
        events.append(other);
        QVERIFY(library.value()->append(events));
        auto t1 = library.value()->history({ u"Carvera"_s, 1, {}, 0 });
        QCOMPARE(t1.value().size(), 10);
        QVERIFY(std::all_of(t1.value().cbegin(), t1.value().cend(),
            [](const HistoryEvent &e) { return e.tool == 1 && e.machine == u"Carvera"; }));
        auto since = library.value()->history({ u"Carvera"_s, 1, at(10), 0 });
        QCOMPARE(since.value().size(), 5);
        QCOMPARE(since.value().front().at, at(10));
        auto newest = library.value()->history({ u"Carvera"_s, 2, {}, 3 });
        QCOMPARE(newest.value().size(), 3);
        QCOMPARE(newest.value().front().at, at(15)); // oldest first, the newest three
        QCOMPARE(newest.value().back().at, at(19));
        auto machines = library.value()->machines();
        QCOMPARE(machines.value().size(), 2);
    }

    void anEventWrittenTwiceIsOneRow()
    {
        QTemporaryDir dir;
        auto library = Library::open({ dir.filePath(u"l.sqlite"_s) });
        const HistoryEvent e = makeEvent(2, EventKind::Probe, 0, -1.0);
        QCOMPARE(library.value()->append({ e }).value(), 1);
        QCOMPARE(library.value()->append({ e, makeEvent(2, EventKind::Probe, 1, -1.1) }).value(), 1);
        QCOMPARE(library.value()->history({}).value().size(), 2);
    }

    void keepsMachinesAndToolUse()
    {
        QTemporaryDir dir;
        auto library = Library::open({ dir.filePath(u"l.sqlite"_s) });
        QVERIFY(library.value()->addMachine({ u"Carvera"_s, u"carvera"_s, u"/dev/ttyUSB0 115200"_s }));
        QVERIFY(library.value()->addMachine({ u"Carvera"_s, u"carvera"_s, u"emulator"_s }));
        QCOMPARE(library.value()->machines().value(),
            (QList<MachineRecord> { { u"Carvera"_s, u"carvera"_s, u"emulator"_s } }));
        const ToolUse use { HistoryEvent::newId(), u"Carvera"_s, 3, at(0), u"pocket.nc"_s, 754.5, 12034.25 };
        QCOMPARE(library.value()->appendUse({ use, use }).value(), 1);
        QCOMPARE(library.value()->uses(u"Carvera"_s, 3).value(), QList<ToolUse> { use });
        QVERIFY(library.value()->uses(u"Carvera"_s, 4).value().isEmpty());
    }

    // A machine's setter repeatability is kept with it, the newest only; a value another program garbled is
    // said, not guessed at.
    void aMachinesSetterRepeatabilityIsKept()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"l.sqlite"_s);
        auto library = Library::open({ path });
        QVERIFY(library);
        QCOMPARE(library.value()->repeatability(u"Router"_s).value(), std::nullopt);
        const SetterRepeatability measured { 3, QDateTime(QDate(2026, 11, 29), QTime(8, 0), QTimeZone::utc()),
            { -80.0, -79.998, -80.002 } };
        QVERIFY(library.value()->setRepeatability(u"Router"_s, measured));
        QCOMPARE(library.value()->repeatability(u"Router"_s).value(), std::optional(measured));
        QCOMPARE(library.value()->repeatability(u"Router"_s).value()->spread(), 0.004);
        QVERIFY(!library.value()->setRepeatability(u"Router"_s, { 3, measured.at, { -80.0 } }));
        library.value().reset();
        {
            RawConnection raw(path, u"raw-rep"_s);
            QVERIFY(raw.exec(u"UPDATE machines SET repeatability = '{\"tool\": 3}' WHERE name = 'Router'"_s));
        }
        library = Library::open({ path });
        const auto garbled = library.value()->repeatability(u"Router"_s);
        QVERIFY(!garbled);
        QVERIFY2(
            garbled.error().message.contains(u"measure it again"_s), qPrintable(garbled.error().message));
    }

    void aVersionTwoLibraryIsBroughtUpToDateAndKeepsEachMachinesToolSetter()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"l.sqlite"_s);
        {
            auto library = Library::open({ path });
            QVERIFY(library.value()->append({ makeEvent(1, EventKind::Probe, 0, -3.5) }));
        }
        {
            // As Toffee wrote it before machines had a tool setter (or an identity).
            RawConnection raw(path, u"raw-v2"_s);
            QVERIFY(raw.exec(u"ALTER TABLE machines DROP COLUMN repeatability"_s));
            QVERIFY(raw.exec(u"ALTER TABLE events DROP COLUMN touches"_s));
            QVERIFY(raw.exec(u"ALTER TABLE events DROP COLUMN spread"_s));
            QVERIFY(raw.exec(u"ALTER TABLE machines DROP COLUMN setter"_s));
            QVERIFY(raw.exec(u"ALTER TABLE machines DROP COLUMN identity"_s));
            QVERIFY(raw.exec(u"UPDATE toffee_schema SET version = 2"_s));
        }
        auto library = Library::open({ path });
        QVERIFY2(library, qPrintable(library ? QString() : library.error().message));
        QCOMPARE(library.value()->history({}).value().size(), 1); // nothing lost on the way
        QCOMPARE(library.value()->toolSetter(u"Carvera"_s).value(), std::nullopt);
        const ToolSetter setter = ToolSetter::parse(u"12.5,-40,-120,800,50,1.5"_s).value();
        QVERIFY(library.value()->setToolSetter(u"Carvera"_s, setter));
        QVERIFY(library.value()->setToolSetter(u"LongMill"_s, ToolSetter::parse(u"0,0,-90"_s).value()));
        QCOMPARE(library.value()->toolSetter(u"Carvera"_s).value(), std::optional(setter));
        QCOMPARE(library.value()->toolSetter(u"LongMill"_s).value()->zMin, -90.0);
        // A machine's dialect written again keeps its setter.
        QVERIFY(library.value()->addMachine({ u"LongMill"_s, u"grblhal"_s, u"127.0.0.1:23"_s }));
        QCOMPARE(library.value()->toolSetter(u"LongMill"_s).value()->zMin, -90.0);
        library.value().reset();
        {
            RawConnection raw(path, u"raw-v3"_s);
            QCOMPARE(raw.value(u"SELECT version FROM toffee_schema"_s).toInt(), Library::kSchemaVersion);
            QCOMPARE(raw.value(u"SELECT setter FROM machines WHERE name = 'Carvera'"_s).toString(),
                u"12.5,-40,-120,800,50,1.5"_s);
            QVERIFY(raw.exec(u"UPDATE machines SET setter = 'over there' WHERE name = 'LongMill'"_s));
        }
        // Another program's value that does not read is said, not guessed at.
        library = Library::open({ path });
        const auto garbled = library.value()->toolSetter(u"LongMill"_s);
        QVERIFY(!garbled);
        QVERIFY2(garbled.error().message.contains(u"Set it again"_s), qPrintable(garbled.error().message));
    }

    void aVersionThreeLibraryTakesNewCuttersAndKeepsEveryEvent()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"l.sqlite"_s);
        {
            auto library = Library::open({ path });
            QVERIFY(library.value()->append(
                { makeEvent(3, EventKind::Probe, 0, -30.2), makeEvent(3, EventKind::BreakTest, 5, -30.2) }));
        }
        {
            // As Toffee wrote it before a new cutter was an event: its CHECK refuses the kind.
            RawConnection raw(path, u"raw-v3"_s);
            QVERIFY(raw.exec(u"ALTER TABLE machines DROP COLUMN repeatability"_s));
            QVERIFY(raw.exec(u"ALTER TABLE machines DROP COLUMN identity"_s));
            QVERIFY(raw.exec(u"DROP TABLE events"_s));
            QVERIFY(
                raw.exec(u"CREATE TABLE events (id TEXT PRIMARY KEY, machine TEXT NOT NULL REFERENCES "
                         "machines (name), tool INTEGER NOT NULL, measured_at TEXT NOT NULL, kind TEXT NOT "
                         "NULL CHECK (kind IN ('probe', 'break_test', 'manual_set', 'restore', 'import')), "
                         "tlo DOUBLE PRECISION, reference_mz DOUBLE PRECISION, current_mz DOUBLE "
                         "PRECISION, tolerance DOUBLE PRECISION, old_tlo DOUBLE PRECISION, new_tlo DOUBLE "
                         "PRECISION, failed INTEGER CHECK (failed IN (0, 1)))"_s));
            QVERIFY(raw.exec(u"INSERT INTO events (id, machine, tool, measured_at, kind, tlo) VALUES ('a', "
                             "'Carvera', 3, '2026-11-23T08:00:00.125Z', 'probe', -30.2)"_s));
            QVERIFY(!raw.exec(u"INSERT INTO events (id, machine, tool, measured_at, kind) VALUES ('b', "
                              "'Carvera', 3, '2026-11-23T09:00:00.000Z', 'new_cutter')"_s));
            QVERIFY(raw.exec(u"UPDATE toffee_schema SET version = 3"_s));
        }
        {
            // Read-only (a share, a file without write permission): it cannot be brought up to date, and is
            // read as it is. It once could not be read at all.
            auto readOnly = Library::open({ path }, Library::Options { .readOnly = true });
            QVERIFY2(readOnly, qPrintable(readOnly ? QString() : readOnly.error().message));
            QVERIFY(readOnly.value()->isReadOnly());
            QCOMPARE(readOnly.value()->history({}).value().size(), 1);
            QVERIFY(!readOnly.value()->append({ makeEvent(3, EventKind::Probe, 1, -30.1) }));
        }
        auto library = Library::open({ path });
        QVERIFY2(library, qPrintable(library ? QString() : library.error().message));
        QCOMPARE(library.value()->history({}).value().size(), 1); // nothing lost on the way
        HistoryEvent ended = makeEvent(3, EventKind::NewCutter, 90, 0.0);
        ended.tlo.reset();
        ended.oldTlo = -30.2;
        QVERIFY(library.value()->append({ ended }));
        const QList<HistoryEvent> events = library.value()->history({}).value();
        QCOMPARE(events.size(), 2);
        QCOMPARE(events.last(), ended);
        // Program runs before the new cutter are the old cutter's life.
        ToolUse before { HistoryEvent::newId(), u"Carvera"_s, 3, at(60), u"a.nc"_s, 600.0, 6000.0 };
        ToolUse after { HistoryEvent::newId(), u"Carvera"_s, 3, at(120), u"b.nc"_s, 90.0, 900.0 };
        QVERIFY(library.value()->appendUse({ before, after }));
        QCOMPARE(library.value()->usedLife(u"Carvera"_s, 3).value().value(3), (UsedLife { 90.0, 1 }));
        QCOMPARE(library.value()->usedLife(u"Carvera"_s).value().value(3), (UsedLife { 90.0, 1 }));
    }

    // A name stands for one machine: bound to the first identity it meets (new), the same again (same),
    // another refused without a change (other, naming the one it is), bound anew only when the operator says
    // it is the same machine reached another way. A version-4 library (no identities) is brought up to date
    // with every event and machine kept, its machines bound to nothing until one is met; read-only, it is
    // read and binds nothing.
    void aNameStandsForOneMachine()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"l.sqlite"_s);
        using Kind = Library::MachineBinding::Kind;
        {
            auto library = Library::open({ path });
            QVERIFY(library.value()->append({ makeEvent(1, EventKind::Probe, 0, -3.5) }));
            QVERIFY(library.value()->setToolSetter(u"LongMill"_s, ToolSetter::parse(u"0,0,-90"_s).value()));
        }
        {
            // As Toffee wrote it before machines had an identity.
            RawConnection raw(path, u"raw-v4"_s);
            QVERIFY(raw.exec(u"ALTER TABLE machines DROP COLUMN repeatability"_s));
            QVERIFY(raw.exec(u"ALTER TABLE events DROP COLUMN touches"_s));
            QVERIFY(raw.exec(u"ALTER TABLE events DROP COLUMN spread"_s));
            QVERIFY(raw.exec(u"ALTER TABLE machines DROP COLUMN identity"_s));
            QVERIFY(raw.exec(u"UPDATE toffee_schema SET version = 4"_s));
        }
        {
            auto readOnly = Library::open({ path }, Library::Options { .readOnly = true });
            QVERIFY2(readOnly, qPrintable(readOnly ? QString() : readOnly.error().message));
            const auto bound = readOnly.value()->bindMachine(u"Carvera"_s, u"carvera:/dev/ttyACM0"_s);
            QVERIFY2(bound, qPrintable(bound ? QString() : bound.error().message));
            QCOMPARE(bound.value().kind, Kind::New);
            QCOMPARE(readOnly.value()->history({}).value().size(), 1);
        }
        auto library = Library::open({ path });
        QVERIFY2(library, qPrintable(library ? QString() : library.error().message));
        Library &l = *library.value();
        QCOMPARE(l.history({}).value().size(), 1); // nothing lost on the way
        QCOMPARE(l.toolSetter(u"LongMill"_s).value()->zMin, -90.0);
        QCOMPARE(l.bindMachine(u"Carvera"_s, u"carvera:/dev/ttyACM0"_s).value().kind, Kind::New);
        QCOMPARE(l.bindMachine(u"Carvera"_s, u"carvera:/dev/ttyACM0"_s).value().kind, Kind::Same);
        const auto other = l.bindMachine(u"Carvera"_s, u"grblhal:127.0.0.1:23"_s);
        QCOMPARE(other.value().kind, Kind::Other);
        QCOMPARE(other.value().boundTo, u"carvera:/dev/ttyACM0"_s);
        QCOMPARE(
            l.bindMachine(u"Carvera"_s, u"carvera:/dev/ttyACM0"_s).value().kind, Kind::Same); // unchanged
        QCOMPARE(l.bindMachine(u"LongMill"_s, u"grblhal:127.0.0.1:23"_s).value().kind, Kind::New);
        QCOMPARE(l.bindMachine(u"Carvera"_s, u"carvera:192.168.1.57:2222"_s, true).value().kind, Kind::Same);
        QCOMPARE(l.bindMachine(u"Carvera"_s, u"carvera:192.168.1.57:2222"_s).value().kind, Kind::Same);
        QCOMPARE(l.bindMachine(u"Emulator"_s, u"emulator"_s).value().kind, Kind::New);
        QCOMPARE(l.toolSetter(u"LongMill"_s).value()->zMin, -90.0); // binding keeps the rest of the machine
        library.value().reset();
        RawConnection raw(path, u"raw-v5"_s);
        QCOMPARE(raw.value(u"SELECT identity FROM machines WHERE name = 'LongMill'"_s).toString(),
            u"grblhal:127.0.0.1:23"_s);
    }

    void refusesANewerLibraryAndLeavesItAsItIs()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"l.sqlite"_s);
        {
            auto library = Library::open({ path });
            QVERIFY(library.value()->append({ makeEvent(1, EventKind::Probe, 0, 0.0) }));
        }
        {
            RawConnection raw(path, u"raw-newer"_s);
            QVERIFY(raw.exec(u"UPDATE toffee_schema SET version = 7"_s));
            QVERIFY(raw.exec(u"PRAGMA wal_checkpoint(TRUNCATE)"_s));
        }
        const QByteArray before = digest(path);
        auto library = Library::open({ path });
        QVERIFY(!library);
        QVERIFY2(library.error().message.contains(u"newer Toffee"_s), qPrintable(library.error().message));
        QVERIFY(library.error().message.contains(path));
        QVERIFY(library.error().message.contains(u"version 7"_s));
        QCOMPARE(digest(path), before);
    }

    void refusesWhatIsNotALibraryByName_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("message");
        QTest::newRow("a folder") << u"folder"_s << u"is a folder"_s;
        QTest::newRow("a text file") << u"text"_s << u"not an SQLite database"_s;
        QTest::newRow("a damaged SQLite file") << u"corrupt"_s << u"is damaged"_s;
        QTest::newRow("another program's database") << u"foreign"_s << u"not a Toffee library"_s;
        QTest::newRow("a PostgreSQL URL with a password") << u"postgresql"_s << u"PostgreSQL password file"_s;
    }
    void refusesWhatIsNotALibraryByName()
    {
        QFETCH(QString, kind);
        QFETCH(QString, message);
        QTemporaryDir dir;
        QString path = dir.filePath(u"library.sqlite"_s);
        if (kind == u"folder") {
            QVERIFY(QDir().mkpath(path));
        } else if (kind == u"text") {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("tool,pocket\n1,1\n");
        } else if (kind == u"corrupt") {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray("SQLite format 3\0", 16) + QByteArray(8192, '\x5a'));
        } else if (kind == u"foreign") {
            RawConnection raw(path, u"raw-foreign"_s);
            QVERIFY(raw.exec(u"CREATE TABLE recipes (name TEXT)"_s));
        }
        const QByteArray before = digest(path);
        auto location = kind == u"postgresql"
            ? LibraryLocation::parse(u"postgresql://shop:secret@server/tools"_s)
            : Result<LibraryLocation>(LibraryLocation { path });
        QString error = location ? QString() : location.error().message;
        if (location) {
            auto library = Library::open(location.value());
            QVERIFY(!library);
            error = library.error().message;
            QVERIFY2(error.contains(path), qPrintable(error));
            QCOMPARE(digest(path), before);
        }
        QVERIFY2(error.contains(message), qPrintable(error));
    }

    void readsALocationAsAPathOrAnSqliteUrl()
    {
        QCOMPARE(LibraryLocation::parse(u"sqlite:/tmp/a.sqlite"_s).value().path, u"/tmp/a.sqlite"_s);
        QCOMPARE(LibraryLocation::parse(u"/tmp/b.sqlite"_s).value().path, u"/tmp/b.sqlite"_s);
        QCOMPARE(LibraryLocation::parse(u"/tmp/b.sqlite"_s).value().text(), u"sqlite:/tmp/b.sqlite"_s);
        QVERIFY(!LibraryLocation::parse(u"sqlite:"_s));
        QVERIFY(!LibraryLocation::parse(u"mysql://server/db"_s));
        QVERIFY(LibraryLocation::standard().path.endsWith(u"/library.sqlite"_s));
    }
};

QTEST_GUILESS_MAIN(TestLibrary)
#include "tst_library.moc"
