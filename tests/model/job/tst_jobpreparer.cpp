// SPDX-License-Identifier: GPL-3.0-or-later
// Preparing a program for the machine: each prepared program is run again through the interpreter, and every
// cutting move must reach the original's work position with the loaded tool's own offset from the table.
// What it refuses and leaves alone: tst_jobpreparerrefusals.
#include <QTemporaryDir>
#include <QTest>

#include "tests/model/job/preparedcuts.h"

using namespace Qt::StringLiterals;
using namespace Toffee;
using namespace Toffee::Test;

class TestJobPreparer : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void theCarveraRestoresFreshStoredOffsetsAfterManualChanges()
    {
        PrepareOptions o;
        o.useStoredTlo = true;
        o.rack = { 1, 2, 3, 4, 5, 6 };
        PrepareSummary summary;
        const QByteArray prepared = prepare(kCarveraJob, o, &summary);
        const QList<QByteArray> lines = prepared.split('\n');
        QVERIFY(lines.contains("M6 T2")); // the rack: the machine measures it at the change
        const qsizetype t7 = lines.indexOf(
            "M6 T7 H-5.25 (Toffee: was \"M6 T7\": T7 takes its stored TLO instead of a probe) (the chamfer)");
        QVERIFY2(t7 > 0, prepared.constData());
        QCOMPARE(lines.at(t7 + 1), "M493.2 T7 (Toffee: T7 is the tool in the spindle)");
        QVERIFY2(lines.at(t7 + 2).startsWith(
                     "M493.3 Z-5.25 (Toffee: T7's stored TLO, measured 2026-11-23 12:00 UTC "
                     "against reference MCS Z -72.3)"),
            lines.at(t7 + 2).constData());
        QVERIFY(lines.contains("M6 T8")); // stale: measured at the change
        QCOMPARE(summary.inserted, 2);
        QCOMPARE(summary.changed, 1);
        QCOMPARE(summary.cuttingMoves, 5);
        QVERIFY(summary.notes.join(u'\n').contains(u"T2 is in the rack"_s));
        QVERIFY(summary.notes.join(u'\n').contains(u"T8's stored TLO is older than the stale limit (7 d)"_s));
        verifyEveryNewLineSaysWhy(kCarveraJob, prepared);
        verifyCutsWithEachToolsOffset(kCarveraJob, prepared, Dialect::Carvera);
        // The preview: the change with its context, the original on the left.
        QCOMPARE(summary.hunks.size(), 1);
        const PrepareHunk &hunk = summary.hunks.front();
        QVERIFY(std::any_of(hunk.cbegin(), hunk.cend(), [](const PrepareRow &r) {
            return r.originalLine == 8 && r.original == u"M6 T7 (the chamfer)"_s
                && r.prepared.startsWith(u"M6 T7 H"_s);
        }));
        QVERIFY(std::any_of(hunk.cbegin(), hunk.cend(), [](const PrepareRow &r) {
            return r.originalLine == 0 && r.prepared.startsWith(u"M493.2 T7"_s);
        }));
        // A TLO set by hand is not a measurement: its tool is measured at its change, not restored.
        ToolTable byHand = table();
        Tool handSet = *byHand.find(7);
        handSet.tloSource = TloSource::Manual;
        QVERIFY(byHand.replace(7, handSet).ok());
        QTemporaryDir dir;
        const QString in = dir.filePath(u"job.nc"_s);
        QFile file(in);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(kCarveraJob);
        file.close();
        o.now = kNow;
        const auto manual = prepareJobFile(in, byHand, o, dir.filePath(u"out.nc"_s));
        QVERIFY(manual);
        QCOMPARE(manual.value().inserted, 0);
        QVERIFY(manual.value().notes.join(u'\n').contains(u"T7's TLO was set by hand"_s));
    }

    // A stored TLO that does not say which reference it was measured against is not restored (as the window's
    // Restore refuses it): the tool is measured at its change, and the note says why.
    void aTloWithoutItsReferenceIsNotRestored()
    {
        ToolTable unknown = table();
        Tool t7 = *unknown.find(7);
        t7.referenceMz.reset();
        QVERIFY(unknown.replace(7, t7).ok());
        QTemporaryDir dir;
        const QString in = dir.filePath(u"job.nc"_s);
        QFile file(in);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(kCarveraJob);
        file.close();
        PrepareOptions o;
        o.useStoredTlo = true;
        o.rack = { 1, 2, 3, 4, 5, 6 };
        o.now = kNow;
        const QString out = dir.filePath(u"out.nc"_s);
        const auto summary = prepareJobFile(in, unknown, o, out);
        QVERIFY(summary);
        QCOMPARE(summary.value().inserted, 0);
        QCOMPARE(summary.value().changed, 0);
        QVERIFY2(summary.value().notes.join(u'\n').contains(
                     u"T7's stored TLO does not say which reference it was measured against"_s),
            qPrintable(summary.value().notes.join(u'\n')));
        QFile written(out);
        QVERIFY(written.open(QIODevice::ReadOnly));
        const QByteArray prepared = written.readAll();
        QVERIFY2(
            prepared.contains("M6 T7 (the chamfer)\n") && !prepared.contains("M493.3"), prepared.constData());
    }

    // A tool loaded twice is tested after each of its stints, and neither comment calls its cut the last.
    void aToolLoadedAgainIsTestedAfterEachStint()
    {
        PrepareOptions o;
        o.breakTest = true;
        o.tolerance = 0.05;
        const QByteArray job = "M6 T2\nG1 Z-1 F100\nM6 T7\nG1 Z-1 F100\nM6 T2\nG1 X5 F100\nM30\n";
        const QByteArray prepared = prepare(job, o);
        QVERIFY2(!prepared.contains("last cut"), prepared.constData());
        QCOMPARE(
            prepared.count("M491.1 H0.05 (Toffee: break test of T2 after its cuts up to original line "), 2);
        QVERIFY2(prepared.contains("break test of T2 after its cuts up to original line 2,"),
            prepared.constData());
        QVERIFY2(prepared.contains("break test of T2 after its cuts up to original line 6,"),
            prepared.constData());
    }

    void theCarveraBreakTestsEachToolAfterItsLastCut()
    {
        PrepareOptions o;
        o.breakTest = true;
        o.tolerance = 0.05;
        PrepareSummary summary;
        const QByteArray prepared = prepare(kCarveraJob, o, &summary);
        const QList<QByteArray> lines = prepared.split('\n');
        // T2: the spindle turns, so it stops first; the test comes before the next change.
        const qsizetype t7 = lines.indexOf("M6 T7 (the chamfer)");
        QCOMPARE(lines.at(t7 - 2), "M5 (Toffee: the spindle stops for T2's break test)");
        QCOMPARE(lines.at(t7 - 1),
            "M491.1 H0.05 (Toffee: break test of T2 after its cuts up to original line 6, "
            "tolerance 0.05 mm)");
        // T7: the program stopped the spindle itself.
        const qsizetype t8 = lines.indexOf("M6 T8");
        QCOMPARE(lines.at(t8 - 1),
            "M491.1 H0.05 (Toffee: break test of T7 after its cuts up to original line 10, "
            "tolerance 0.05 mm)");
        QCOMPARE(lines.at(t8 - 2), "M5");
        // T8: before the end.
        const qsizetype end = lines.indexOf("M30");
        QVERIFY(lines.at(end - 1).startsWith(
            "M491.1 H0.05 (Toffee: break test of T8 after its cuts up to original line 14"));
        QCOMPARE(summary.inserted, 4);
        verifyEveryNewLineSaysWhy(kCarveraJob, prepared);
        verifyCutsWithEachToolsOffset(kCarveraJob, prepared, Dialect::Carvera);
        // A program with no end: the last test is appended.
        const QByteArray open = prepare("M6 T2\nG1 Z-1 F100\n", o);
        QVERIFY(open.endsWith("tolerance 0.05 mm)\n"));
    }

    void theCarveraTakesBothAtOnce()
    {
        PrepareOptions o;
        o.useStoredTlo = true;
        o.breakTest = true;
        const QByteArray prepared = prepare(kCarveraJob, o);
        QVERIFY(prepared.contains("M493.3 Z-5.25"));
        QCOMPARE(prepared.count("M491.1 H0.1"), 3);
        verifyCutsWithEachToolsOffset(kCarveraJob, prepared, Dialect::Carvera);
    }

    void theG43ControllersGetTheMissingG43AndNothingElse_data()
    {
        QTest::addColumn<int>("dialect");
        QTest::addColumn<QByteArray>("program");
        QTest::addColumn<QByteArray>("inserted");
        QTest::newRow("FANUC") << int(Dialect::Fanuc)
                               << QByteArray(
                                      "G21 G90 G17\nT1 M6\nG43 H1 G0 Z50\nG1 Z-1 F100\nG28 G91 Z0\nG90\n"
                                      "T2 M6\nG0 X5 Y5\nG0 Z10\nG1 Z-3 F200\nT7 M6\nG43 H7 Z5\nG1 Z-1\nG55\n"
                                      "G98 G83 X10 Y10 Z-5 R2 Q1 F100\nX20\nG80\nM30\n")
                               << QByteArray(
                                      "G43 H2 (Toffee: no G43 for T2 after its change at original line 7)");
        QTest::newRow("Allen-Bradley 9")
            << int(Dialect::AllenBradley9) << QByteArray("G90\nT2 M6\nG0 X1\nG1 Z-1 F100\nG1 X3\nM30\n")
            << QByteArray("G43 H2 (Toffee: no G43 for T2 after its change at original line 2)");
        QTest::newRow("FAGOR 8055M")
            << int(Dialect::Fagor8055M) << QByteArray("G90\nT7 M6\nG1 Z-1 F100\nG1 X3\nM30\n")
            << QByteArray("G43 D7 (Toffee: no G43 for T7 after its change at original line 2)");
        QTest::newRow("LinuxCNC")
            << int(Dialect::LinuxCnc)
            << QByteArray("G21 G90\nT1 M6\nG43\nG1 Z-1 F100\nT2 M6\nG53 G0 Z0\nG0 X10\n"
                          "G0 Z5\nG1 Z-2 F100\nM2\n")
            << QByteArray("G43 H2 (Toffee: no G43 for T2 after its change at original line 5)");
        QTest::newRow("grblHAL")
            << int(Dialect::GrblHal)
            << QByteArray("G21 G90\nM6 T1\nG43 H1\nG1 Z-1 F100\nM6 T2\nG0 X10\nG1 Z-2 F100\nM30\n")
            << QByteArray("G43 H2 (Toffee: no G43 for T2 after its change at original line 5)");
    }

    void theG43ControllersGetTheMissingG43AndNothingElse()
    {
        QFETCH(int, dialect);
        QFETCH(QByteArray, program);
        QFETCH(QByteArray, inserted);
        PrepareOptions o;
        o.dialect = Dialect(dialect);
        PrepareSummary summary;
        const QByteArray prepared = prepare(program, o, &summary);
        QCOMPARE(summary.inserted, 1);
        QCOMPARE(summary.changed, 0);
        QVERIFY2(prepared.split('\n').contains(inserted), prepared.constData());
        QCOMPARE(prepared.count("(Toffee: "), 1);
        verifyCutsWithEachToolsOffset(program, prepared, Dialect(dialect));
        // Prepared again: nothing is missing any more.
        PrepareSummary again;
        QCOMPARE(prepare(prepared, o, &again), prepared);
        QCOMPARE(again.inserted, 0);
    }
};

QTEST_GUILESS_MAIN(TestJobPreparer)
#include "tst_jobpreparer.moc"
