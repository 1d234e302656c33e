// SPDX-License-Identifier: GPL-3.0-or-later
// Unsaved edits outlive the application, proved: a process editing a table with AutoSave on is killed at
// random moments, many times. Each time, the next start finds its copy, and the copy is the table as it was
// after some edit, whole; the file on disk is untouched; and once discarded, nothing is left.
#include <QDir>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

#include "model/document/autosave.h"
#include "tests/support/processes.h"
#include "tests/support/testtables.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

class TestAutoSaveRecovery : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void recoversEditsAfterAKill()
    {
        QTemporaryDir dir;
        const QString table = dir.filePath(u"tools.json"_s);
        const QString recovery = dir.filePath(u"recovery"_s);
        const ToolTable original = Test::generatedTable(200);
        QVERIFY(saveTableFile(table, original, TableFormat::Json).ok());
        const QByteArray onDisk = Test::readFile(table);

        QRandomGenerator random(11);
        const QDir copies(recovery);
        for (int round = 0; round < 20; ++round) {
            QProcess worker;
            worker.start(QStringLiteral(TOFFEE_TESTS_DIR "/toffee-autosave-worker"), { recovery, table });
            QVERIFY(worker.waitForReadyRead(10000)); // it is editing
            // Killed at a random moment once its edits are protected (tst_autosave covers a kill before
            // that).
            QTRY_VERIFY_WITH_TIMEOUT(!copies.entryList({ u"*.json"_s }, QDir::Files).isEmpty(), 10000);
            QTest::qWait(int(random.bounded(0, 50)));
            worker.kill(); // SIGKILL: no destructor runs, the copy stays
            QVERIFY(worker.waitForFinished(5000));
            QCOMPARE(worker.exitStatus(), QProcess::CrashExit);

            const auto sessions = AutoSave::findRecoverable(recovery);
            QCOMPARE(sessions.size(), 1);
            const AutoSave::Session &session = sessions.first();
            QCOMPARE(session.originalPath, table);
            const auto copy = AutoSave::load(session);
            QVERIFY2(copy.ok(), qPrintable(copy.error().text()));

            // The table after its k-th edit: the original, then T1000 ... T(1000 + k - 1), in order.
            const QList<Tool> &tools = copy.value().tools();
            QVERIFY(tools.size() > original.size());
            QCOMPARE(tools.first(original.size()), original.tools());
            for (qsizetype i = original.size(); i < tools.size(); ++i) {
                QCOMPARE(tools.at(i).number, int(1000 + i - original.size()));
                QCOMPARE(tools.at(i).lengthGeometry, tools.at(i).number / 100.0);
            }
            QCOMPARE(Test::readFile(table), onDisk); // autosave never touches the operator's file
            AutoSave::discard(session);
        }
        QVERIFY2(QDir(recovery).isEmpty(), qPrintable(QDir(recovery).entryList().join(u' ')));
    }
};

QTEST_GUILESS_MAIN(TestAutoSaveRecovery)
#include "tst_autosaverecovery.moc"
