// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli on a shared library, on a real PostgreSQL server the test starts (PgCluster): a machine's table
// put there from a file, a probe recorded into it, read back; and what a script is told when the URL is
// wrong.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/support/pgcluster.h"
#include "tests/support/processes.h"

using namespace Toffee::Test;
using namespace Qt::StringLiterals;

namespace {

QJsonObject json(const Run &run)
{
    return QJsonDocument::fromJson(run.out.trimmed().split('\n').last()).object();
}

} // namespace

class TestSharedLibraryCli : public QObject
{
    Q_OBJECT

    PgCluster m_cluster;
    QTemporaryDir m_dir;

    QString url(const QString &user = u"shop"_s) const { return m_cluster.url(user, u"tools"_s); }
    Run toffee(const QStringList &arguments, const QString &user = u"shop"_s) const
    {
        return cli(QStringList { u"--json"_s, u"--library"_s, url(user) } + arguments);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QString error;
        QVERIFY2(m_cluster.start(&error), qPrintable(error));
        QVERIFY(m_cluster.createRole(u"shop"_s, u"Sh0p-pw"_s, true, &error));
        QVERIFY(m_cluster.createRole(u"viewer"_s, u"V1ew-pw"_s, true, &error));
        QVERIFY(m_cluster.createDatabase(u"tools"_s, u"shop"_s, &error));
        QVERIFY(m_cluster.writePassFile(m_dir.filePath(u"pgpass"_s),
            { { u"*"_s, u"shop"_s, u"Sh0p-pw"_s }, { u"*"_s, u"viewer"_s, u"V1ew-pw"_s } }, &error));
        qputenv("PGPASSFILE", m_dir.filePath(u"pgpass"_s).toLocal8Bit()); // the children's libpq reads it
        // The children's own SQLite library (their outbox) is the test's, not the user's.
        qputenv("XDG_DATA_HOME", m_dir.filePath(u"data"_s).toLocal8Bit());
    }

    void putsATableRecordsAProbeIntoItAndReadsItBack()
    {
        Run run = toffee({ u"library"_s, u"put"_s, u"--machine"_s, u"C1"_s,
            QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json") });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        const int tools = json(run).value(u"tools"_s).toInt();
        QVERIFY(tools > 1);
        run = toffee({ u"library"_s, u"put"_s, u"--machine"_s, u"C1"_s,
            QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json") });
        QCOMPARE(run.exitCode, 2);
        QVERIFY(json(run).value(u"error"_s).toString().contains(u"already has a tool table for C1"_s));

        run = toffee({ u"--machine"_s, u"C1"_s, u"--emulator"_s, u"probe"_s });
        QVERIFY2(run.exitCode == 0, run.err.constData());
        const double tlo = json(run).value(u"tlo"_s).toDouble();

        run = toffee({ u"library"_s, u"tables"_s });
        QCOMPARE(run.exitCode, 0);
        const QJsonObject listed = json(run).value(u"tables"_s).toArray().first().toObject();
        QCOMPARE(listed.value(u"machine"_s).toString(), u"C1"_s);
        QCOMPARE(listed.value(u"tools"_s).toInt(), tools);
        QCOMPARE(json(run).value(u"read_only"_s).toBool(), false);

        const QString out = m_dir.filePath(u"c1.json"_s);
        QCOMPARE(toffee({ u"library"_s, u"get"_s, u"--machine"_s, u"C1"_s, u"-o"_s, out }).exitCode, 0);
        run = cli({ u"--json"_s, u"show"_s, out });
        const QJsonObject t1 = json(run).value(u"tools"_s).toArray().first().toObject();
        QCOMPARE(t1.value(u"number"_s).toInt(), 1);
        QCOMPARE(t1.value(u"measured_tlo"_s).toDouble(), tlo); // the probe reached the machine's table
        run = toffee({ u"history"_s, u"--machine"_s, u"C1"_s });
        QCOMPARE(json(run).value(u"events"_s).toArray().size(), 1);
    }

    void aProbeWhoseServerDiesIsKeptAndSentOnceItIsBack()
    {
        Emulator emulator(m_dir.filePath(u"tty"_s), { u"--probe-ms"_s, u"1500"_s });
        QVERIFY(emulator.started());
        QProcess probe;
        probe.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"),
            { u"--json"_s, u"--library"_s, url(), u"--machine"_s, u"C2"_s, u"--port"_s,
                m_dir.filePath(u"tty"_s), u"probe"_s });
        QTest::qWait(700); // the library is open and the tool is on the setter
        QString error;
        QVERIFY2(m_cluster.kill9(&error), qPrintable(error));
        QVERIFY(probe.waitForFinished(30000));
        const QString err = QString::fromUtf8(probe.readAllStandardError());
        QCOMPARE(probe.exitCode(), 0); // the machine measured: the probe itself succeeded
        QVERIFY2(err.contains(u"is kept on this computer"_s) && err.contains(u"will be sent the next time"_s),
            qPrintable(err));
        QVERIFY2(m_cluster.restart(&error), qPrintable(error));
        for (int i = 0; i < 2; ++i) { // the first sends what waits; the second finds nothing more to send
            // C2, a machine of its own (on a serial port; C1 is the built-in emulator): this probe alone.
            const Run run = toffee({ u"history"_s, u"--machine"_s, u"C2"_s, u"--tool"_s, u"1"_s });
            QCOMPARE(run.exitCode, 0);
            QCOMPARE(json(run).value(u"events"_s).toArray().size(), 1);
            QCOMPARE(run.err.contains("sent 1 measurement kept on this computer"), i == 0);
        }
    }

    void aReadOnlyRoleReadsAndIsRefusedAWrite()
    {
        QString error;
        QVERIFY2(m_cluster.grantReadOnly(u"viewer"_s, u"tools"_s, &error), qPrintable(error));
        Run run = toffee({ u"library"_s, u"tables"_s }, u"viewer"_s);
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(json(run).value(u"read_only"_s).toBool(), true);
        run = toffee({ u"library"_s, u"put"_s, u"--machine"_s, u"C2"_s,
                         QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json") },
            u"viewer"_s);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(
            json(run).value(u"error"_s).toString().contains(u"read-only for viewer"_s), run.out.constData());
    }

    void aWrongUrlSaysWhatToFix_data()
    {
        QTest::addColumn<QString>("library");
        QTest::addColumn<QString>("expected");
        QTest::newRow("a password in it") << u"postgresql://shop:Sh0p-pw@/tools"_s << u"never stores one"_s;
        QTest::newRow("no database") << u"postgresql://shop@server"_s << u"names no database"_s;
        QTest::newRow("an unknown setting")
            << u"postgresql://shop@server/tools?colour=red"_s << u"\"colour\""_s;
        QTest::newRow("another scheme") << u"mysql://shop@server/tools"_s << u"not from \"mysql\""_s;
    }
    void aWrongUrlSaysWhatToFix()
    {
        QFETCH(QString, library);
        QFETCH(QString, expected);
        const Run run = cli({ u"--json"_s, u"--library"_s, library, u"library"_s, u"tables"_s });
        QCOMPARE(run.exitCode, 2);
        const QString error = json(run).value(u"error"_s).toString();
        QVERIFY2(error.contains(expected), qPrintable(error));
        QVERIFY(!error.contains(u"Sh0p-pw"_s));
    }

    void aMissingDatabaseAndAWrongPasswordAreNamed()
    {
        Run run = cli({ u"--json"_s, u"--library"_s, m_cluster.url(u"shop"_s, u"nosuch"_s), u"library"_s,
            u"tables"_s });
        QCOMPARE(run.exitCode, 2);
        QVERIFY(json(run).value(u"error"_s).toString().contains(u"has no database \"nosuch\""_s));
        run = toffee({ u"library"_s, u"tables"_s }, u"ghost"_s);
        QCOMPARE(run.exitCode, 2);
        QVERIFY(json(run).value(u"error"_s).toString().contains(u"password file"_s));
    }
};

QTEST_GUILESS_MAIN(TestSharedLibraryCli)
#include "tst_sharedlibrarycli.moc"
