// SPDX-License-Identifier: GPL-3.0-or-later
// The job check with the history library (a real SQLite file) and at scale: what the library knows of each
// tool, the first thousand tools listed and the rest counted, the library asked only for the tools listed, a
// cancelled check and a file that is no program (tests/model/job/jobcheckcases.h).
#include <cmath>

#include <QTemporaryDir>
#include <QTest>

#include "tests/model/job/jobcheckcases.h"

using namespace Qt::StringLiterals;
using namespace Toffee;
using namespace Toffee::Test;

class TestJobCheckerLibrary : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void readsWhatTheHistoryLibraryKnows()
    {
        QTemporaryDir dir;
        auto library = Library::open(LibraryLocation { dir.filePath(u"library.sqlite"_s) });
        QVERIFY2(library.ok(), qPrintable(library.ok() ? QString() : library.error().message));
        auto event
            = [](int tool, EventKind kind, QDateTime at, std::optional<double> tlo, bool failed = false) {
                  HistoryEvent e;
                  e.id = HistoryEvent::newId();
                  e.machine = u"Carvera"_s;
                  e.tool = tool;
                  e.kind = kind;
                  e.at = at;
                  e.tlo = tlo;
                  if (kind == EventKind::BreakTest)
                      e.failed = failed;
                  return e;
              };
        // T2: probed at the table's time, then failed a break test. T1: probed again an hour ago, to another
        // TLO than the table's. T3: the table has no TLO; the library has one.
        QVERIFY(library.value()
                    ->append({ event(2, EventKind::Probe, kNow.addDays(-2), -33.388),
                        event(2, EventKind::BreakTest, kNow.addDays(-1), -33.9, true),
                        event(1, EventKind::Probe, kNow.addSecs(-3600), 0.05),
                        event(3, EventKind::Probe, kNow.addDays(-3), -7.5) })
                    .ok());
        QTemporaryDir programs;
        const QString path = programs.filePath(u"job.nc"_s);
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("M6 T1\nG1 Z-1 F100\nM6 T2\nG1 Z-1\nM6 T3\nG1 Z-1\nM30\n");
        file.close();
        JobCheckSetup setup;
        setup.useTable(shopTable());
        setup.now = kNow;
        const Library &lib = *library.value();
        const auto report
            = checkJobFile(path, setup, [&lib](QHash<int, ToolFacts> &facts, const QList<int> &tools) {
                  return addLibraryFacts(facts, lib, u"Carvera"_s, tools);
              });
        QVERIFY(report.ok());
        const JobReport &r = report.value();
        QCOMPARE(find(r, FindingKind::BrokenTool, 2)->line, 3);
        const Finding *newer = find(r, FindingKind::StaleTlo, 1);
        QVERIFY(newer);
        QVERIFY2(newer->message.contains(u"0.050 mm"_s) && newer->message.contains(u"1 h ago"_s),
            qPrintable(newer->message));
        // The table says T3 is unmeasured; the library's probe is not the table's TLO.
        QVERIFY(find(r, FindingKind::NotMeasured, 3));
        QCOMPARE(r.program, u"job.nc"_s);
    }

    void listsTheFirstThousandToolsAndCountsTheRest()
    {
        // T8 to T1507, each plunging below the floor: the first 1,000 are listed, the other 500 counted. Then
        // a listed tool again, a counted one again (below the floor again), and T2, in the table and the
        // rack.
        QByteArray program = "G21 G90\n";
        for (int t = 8; t < 1508; ++t)
            program += "M6 T" + QByteArray::number(t) + "\nG1 Z-21 F600\nG0 Z0\n";
        program += "M6 T8\nG1 X10\nM6 T1500\nG1 Z-22\nM6 T2\nM30\n";
        const int firstCounted = 2 + 3 * JobChecker::kMaxListedTools; // M6 T1008
        const JobReport r = check(program, Dialect::Carvera, shopTable(), -20.0, carveraRack());
        QCOMPARE(r.tools.size(), JobChecker::kMaxListedTools);
        QCOMPARE(r.tools.front().number, 8);
        QCOMPARE(r.tools.back().number, 1007);
        QCOMPARE(r.tools.front().loads, 2); // listed, so loaded twice
        QCOMPARE(r.tools.front().loadLines, (QList<int> { 2, 4502 }));
        QCOMPARE(r.tools.front().feedPathMm, 21.0 + 10.0);
        QCOMPARE(r.moreTools, 501);
        QCOMPARE(r.moreLoads, 502);
        QCOMPARE(r.moreFromLine, firstCounted);
        QCOMPARE(r.distinctTools(), 1501);
        // Every feed counted in the total: 1,500 plunges of 21 mm, 10 mm, and 22 mm at 600 mm/min.
        QVERIFY(std::fabs(r.cuttingSeconds - (1500 * 21.0 + 10.0 + 22.0) / 10.0) < 1e-6);

        // One finding per kind for the counted tools: which, how many, how often, from where.
        const auto summary = [&r](FindingKind kind) -> const Finding * {
            for (const Finding &f : r.findings) {
                if (f.kind == kind && f.moreTools > 0)
                    return &f;
            }
            return nullptr;
        };
        const Finding *missing = summary(FindingKind::MissingTool);
        QVERIFY(missing);
        QCOMPARE(missing->moreTools, 500); // not T2: the table has it
        QCOMPARE(missing->count, 501); // T1500 was loaded twice
        QCOMPARE(missing->line, firstCounted);
        QCOMPARE(missing->lines.size(), JobChecker::kMaxLinesPerFinding);
        QCOMPARE(missing->lines.at(1), firstCounted + 3);
        QCOMPARE(missing->tool, -1);
        QCOMPARE(missing->severity(), Severity::Error);
        QVERIFY2(
            missing->message.startsWith(u"500 more tools the table lacks, beyond the first 1000 tools the "
                                        "program loads; the first of them is T1008. Counted, not listed."_s),
            qPrintable(missing->message));
        const Finding *manual = summary(FindingKind::ManualChange);
        QVERIFY(manual);
        QCOMPARE(manual->moreTools, 500); // T2 is in the rack
        QCOMPARE(manual->severity(), Severity::Warning);
        const Finding *below = summary(FindingKind::BelowFloor);
        QVERIFY(below);
        QCOMPARE(below->moreTools, 500);
        QCOMPARE(below->count, 501); // T1500 plunged twice
        QCOMPARE(below->line, firstCounted + 1);
        QVERIFY2(below->message.contains(u"500 more tools feed below the floor of -20.000"_s),
            qPrintable(below->message));
        QVERIFY(!summary(FindingKind::StaleTlo) && !summary(FindingKind::NotMeasured));
        // The listed tools' own findings stay; no counted tool has one of its own.
        QVERIFY(find(r, FindingKind::MissingTool, 1007));
        QVERIFY(find(r, FindingKind::BelowFloor, 1007));
        QVERIFY(!find(r, FindingKind::MissingTool, 1008));
        QVERIFY(!find(r, FindingKind::BelowFloor, 1500));
        // A summary counts once for each tool it stands for: 1,000 + 500 missing, 1,000 + 500 below the
        // floor.
        QCOMPARE(r.errors(), 3000);
        QCOMPARE(r.warnings(), 1500);
        for (qsizetype i = 1; i < r.findings.size(); ++i)
            QVERIFY(r.findings.at(i - 1).line <= r.findings.at(i).line);
        // Length compensation of a counted tool is summed up too.
        QByteArray fanuc;
        for (int t = 1; t <= JobChecker::kMaxListedTools + 3; ++t)
            fanuc += "T" + QByteArray::number(t) + " M6\nG1 Z-1 F100\n";
        const JobReport g43 = check(fanuc, Dialect::Fanuc, shopTable());
        const Finding *none = nullptr;
        for (const Finding &f : g43.findings) {
            if (f.kind == FindingKind::NoLengthCompensation && f.moreTools > 0)
                none = &f;
        }
        QVERIFY(none);
        QCOMPARE(none->moreTools, 3);
        QCOMPARE(none->line, 2 * JobChecker::kMaxListedTools + 2);
    }

    void theLibraryIsAskedOnlyForTheListedTools()
    {
        QByteArray program;
        for (int t = 1; t <= JobChecker::kMaxListedTools + 50; ++t)
            program += "M6 T" + QByteArray::number(t) + "\n";
        QTemporaryDir dir;
        const QString path = dir.filePath(u"many.nc"_s);
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(program);
        file.close();
        JobCheckSetup setup;
        setup.useTable(shopTable());
        setup.now = kNow;
        qsizetype asked = 0;
        const auto report
            = checkJobFile(path, setup, [&asked](QHash<int, ToolFacts> &, const QList<int> &tools) {
                  asked = tools.size();
                  return Result<void>();
              });
        QVERIFY(report.ok());
        QCOMPARE(asked, JobChecker::kMaxListedTools);
        QCOMPARE(report.value().moreTools, 50);
    }

    void aCancelledCheckSaysSoAndAFileThatIsNotOneIsRefused()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"long.nc"_s);
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("M6 T2\n");
        for (int i = 0; i < 300000; ++i)
            file.write("G1 X1 F100\nG1 X0\n");
        file.close();
        JobCheckSetup setup;
        setup.useTable(shopTable());
        int calls = 0;
        const auto report = checkJobFile(
            path, setup, {}, [&calls](qint64 done, qint64 total) { return ++calls < 2 && done < total; });
        QVERIFY(report.ok());
        QVERIFY(report.value().cancelled);
        QVERIFY(report.value().lines < 600001);
        QVERIFY(report.value().lines >= 65536);
        const auto folder = checkJobFile(dir.path(), setup);
        QVERIFY(!folder.ok());
        QVERIFY2(folder.error().message.contains(u"folder"_s), qPrintable(folder.error().message));
        const auto device = checkJobFile(u"/dev/zero"_s, setup);
        QVERIFY(!device.ok());
        QVERIFY2(device.error().message.contains(u"device"_s), qPrintable(device.error().message));
    }
};

QTEST_GUILESS_MAIN(TestJobCheckerLibrary)
#include "tst_jobcheckerlibrary.moc"
