// SPDX-License-Identifier: GPL-3.0-or-later
// The outbox folder (Spool) under a hostile world: a library named by another spelling (a symlink, a
// relative path) still gets what was kept for it; what waits for other libraries is never read; several
// senders at once send each event once and report nothing false; a file with one event the history cannot
// take sends the others and puts that one apart; a file an older Toffee wrote is still sent.
#include <thread>

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include "model/library/library.h"
#include "model/library/spool.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

HistoryEvent probe(int tool, double tlo)
{
    HistoryEvent e;
    e.id = HistoryEvent::newId();
    e.machine = u"C1"_s;
    e.tool = tool;
    e.at = QDateTime(QDate(2026, 11, 21), QTime(8, 0), Qt::UTC).addSecs(tool);
    e.kind = EventKind::Probe;
    e.tlo = tlo;
    return e;
}

qsizetype historySize(const QString &path)
{
    auto library = Library::open({ path });
    return library ? library.value()->history({}).value().size() : -1;
}

} // namespace

class TestSpool : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void aLibraryIsKnownByItselfNotByTheSpellingOfItsPath()
    {
        QTemporaryDir dir;
        const QString real = dir.filePath(u"shop/library.sqlite"_s);
        QVERIFY(QDir().mkpath(dir.filePath(u"shop"_s)));
        QVERIFY(Library::open({ real }));
        QVERIFY(QFile::link(dir.filePath(u"shop"_s), dir.filePath(u"link"_s)));
        const Spool spool(dir.filePath(u"outbox"_s));
        // Kept under three spellings: a symlinked folder, "a/../b", and the path itself.
        QVERIFY(spool.keep({ dir.filePath(u"link/library.sqlite"_s) }, { probe(1, 10.0) }));
        QVERIFY(spool.keep({ dir.filePath(u"shop/../shop/library.sqlite"_s) }, { probe(2, 11.0) }));
        QVERIFY(spool.keep({ real }, { probe(3, 12.0) }));
        QCOMPARE(spool.count({ real }), 3);
        QCOMPARE(spool.count({ dir.filePath(u"link/library.sqlite"_s) }), 3);
        auto library = Library::open({ real });
        const auto sent = spool.send(*library.value());
        QVERIFY(sent);
        QCOMPARE(sent.value().events, 3);
        QCOMPARE(library.value()->history({}).value().size(), 3);
        QCOMPARE(spool.count({ real }), 0);
    }

    // What waits for another library is in that library's folder, never read: a damaged file there is not
    // even noticed (let alone quarantined) when this library sends.
    void whatWaitsForAnotherLibraryIsNeverRead()
    {
        QTemporaryDir dir;
        const LibraryLocation mine { dir.filePath(u"mine.sqlite"_s) };
        const LibraryLocation theirs { dir.filePath(u"theirs.sqlite"_s) };
        const Spool spool(dir.filePath(u"outbox"_s));
        const auto kept = spool.keep(theirs, { probe(1, 10.0) });
        QVERIFY(kept);
        {
            QFile damaged(QFileInfo(kept.value()).absoluteDir().filePath(u"20261121T080000000-x.json"_s));
            QVERIFY(damaged.open(QIODevice::WriteOnly));
            damaged.write("{ not an outbox file");
        }
        const auto own = spool.keep(mine, { probe(2, 11.0) });
        QVERIFY(own);
        QVERIFY(QFileInfo(kept.value()).absolutePath() != QFileInfo(own.value()).absolutePath());
        QCOMPARE(QDir(dir.filePath(u"outbox"_s)).entryList({ u"library-*"_s }, QDir::Dirs).size(), 2);
        auto library = Library::open(mine);
        const auto sent = spool.send(*library.value());
        QVERIFY(sent);
        QCOMPARE(sent.value().events, 1);
        QVERIFY2(sent.value().quarantined.isEmpty(), qPrintable(sent.value().quarantined.join(u'\n')));
        QVERIFY(!QDir(dir.filePath(u"outbox/quarantine"_s)).exists());
        QCOMPARE(spool.count(theirs), 1);
    }

    // Three senders at once, as two toffee-cli and the window may be: each event reaches the history once,
    // and nobody reports a file another sent meanwhile as damaged (5,000 such lines were printed).
    void severalSendersAtOnceSendEachEventOnceAndSayNothingFalse()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"library.sqlite"_s);
        QVERIFY(Library::open({ path }));
        const Spool spool(dir.filePath(u"outbox"_s));
        for (int i = 0; i < 300; ++i)
            QVERIFY(spool.keep({ path }, { probe(i + 1, 10.0 + i / 100.0) }));
        QStringList said[3];
        bool ok[3] = { false, false, false };
        std::vector<std::thread> senders;
        for (int s = 0; s < 3; ++s) {
            senders.emplace_back([&, s] {
                auto library = Library::open({ path }, Library::Options { .station = u"S%1"_s.arg(s) });
                if (!library)
                    return;
                const auto sent = Spool(dir.filePath(u"outbox"_s)).send(*library.value());
                ok[s] = bool(sent);
                if (sent)
                    said[s] = sent.value().quarantined;
            });
        }
        for (std::thread &t : senders)
            t.join();
        for (int s = 0; s < 3; ++s)
            QVERIFY2(said[s].isEmpty(), qPrintable(said[s].join(u'\n')));
        QVERIFY(ok[0] || ok[1] || ok[2]);
        QCOMPARE(historySize(path), 300);
        QCOMPARE(spool.count({ path }), 0);
    }

    // One event the history cannot take (a TLO of 50000 mm, written by hand or by an older Toffee) goes to
    // the quarantine alone; the file's good events are sent, none taken out of the history with it.
    void oneBadEventIsPutApartAndTheOthersAreSent()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"library.sqlite"_s);
        const Spool spool(dir.filePath(u"outbox"_s));
        const auto kept = spool.keep({ path }, { probe(1, 10.0), probe(2, 11.0), probe(3, 12.0) });
        QVERIFY(kept);
        QFile file(kept.value());
        QVERIFY(file.open(QIODevice::ReadOnly));
        QByteArray text = file.readAll();
        file.close();
        text.replace("\"tlo\":11", "\"tlo\":50000");
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(text);
        file.close();
        auto library = Library::open({ path });
        const auto sent = spool.send(*library.value());
        QVERIFY(sent);
        QCOMPARE(sent.value().events, 2);
        QCOMPARE(sent.value().quarantined.size(), 1);
        QVERIFY2(sent.value().quarantined.first().contains(u"1 event(s)"_s)
                && sent.value().quarantined.first().contains(u"50000.000 mm, beyond any tool"_s),
            qPrintable(sent.value().quarantined.first()));
        QCOMPARE(library.value()->history({}).value().size(), 2);
        QVERIFY(!QFile::exists(kept.value()));
        const QStringList apart
            = QDir(dir.filePath(u"outbox/quarantine"_s)).entryList({ u"*.rejected.json"_s });
        QCOMPARE(apart.size(), 1);
        QFile rejected(dir.filePath(u"outbox/quarantine/"_s) + apart.first());
        QVERIFY(rejected.open(QIODevice::ReadOnly));
        QVERIFY(rejected.readAll().contains("50000"));
    }

    // A file an older Toffee wrote at the top of the folder is still found and sent.
    void aFileAnOlderToffeeWroteIsStillSent()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"library.sqlite"_s);
        const Spool spool(dir.filePath(u"outbox"_s));
        const auto kept = spool.keep({ path }, { probe(1, 10.0) });
        QVERIFY(kept);
        QVERIFY(QFile::rename(kept.value(), dir.filePath(u"outbox/"_s) + QFileInfo(kept.value()).fileName()));
        QCOMPARE(spool.count({ path }), 1);
        auto library = Library::open({ path });
        QCOMPARE(spool.send(*library.value()).value().events, 1);
        QCOMPARE(library.value()->history({}).value().size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestSpool)
#include "tst_spool.moc"
