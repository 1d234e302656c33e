// SPDX-License-Identifier: GPL-3.0-or-later
// Crash-safe saving, proved: a process saving tables is killed at random moments, many times; the file is
// always the old table or the new one, whole, never damaged.
#include <QDir>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

#include "model/formats/tablefile.h"
#include "tests/support/testtables.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestCrashSafeSave : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void survivesBeingKilledMidSave_data()
    {
        QTest::addColumn<QString>("suffix");
        QTest::newRow("json") << u"json"_s;
        QTest::newRow("tbl") << u"tbl"_s;
        QTest::newRow("csv") << u"csv"_s;
    }
    void survivesBeingKilledMidSave()
    {
        QFETCH(QString, suffix);
        QTemporaryDir dir;
        const QString path = dir.filePath(u"tools."_s + suffix);
        const auto format = *formatForPath(path);
        // What a format holds of the tables is what must come back: compare what it writes.
        const QByteArray a = writeTable(Test::generatedTable(3000, 1), format);
        const QByteArray b = writeTable(Test::generatedTable(3000, 2), format);
        QVERIFY(a != b);
        QVERIFY(saveTableFile(path, Test::generatedTable(3000, 1), format).ok());

        QRandomGenerator random(7);
        int kills = 0;
        for (int round = 0; round < 25; ++round) {
            QProcess worker;
            worker.start(QStringLiteral(TOFFEE_TESTS_DIR "/toffee-save-worker"), { path });
            QVERIFY(worker.waitForReadyRead(10000)); // it has started saving
            QTest::qWait(int(random.bounded(1, 40)));
            worker.kill(); // SIGKILL: no chance to clean up
            QVERIFY(worker.waitForFinished(5000));
            kills += worker.exitStatus() == QProcess::CrashExit;

            auto loaded = loadTableFile(path);
            QVERIFY2(loaded.ok(), qPrintable(loaded.error().text()));
            const QByteArray now = writeTable(loaded.value(), format);
            QVERIFY2(now == a || now == b, "the file is neither the old table nor the new one");
        }
        QVERIFY(kills > 20); // it really was killed, not finished
        // QSaveFile's temporary files may be left behind by a kill, but never in the table's place.
        const QStringList left = QDir(dir.path()).entryList(QDir::Files);
        QVERIFY(left.contains(u"tools."_s + suffix));
    }
};

QTEST_GUILESS_MAIN(TestCrashSafeSave)
#include "tst_crashsafesave.moc"
