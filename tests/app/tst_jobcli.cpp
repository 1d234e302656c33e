// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli job check and job prepare as a script runs them: exit codes, JSON, refusals, and memory that
// does not grow with the program (a million lines and five million peak within 10 % of each other) nor with
// the tools it loads (a million distinct tools checked within a ceiling of address space).
#include <sys/resource.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "tests/support/processes.h"
#include "tests/support/programs.h"
#include "tests/support/testclock.h"

using namespace Qt::StringLiterals;
using namespace Toffee::Test;

namespace {

// Under AddressSanitizer memory is the sanitizer's: the bound is for the real build, the ratio for both.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kUnderAsan = true;
#else
constexpr bool kUnderAsan = false;
#endif

const QString kExample = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

void write(const QString &path, const QByteArray &content)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(content);
}

QJsonObject json(const Run &run)
{
    return QJsonDocument::fromJson(run.out).object();
}

// A program that loads `tools` distinct tools, T0 upwards, each with a feed move.
void writeManyTools(const QString &path, int tools)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    QByteArray chunk = "G21 G90\n";
    for (int t = 0; t < tools; ++t) {
        chunk += "T" + QByteArray::number(t) + " M6\nG1 X" + QByteArray::number(t % 2) + " F100\n";
        if (chunk.size() > (1 << 20)) {
            QVERIFY(file.write(chunk) == chunk.size());
            chunk.clear();
        }
    }
    chunk += "M30\n";
    QVERIFY(file.write(chunk) == chunk.size());
}

// toffee-cli run with its address space limited (setrlimit in the child, before exec): a program that needs
// more fails to allocate and aborts.
Run cliWithin(rlim_t bytes, const QStringList &arguments)
{
    QProcess process;
    process.setChildProcessModifier([bytes] {
        const rlimit limit { bytes, bytes };
        setrlimit(RLIMIT_AS, &limit);
    });
    process.start(QStringLiteral(TOFFEE_BIN_DIR "/toffee-cli"), arguments);
    Run run;
    if (!process.waitForFinished(120000)) {
        process.kill();
        process.waitForFinished();
        run.err = "TEST: toffee-cli did not finish";
        return run;
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

} // namespace

class TestJobCli : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        qputenv("HOME", m_home.path().toUtf8());
        setClock(exampleMorningAfter()); // the example's TLOs a day old, whatever day it is
    }

    void exitsByTheWorstFinding_data()
    {
        QTest::addColumn<QByteArray>("program");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("kind");
        // The example table's T1 and T2 are measured, T3 is not; the stale limit is a long one here.
        QTest::newRow("clean") << QByteArray("G21\nM6 T2\nG1 Z-1 F300\nM30\n") << 0 << QString();
        QTest::newRow("a warning") << QByteArray("M6 T3\nG1 Z-1 F300\nM30\n") << 1 << u"not_measured"_s;
        QTest::newRow("an error") << QByteArray("M6 T2\nG1 Z-1 F300\nM6 T42\nM30\n") << 4
                                  << u"missing_tool"_s;
        QTest::newRow("inches") << QByteArray("G20\nM6 T2\nM30\n") << 4 << u"inch_on_carvera"_s;
        QTest::newRow("below the floor") << QByteArray("M6 T2\nG1 Z-30 F300\nM30\n") << 4 << u"below_floor"_s;
    }

    void exitsByTheWorstFinding()
    {
        QFETCH(QByteArray, program);
        QFETCH(int, exitCode);
        QFETCH(QString, kind);
        const QString path = m_dir.filePath(u"job.nc"_s);
        write(path, program);
        const Run run = cli({ u"--json"_s, u"job"_s, u"check"_s, path, u"--table"_s, kExample, u"--z-floor"_s,
            u"-20"_s, u"--stale-days"_s, u"3650"_s, u"--no-history"_s });
        QCOMPARE(run.exitCode, exitCode);
        const QJsonObject o = json(run);
        QCOMPARE(o.value(u"program"_s).toString(), u"job.nc"_s);
        QCOMPARE(o.value(u"dialect"_s).toString(), u"carvera"_s);
        const QJsonArray findings = o.value(u"findings"_s).toArray();
        QCOMPARE(findings.isEmpty(), kind.isEmpty());
        QStringList kinds;
        for (const QJsonValue &f : findings)
            kinds << f.toObject().value(u"kind"_s).toString();
        QVERIFY2(kind.isEmpty() || kinds.contains(kind), qPrintable(kinds.join(u", "_s)));
    }

    void reportsToolsAndFindingsForPeople()
    {
        const QString path = m_dir.filePath(u"people.nc"_s);
        write(path, "M6 T2\nG1 X60 F600\nM6 T9\nG1 Z-1 F100\nM30\n");
        const Run run = cli({ u"job"_s, u"check"_s, path, u"--table"_s, kExample, u"--stale-days"_s,
            u"3650"_s, u"--no-history"_s });
        QCOMPARE(run.exitCode, 4);
        QVERIFY2(run.out.contains("T2  loaded at line 1  TLO 9.652"), run.out.constData());
        QVERIFY2(run.out.contains("cutting 6 s, 60.000 mm"), run.out.constData());
        QVERIFY2(run.out.contains("error: line 3: T9 is not in the tool table"), run.out.constData());
        QVERIFY2(
            run.out.contains("warning: line 3: The machine's rack does not hold T9"), run.out.constData());
        QVERIFY2(run.out.contains("1 error, 1 warning"), run.out.constData());
    }

    void refusesBadInputWithExit2_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        const QString program = QStringLiteral(TOFFEE_SOURCE_DIR "/README.md");
        QTest::newRow("no program") << QStringList { u"job"_s, u"check"_s }
                                    << u"usage: toffee-cli job check"_s;
        QTest::newRow("no such program") << QStringList { u"job"_s, u"check"_s, u"/nonexistent.nc"_s }
                                         << u"/nonexistent.nc: cannot open"_s;
        QTest::newRow("a folder") << QStringList { u"job"_s, u"check"_s, u"/tmp"_s } << u"folder"_s;
        QTest::newRow("bad floor") << QStringList { u"job"_s, u"check"_s, program, u"--z-floor"_s, u"deep"_s }
                                   << u"--z-floor must be a work Z"_s;
        QTest::newRow("bad dialect") << QStringList { u"job"_s, u"check"_s, program, u"--dialect"_s,
            u"heidenhain"_s } << u"--dialect must be one of"_s;
        QTest::newRow("bad rack") << QStringList { u"job"_s, u"check"_s, program, u"--rack"_s, u"6-1"_s }
                                  << u"--rack: a rack is \"none\""_s;
        QTest::newRow("bad stale days") << QStringList { u"job"_s, u"check"_s, program, u"--stale-days"_s,
            u"0"_s } << u"--stale-days must be"_s;
        QTest::newRow("prepare without table") << QStringList { u"job"_s, u"prepare"_s, program, u"-o"_s,
            u"/tmp/x.nc"_s } << u"usage: toffee-cli job prepare"_s;
        QTest::newRow("a break test on FANUC") << QStringList { u"job"_s, u"prepare"_s, program, u"--table"_s,
            kExample, u"--dialect"_s, u"fanuc"_s, u"--break-test"_s, u"-o"_s, u"/tmp/x.nc"_s }
                                               << u"for the Carvera"_s;
        QTest::newRow("tolerance below the minimum") << QStringList { u"job"_s, u"prepare"_s, program,
            u"--table"_s, kExample, u"--break-test"_s, u"--tolerance"_s, u"0.01"_s, u"-o"_s, u"/tmp/x.nc"_s }
                                                     << u"must be from 0.02 mm"_s;
        QTest::newRow("unknown subcommand")
            << QStringList { u"job"_s, u"run"_s } << u"usage: toffee-cli job"_s;
    }

    void refusesBadInputWithExit2()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        const Run run = cli(arguments << u"--no-history"_s);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(QString::fromUtf8(run.err).contains(message), run.err.constData());
    }

    void refusesToWriteOverTheProgramOrTheTable()
    {
        const QString path = m_dir.filePath(u"guarded.nc"_s);
        write(path, "M6 T2\nG1 Z-1 F300\nM30\n");
        const QString table = m_dir.filePath(u"guarded.json"_s);
        QVERIFY(QFile::copy(kExample, table));
        const QByteArray tableBefore = readFile(table);
        const QString link = m_dir.filePath(u"link.nc"_s);
        QVERIFY(QFile::link(path, link));
        const struct
        {
            QString output;
            QString message;
        } refused[] = { { table, u"is the tool table"_s }, { link, u"another file than the program"_s },
            { QString(), u"no file name was given"_s } };
        for (const auto &r : refused) {
            const Run run = cli({ u"job"_s, u"prepare"_s, path, u"--table"_s, table, u"--break-test"_s,
                u"-o"_s, r.output, u"--no-history"_s });
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(QString::fromUtf8(run.err).contains(r.message), run.err.constData());
        }
        QCOMPARE(readFile(table), tableBefore);
        QCOMPARE(readFile(path), QByteArray("M6 T2\nG1 Z-1 F300\nM30\n"));
        // A program the check finds errors in is not prepared: T9 is not in the table.
        write(path, "M6 T2\nG1 Z-1 F300\nM6 T9\nG1 Z-1\nM30\n");
        const Run run = cli({ u"job"_s, u"prepare"_s, path, u"--table"_s, table, u"--break-test"_s, u"-o"_s,
            m_dir.filePath(u"out.nc"_s), u"--no-history"_s });
        QCOMPARE(run.exitCode, 4);
        QVERIFY2(run.err.contains(
                     "the job check finds an error; the first, on line 3: T9 is not in the tool table"),
            run.err.constData());
        QVERIFY(!QFile::exists(m_dir.filePath(u"out.nc"_s)));
    }

    void preparesAProgramThatChecksClean()
    {
        const QString path = m_dir.filePath(u"carvera.nc"_s);
        const QString out = m_dir.filePath(u"prepared.nc"_s);
        write(path, "G21\nM6 T2\nM3 S10000\nG1 Z-1 F300\nG1 X10\nM6 T1\nG1 Z-1\nM30\n");
        Run run = cli({ u"--json"_s, u"job"_s, u"prepare"_s, path, u"--table"_s, kExample, u"--break-test"_s,
            u"--tolerance"_s, u"0.05"_s, u"-o"_s, out, u"--no-history"_s });
        QCOMPARE(run.exitCode, 0);
        // T2 is stopped and tested, and T1 after its cut (the spindle stopped at the change already).
        QCOMPARE(json(run).value(u"inserted"_s).toInt(), 3);
        QCOMPARE(json(run).value(u"cutting_moves_checked"_s).toInt(), 3);
        QVERIFY(json(run).value(u"notes"_s).toArray().isEmpty());
        const QByteArray prepared = readFile(out);
        QCOMPARE(prepared.count("M491.1 H0.05"), 2);
        QVERIFY(prepared.contains("M5 (Toffee: the spindle stops for T2's break test)\n"));
        run = cli({ u"job"_s, u"check"_s, out, u"--table"_s, kExample, u"--stale-days"_s, u"3650"_s,
            u"--no-history"_s });
        QCOMPARE(run.exitCode, 0);
    }

    void checksAProgramInMemoryThatDoesNotGrowWithIt()
    {
        const QString small = m_dir.filePath(u"1m.nc"_s);
        const QString large = m_dir.filePath(u"5m.nc"_s);
        QVERIFY(writeCamProgram(small, 1000000));
        QVERIFY(writeCamProgram(large, 5000000));
        const QStringList common { u"--table"_s, kExample, u"--stale-days"_s, u"3650"_s, u"--z-floor"_s,
            u"-0.5"_s, u"--no-history"_s, u"--json"_s };
        const MeasuredRun one = cliWithPeak(QStringList { u"job"_s, u"check"_s, small } + common);
        const MeasuredRun five = cliWithPeak(QStringList { u"job"_s, u"check"_s, large } + common);
        QCOMPARE(one.exitCode, 4); // the floor is crossed: errors, each counted
        QCOMPARE(five.exitCode, 4);
        QCOMPARE(json(five).value(u"lines"_s).toInteger(), 5000000);
        // The findings are the table's and the floor's (one per tool, each with its count): the controller
        // runs every line.
        for (const QJsonValue &f : json(five).value(u"findings"_s).toArray())
            QVERIFY(f.toObject().value(u"kind"_s).toString() != u"program_error"_s);
        QVERIFY(one.peakKb > 0 && five.peakKb > 0);
        qInfo("job check peak: 1,000,000 lines %ld KB, 5,000,000 lines %ld KB", one.peakKb, five.peakKb);
        QVERIFY2(double(five.peakKb) <= 1.1 * double(one.peakKb),
            qPrintable(u"%1 KB against %2 KB"_s.arg(five.peakKb).arg(one.peakKb)));
        QVERIFY2(five.peakKb <= 60 * 1024 || kUnderAsan, qPrintable(u"%1 KB"_s.arg(five.peakKb)));
        // simulate streams the same way, printing every move.
        const MeasuredRun simOne = cliWithPeak({ u"simulate"_s, u"--dialect"_s, u"carvera"_s, small }, false);
        const MeasuredRun simFive
            = cliWithPeak({ u"simulate"_s, u"--dialect"_s, u"carvera"_s, large }, false);
        QCOMPARE(simOne.exitCode, 0);
        QCOMPARE(simFive.exitCode, 0);
        qInfo("simulate peak: 1,000,000 lines %ld KB, 5,000,000 lines %ld KB", simOne.peakKb, simFive.peakKb);
        QVERIFY2(double(simFive.peakKb) <= 1.1 * double(simOne.peakKb),
            qPrintable(u"%1 KB against %2 KB"_s.arg(simFive.peakKb).arg(simOne.peakKb)));
    }

    void listsTheFirstThousandToolsAndCountsTheRest()
    {
        const QString path = m_dir.filePath(u"many.nc"_s);
        writeManyTools(path, 1200);
        const Run run = cli({ u"job"_s, u"check"_s, path, u"--table"_s, kExample, u"--stale-days"_s,
            u"3650"_s, u"--no-history"_s });
        QCOMPARE(run.exitCode, 4);
        QVERIFY2(run.out.contains("  T999  loaded at line 2000"), run.out.constData());
        QVERIFY2(!run.out.contains("  T1000  loaded"), run.out.constData());
        QVERIFY2(
            run.out.contains("  … and 200 more tools from line 2002 (200 loads): counted, not listed; the "
                             "first 1000 of the program's 1200 distinct tools are listed.\n"),
            run.out.constData());
        QVERIFY2(run.out.contains("error: line 2002: 200 more tools the table lacks, beyond the first 1000 "
                                  "tools the program loads; the first of them is T1000. Counted, not listed. "
                                  "(lines 2002, 2004,"),
            run.out.constData());
        QVERIFY2(run.out.contains("warning: line 2002: 200 more tools the machine's rack does not hold"),
            run.out.constData());
        // The example table holds T1 to T6 (T3 to T6 not measured); T0 is the Carvera's probe. Each counted
        // tool is one error and one warning, as a listed one is.
        QVERIFY2(run.out.contains("1193 errors, 1197 warnings"), run.out.constData());
    }

    // The old check held about a kilobyte for each distinct tool (1.1 GB for a million; 7 KB each with
    // --json) and asked the library twice for each (77 s). Address space, not resident memory, is what the
    // kernel can cap: an ordinary program needs about 60 MB of it (Qt's and ICU's libraries and data mapped,
    // little of it resident), a million tools now 70 MB. The aim, under 200 bytes a tool above an ordinary
    // program, is 260 MB for a million: 256 MB is that, with room for the allocator's arenas.
    void checksAMillionDistinctToolsWithinAFixedAddressSpace()
    {
        if (kUnderAsan)
            QSKIP("AddressSanitizer reserves terabytes of address space");
        const QString path = m_dir.filePath(u"million-tools.nc"_s);
        writeManyTools(path, 1000000);
        const QStringList arguments { u"--json"_s, u"job"_s, u"check"_s, path, u"--table"_s, kExample,
            u"--stale-days"_s, u"3650"_s, u"--no-history"_s };
        constexpr rlim_t kCeiling = 256 * 1024 * 1024;
        const Run run = cliWithin(kCeiling, arguments);
        QVERIFY2(run.exitCode == 4, run.err.constData());
        const QJsonObject o = json(run);
        QCOMPARE(o.value(u"lines"_s).toInteger(), 2000002);
        QCOMPARE(o.value(u"distinct_tools"_s).toInteger(), 1000000);
        QCOMPARE(o.value(u"tools"_s).toArray().size(), 1000);
        QCOMPARE(o.value(u"more_tools"_s).toInteger(), 999000);
        QCOMPARE(o.value(u"more_tool_loads"_s).toInteger(), 999000);
        QCOMPARE(o.value(u"more_tools_from_line"_s).toInteger(), 2002);
        QJsonObject missing;
        for (const QJsonValue &f : o.value(u"findings"_s).toArray()) {
            if (f.toObject().value(u"kind"_s) == u"missing_tool"_s
                && f.toObject().value(u"more_tools"_s).toInteger() > 0)
                missing = f.toObject();
        }
        // T999990 and up are the Carvera's probes, not looked up.
        QCOMPARE(missing.value(u"more_tools"_s).toInteger(), 998990);
        QCOMPARE(missing.value(u"line"_s).toInt(), 2002);
        QVERIFY(missing.value(u"tool"_s).isNull());
        QCOMPARE(o.value(u"errors"_s).toInt(), 993 + 998990);
        // The history library, when there is one, is read for the listed tools only.
        const Run withLibrary = cliWithin(kCeiling,
            QStringList { u"--library"_s, m_dir.filePath(u"library.sqlite"_s) } + arguments.mid(0, 8));
        QVERIFY2(withLibrary.exitCode == 4, withLibrary.err.constData());
        QCOMPARE(json(withLibrary).value(u"distinct_tools"_s).toInteger(), 1000000);
    }

private:
    QTemporaryDir m_home;
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestJobCli)
#include "tst_jobcli.moc"
