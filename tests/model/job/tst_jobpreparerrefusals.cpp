// SPDX-License-Identifier: GPL-3.0-or-later
// Preparing a program for the machine: what it refuses (stored TLOs of two references, what the controller
// cannot take, a program the controller refuses, leaving the old output as it was), what it leaves alone (a
// deliberate offset) and that what it keeps does not grow with the tools a program loads. Each prepared
// program is run again through the interpreter (tests/model/job/preparedcuts.h).
#include <QTemporaryDir>
#include <QTest>

#include "tests/model/job/preparedcuts.h"

using namespace Qt::StringLiterals;
using namespace Toffee;
using namespace Toffee::Test;

class TestJobPreparerRefusals : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void whatItKeepsDoesNotGrowWithTheToolsAProgramLoads()
    {
        // 300 tools the table lacks, each cutting once: a note for each (measured at its change), the first
        // 100 kept. From T9 up the firmware's break test would halt (it takes them for its wireless probe):
        // none is inserted for them.
        PrepareOptions o;
        o.useStoredTlo = true;
        o.breakTest = true;
        o.tolerance = 0.05;
        o.rack = { 1, 2, 3, 4, 5, 6 };
        o.now = kNow;
        {
            JobPreparer preparer(table(), o);
            qint64 written = 0;
            const auto sink = [&written](QByteArrayView) {
                return ++written > 0;
            };
            int line = 0;
            for (int t = 10; t < 310; ++t) {
                QVERIFY(preparer.feed(QByteArray("M6 T" + QByteArray::number(t)), ++line, sink).ok());
                QVERIFY(preparer.feed("G1 Z-1 F100", ++line, sink).ok());
            }
            QVERIFY(preparer.feed("M30", ++line, sink).ok());
            const auto summary = preparer.finish(sink);
            QVERIFY(summary.ok());
            const PrepareSummary &s = summary.value();
            // No break test from T9 up: a comment says so in its place at each change (kept nowhere).
            QCOMPARE(s.inserted, 300);
            QCOMPARE(written, 901);
            // The first notes, then how many more.
            QCOMPARE(s.notes.size(), JobPreparer::kMaxNotes + 1);
            QCOMPARE(s.notes.front(), u"T10 is not in the table: it is measured at its change."_s);
            QCOMPARE(s.notes.back(),
                u"200 more notes like these, one for each further tool (the first of them T110): counted, "
                u"not "
                "listed."_s);
        }
        // 300 changes round T2 to T8, a cut after each: a break test after each, a change on every third
        // line; the preview in pieces of a bounded size, every insertion in one of them.
        JobPreparer preparer(table(), o);
        const auto sink = [](QByteArrayView) {
            return true;
        };
        int line = 0;
        for (int i = 0; i < 300; ++i) {
            QVERIFY(preparer.feed(QByteArray("M6 T" + QByteArray::number(2 + i % 7)), ++line, sink).ok());
            QVERIFY(preparer.feed("G1 Z-1 F100", ++line, sink).ok());
        }
        QVERIFY(preparer.feed("M30", ++line, sink).ok());
        const auto summary = preparer.finish(sink);
        QVERIFY(summary.ok());
        const PrepareSummary &s = summary.value();
        QVERIFY(s.hunks.size() > 1);
        qsizetype inserted = 0;
        for (const PrepareHunk &hunk : s.hunks) {
            QVERIFY(hunk.size() <= JobPreparer::kMaxHunkRows + JobPreparer::kContextLines);
            inserted += std::count_if(
                hunk.cbegin(), hunk.cend(), [](const PrepareRow &r) { return r.originalLine == 0; });
        }
        QCOMPARE(inserted, s.inserted);
        QVERIFY2(s.inserted >= 300, qPrintable(QString::number(s.inserted)));
    }

    void storedTlosOfTwoReferencesAreRefusedAndTheReferenceToolIsNotBreakTested()
    {
        // T7 and T8 (made fresh) measured against two references: at most one can be the machine's.
        ToolTable mixed = table();
        Tool t8 = *mixed.find(8);
        t8.measuredAt = kNow.addDays(-1);
        t8.referenceMz = -80.0;
        QVERIFY(mixed.replace(8, t8).ok());
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
        const auto refused = prepareJobFile(in, mixed, o, dir.filePath(u"out.nc"_s));
        QVERIFY(!refused);
        QVERIFY2(refused.error().message.contains(u"reference MCS Z -80 and T7's against -72.3"_s),
            qPrintable(refused.error().message));
        QVERIFY(!QFile::exists(dir.filePath(u"out.nc"_s)));
        // Told the machine's reference (the window, connected), the other one is measured at its change.
        o.machineReferenceMz = -72.3;
        const auto prepared = prepareJobFile(in, mixed, o, dir.filePath(u"out.nc"_s));
        QVERIFY(prepared);
        QCOMPARE(prepared.value().inserted, 2);
        QVERIFY(
            prepared.value().notes.join(u'\n').contains(u"T8's stored TLO was measured against reference MCS "
                                                        "Z -80, but the machine's is -72.3"_s));
        // T1's TLO is 0: the community firmware takes it for none and would not compare (seen on it). It goes
        // in as 0.001 first, and is tested as every other tool.
        PrepareOptions test;
        test.breakTest = true;
        PrepareSummary summary;
        const QByteArray withT1 = prepare("M6 T1\nG1 Z-1 F100\nM6 T2\nG1 Z-1\nM30\n", test, &summary);
        QCOMPARE(withT1.count("M491.1"), 2);
        QCOMPARE(summary.untestedTools, 0);
        const qsizetype nudge = withT1.indexOf("M493.3 Z0.001 (Toffee: T1's TLO 0.000 as 0.001 mm");
        QVERIFY2(nudge >= 0 && nudge < withT1.indexOf("M491.1"), withT1.constData());
        // T9 on: the firmware's break test takes them for its wireless probe and halts (seen on it).
        summary = {};
        const QByteArray withT9 = prepare("M6 T2\nG1 Z-1 F100\nM6 T9\nG1 Z-1\nM30\n", test, &summary);
        QCOMPARE(withT9.count("M491.1"), 1);
        QVERIFY(summary.notes.join(u'\n').contains(u"T9 is not break-tested"_s));
        QCOMPARE(summary.untestedTools, 1); // toffee-cli exits 1: the preparation is incomplete
    }

    void aDeliberateOffsetIsLeftAsItIs()
    {
        PrepareOptions o;
        o.dialect = Dialect::Fanuc;
        PrepareSummary summary;
        const QByteArray program = "T7 M6\nG43 H2 Z10\nG1 Z-1 F100\nM30\n";
        QCOMPARE(prepare(program, o, &summary), program);
        QCOMPARE(summary.inserted, 0);
    }

    void refusesWhatTheControllerCannotTake()
    {
        QString error;
        PrepareOptions fanuc;
        fanuc.dialect = Dialect::Fanuc;
        fanuc.breakTest = true;
        QVERIFY(prepare("T1 M6\n", fanuc, nullptr, &error).isEmpty());
        QVERIFY2(error.contains(u"for the Carvera"_s), qPrintable(error));
        PrepareOptions aerotech;
        aerotech.dialect = Dialect::Aerotech;
        QVERIFY(prepare("G1 X1 F10\n", aerotech, nullptr, &error).isEmpty());
        QVERIFY2(error.contains(u"G143"_s), qPrintable(error));
        PrepareOptions small;
        small.breakTest = true;
        small.tolerance = 0.01;
        QVERIFY(prepare("M6 T2\n", small, nullptr, &error).isEmpty());
        QVERIFY2(error.contains(u"from 0.02 mm"_s), qPrintable(error));
        PrepareOptions nothing;
        QVERIFY(prepare("M6 T2\n", nothing, nullptr, &error).isEmpty());
        QVERIFY2(error.contains(u"--use-stored-tlo"_s), qPrintable(error));
    }

    void aProgramTheControllerRefusesIsNotPreparedAndTheOldOutputStays()
    {
        QTemporaryDir dir;
        const QString in = dir.filePath(u"job.nc"_s);
        const QString out = dir.filePath(u"prepared.nc"_s);
        QFile file(in);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("M6 T2\nG1 X1 F100\nG7\nM30\n");
        file.close();
        QFile old(out);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("the old prepared program\n");
        old.close();
        PrepareOptions o;
        o.breakTest = true;
        const auto result = prepareJobFile(in, table(), o, out);
        QVERIFY(!result);
        QCOMPARE(result.error().line, 3);
        QVERIFY2(result.error().text().contains(u"G7"_s), qPrintable(result.error().text()));
        QVERIFY(old.open(QIODevice::ReadOnly));
        QCOMPARE(old.readAll(), QByteArray("the old prepared program\n"));
        const auto same = prepareJobFile(in, table(), o, in);
        QVERIFY(!same);
        QVERIFY2(same.error().message.contains(u"another file"_s), qPrintable(same.error().message));
    }
};

QTEST_GUILESS_MAIN(TestJobPreparerRefusals)
#include "tst_jobpreparerrefusals.moc"
