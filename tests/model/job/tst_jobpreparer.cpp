// SPDX-License-Identifier: GPL-3.0-or-later
// Preparing a program for the machine: each prepared program is run again through the interpreter, and every
// cutting move must reach the original's work position with the loaded tool's own offset from the table.
#include <QTemporaryDir>
#include <QTest>

#include "model/gcode/gcodeinterpreter.h"
#include "model/job/jobprepare.h"
#include "model/tooltable.h"

using namespace Qt::StringLiterals;
using namespace Toffee;

namespace {

const QDateTime kNow(QDate(2026, 11, 24), QTime(12, 0), Qt::UTC);

// T1 the reference, T2 and T7 measured yesterday, T8 measured 30 days ago, T9 never; lengths for G43.
ToolTable table()
{
    QList<Tool> tools;
    const struct
    {
        int number;
        std::optional<double> tlo;
        int daysAgo;
        double length;
    } rows[] = { { 1, 0.0, 1, 38.1 }, { 2, -33.388, 1, 71.488 }, { 7, -5.25, 1, 43.35 },
        { 8, -8.0, 30, 46.1 }, { 9, std::nullopt, 0, 52.5 } };
    for (const auto &r : rows) {
        Tool t;
        t.number = r.number;
        t.pocket = r.number;
        t.lengthGeometry = r.length;
        t.measuredTlo = r.tlo;
        if (r.tlo)
            t.measuredAt = kNow.addDays(-r.daysAgo);
        t.referenceMz = -72.3;
        tools << t;
    }
    return ToolTable::fromTools(tools, Units::Millimetre).value();
}

struct Cut
{
    int tool = -1;
    Position work {};
    Position machine {};
};

// Every feed move of `program` as `dialect` runs it with the table's offsets.
QList<Cut> cuts(const QByteArray &program, Dialect dialect)
{
    GCodeInterpreter interpreter(dialect, offsetTableFor(table(), dialect));
    interpreter.setRecordMoves(false);
    QList<Cut> out;
    int line = 0;
    for (const QByteArray &text : program.split('\n')) {
        const auto ran = interpreter.runLine(text, ++line);
        if (!ran) {
            qWarning("%s", qPrintable(ran.error().text()));
            return {};
        }
        if (interpreter.lastBlock().motion == BlockEffect::Motion::Feed)
            out.append({ interpreter.loadedTool(), interpreter.workPosition(), interpreter.position() });
    }
    return out;
}

QByteArray prepare(const QByteArray &program, PrepareOptions options, PrepareSummary *summary = nullptr,
    QString *error = nullptr)
{
    QTemporaryDir dir;
    const QString in = dir.filePath(u"job.nc"_s);
    const QString out = dir.filePath(u"prepared.nc"_s);
    QFile file(in);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write(program);
    file.close();
    options.now = kNow;
    const auto result = prepareJobFile(in, table(), options, out);
    if (!result) {
        if (error)
            *error = result.error().text();
        return {};
    }
    if (summary)
        *summary = result.value();
    QFile written(out);
    return written.open(QIODevice::ReadOnly) ? written.readAll() : QByteArray();
}

// The prepared program cuts where the original does, each cut with the tool's own offset from the table.
void verifyCutsWithEachToolsOffset(const QByteArray &original, const QByteArray &prepared, Dialect dialect)
{
    const QList<Cut> before = cuts(original, dialect);
    const QList<Cut> after = cuts(prepared, dialect);
    QVERIFY(!before.isEmpty());
    QCOMPARE(after.size(), before.size());
    const OffsetTable offsets = offsetTableFor(table(), dialect);
    for (qsizetype i = 0; i < after.size(); ++i) {
        QCOMPARE(after.at(i).tool, before.at(i).tool);
        for (size_t axis = 0; axis < 3; ++axis)
            QCOMPARE(after.at(i).work[axis], before.at(i).work[axis]);
        const double expected = offsets.at(after.at(i).tool).length();
        QVERIFY2(std::fabs(after.at(i).machine[2] - after.at(i).work[2] - expected) < 1e-9,
            qPrintable(u"cut %1 of T%2: machine Z %3, work Z %4, offset %5"_s.arg(i)
                           .arg(after.at(i).tool)
                           .arg(after.at(i).machine[2])
                           .arg(after.at(i).work[2])
                           .arg(expected)));
    }
}

// Every line the preparation added or changed says why.
void verifyEveryNewLineSaysWhy(const QByteArray &original, const QByteArray &prepared)
{
    const QList<QByteArray> old = original.split('\n');
    for (const QByteArray &line : prepared.split('\n')) {
        if (!old.contains(line))
            QVERIFY2(line.contains("(Toffee: "), line.constData());
    }
}

const QByteArray kCarveraJob = "G21 G90\n"
                               "M6 T2\n" // 2: rack tool
                               "M3 S12000\n"
                               "G0 X0 Y0 Z5\n"
                               "G1 Z-1 F300\n"
                               "G1 X20\n" // 6: T2's last cut
                               "G0 Z5\n"
                               "M6 T7 (the chamfer)\n" // 8: manual, fresh
                               "M3 S10000\n"
                               "G1 Z-0.5 F200\n" // 10: T7's last cut
                               "M5\n"
                               "M6 T8\n" // 12: manual, stale
                               "G1 Z-2 F100\n"
                               "G1 X0\n" // 14: T8's last cut
                               "M30\n";

} // namespace

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

QTEST_GUILESS_MAIN(TestJobPreparer)
#include "tst_jobpreparer.moc"
