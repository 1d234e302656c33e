// SPDX-License-Identifier: GPL-3.0-or-later
// A station whose shared library goes away (PgCluster): the status bar says it is offline and how many
// changes wait, a Save is kept on the station and written when the server is back, and a kept write that
// meets another station's change to the same tool is put to the operator with both sides.
#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include "tests/support/pgcluster.h"
#include "tests/ui/sharedtablestories.h"
#include "ui/common/appsettings.h"

using namespace Toffee;
using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

// A station's way back after an outage: the recorder asks again every kRetryMs, from a thread of its own.
constexpr int kBackMs = 6 * HistoryRecorder::kRetryMs;

} // namespace

class TestSharedTablesOffline : public QObject
{
    Q_OBJECT

    PgCluster m_cluster;
    QTemporaryDir m_home; // the password file
    int m_databases = 0;

    LibraryLocation freshLibrary()
    {
        const QString name = u"shop%1"_s.arg(++m_databases);
        QString error;
        if (!m_cluster.createDatabase(name, u"toffee"_s, &error))
            qFatal("%s", qPrintable(error));
        return LibraryLocation::parse(m_cluster.url(u"toffee"_s, name)).value();
    }
    QString socketName() const { return u".s.PGSQL.%1"_s.arg(m_cluster.port()); }
    static QString label(const LibraryStation &s)
    {
        return s.window.findChild<QLabel *>(u"libraryStatusLabel"_s)->text();
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(u"ToffeeTest"_s);
        QApplication::setApplicationName(u"tst_sharedtablesoffline"_s);
        AppSettings().setMachineName(kMachine);
        QString error;
        QVERIFY2(m_cluster.start(&error), qPrintable(error));
        QVERIFY2(m_cluster.createRole(u"toffee"_s, u"s3cret"_s, true, &error), qPrintable(error));
        QVERIFY2(m_cluster.writePassFile(
                     m_home.filePath(u"pgpass"_s), { { u"*"_s, u"toffee"_s, u"s3cret"_s } }, &error),
            qPrintable(error));
        qputenv("PGPASSFILE", m_home.filePath(u"pgpass"_s).toLocal8Bit());
    }

    // The server dies (SIGKILL) with an edit unsaved: Save keeps it on the station, the status bar counts it,
    // and once the server is back it is written, said, and reaches the other station.
    void aSaveWhileTheServerIsDownIsWrittenWhenItIsBack()
    {
        const LibraryLocation at = freshLibrary();
        LibraryStation a(at, u"Station A"_s), b(at, u"Station B"_s);
        startShop(a, b);
        QCOMPARE(label(a), u"Library: "_s + at.displayName());
        a.edit(5, [](Tool &t) { t.description = u"O-flute, resharpened"_s; });
        QString error;
        QVERIFY2(m_cluster.kill9(&error), qPrintable(error));
        QVERIFY(!a.save().shown);
        QVERIFY2(a.status().contains(u"kept on this station"_s), qPrintable(a.status()));
        QVERIFY(!a.document()->isModified());
        QCOMPARE(label(a), u"Library offline — 1 change waiting"_s);
        QVERIFY(!a.window.history()->isAvailable());

        QVERIFY2(m_cluster.restart(&error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(label(a), u"Library: "_s + at.displayName(), kBackMs);
        QVERIFY2(a.status().contains(u"Library back: 1 change written"_s), qPrintable(a.status()));
        QCOMPARE(libraryTable(at).find(5)->description, u"O-flute, resharpened"_s);
        QVERIFY(!a.document()->isModified());
        // B missed the announcement while its link was down: it reads the table again once back.
        QTRY_COMPARE_WITH_TIMEOUT(b.tool(5).description, u"O-flute, resharpened"_s, kBackMs);
        QVERIFY(!b.document()->isModified());
    }

    // A alone loses the server (its socket gone, its connection ended) and saves T5 and T6; B changes T6 and
    // saves. When A is back, T5 is written and A chooses for T6, seeing B's value and its own.
    void aKeptWriteThatMeetsAnotherStationsChangeIsPutToTheOperator_data()
    {
        QTest::addColumn<bool>("keepMine");
        QTest::newRow("keeps mine") << true;
        QTest::newRow("takes theirs") << false;
    }
    void aKeptWriteThatMeetsAnotherStationsChangeIsPutToTheOperator()
    {
        QFETCH(bool, keepMine);
        const LibraryLocation at = freshLibrary();
        QTemporaryDir way; // A's own way to the server's socket, to be cut
        const QString socket = way.filePath(socketName());
        QVERIFY(QFile::link(m_cluster.socketDir() + u'/' + socketName(), socket));
        QFile passFile(m_home.filePath(u"pgpass"_s)); // the password file names the socket's folder
        QVERIFY(passFile.open(QIODevice::Append));
        passFile.write(
            way.path().toUtf8() + ':' + QByteArray::number(m_cluster.port()) + ":*:toffee:s3cret\n");
        passFile.close();
        LibraryLocation viaWay = at;
        viaWay.host = way.path();
        viaWay.options = u"application_name=stationA"_s;
        LibraryStation a(viaWay, u"Station A"_s), b(at, u"Station B"_s);
        QVERIFY2(a.window.history()->location() == viaWay, qPrintable(a.status()));
        QVERIFY(a.window.history()->isAvailable());
        startShop(a, b);

        QVERIFY(QFile::remove(socket));
        QString error;
        QVERIFY2(m_cluster.exec(u"SELECT pg_terminate_backend(pid) FROM pg_stat_activity WHERE "
                                "application_name = 'stationA'"_s,
                     &error),
            qPrintable(error));
        a.edit(5, [](Tool &t) { t.notes = u"Offline note"_s; });
        a.edit(6, [](Tool &t) { t.lengthGeometry = 60.0; });
        QVERIFY(!a.save().shown);
        QVERIFY2(a.status().contains(u"kept on this station"_s), qPrintable(a.status()));
        QCOMPARE(label(a), u"Library offline — 1 change waiting"_s);
        b.edit(6, [](Tool &t) { t.lengthGeometry = 61.0; });
        QVERIFY(!b.save().shown);

        QVERIFY(QFile::link(m_cluster.socketDir() + u'/' + socketName(), socket));
        ConflictsSeen seen;
        answering<ConflictDialog>(
            [&](ConflictDialog *dialog) {
                LibraryStation::answer(dialog, { { 6, keepMine } }, seen);
            },
            [&] { QTRY_VERIFY_WITH_TIMEOUT(seen.shown, kBackMs); });
        QCOMPARE(seen.tools, QList<int> { 6 });
        QVERIFY2(seen.theirs.front().contains(u"Station B"_s), qPrintable(seen.theirs.front()));
        QVERIFY2(seen.theirs.front().contains(u"61.000 mm"_s), qPrintable(seen.theirs.front()));
        QVERIFY2(seen.mine.front().contains(u"60.000 mm"_s), qPrintable(seen.mine.front()));

        const double chosen = keepMine ? 60.0 : 61.0;
        QTRY_COMPARE(a.tool(6).lengthGeometry, chosen);
        QVERIFY(!a.document()->isModified());
        QVERIFY(!a.window.isWindowModified());
        const ToolTable stored = libraryTable(at);
        QCOMPARE(stored.find(5)->notes, u"Offline note"_s); // written with the replay, no question
        QCOMPARE(stored.find(6)->lengthGeometry, chosen);
        QCOMPARE(a.table(), stored);
        QTRY_COMPARE_WITH_TIMEOUT(b.table(), stored, kLiveMs);
    }
};

QTEST_MAIN(TestSharedTablesOffline)
#include "tst_sharedtablesoffline.moc"
