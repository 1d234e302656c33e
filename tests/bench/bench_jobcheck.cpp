// SPDX-License-Identifier: GPL-3.0-or-later
// The job check of a long program: toffee-cli job check (lines per second, peak memory), LinuxCNC's own
// interpreter rs274 on the same file where it is installed (the yardstick, in the same run), and the window's
// check (its event loop's longest stall while the check runs on its own thread). Then a hostile program: a
// million distinct tools, against one of the same lines that loads six, for the memory each tool costs.
//   toffee-bench-jobcheck [LINES]      (5,000,000 by default)
#include <QApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTextStream>
#include <QTimer>

#include "model/formats/tablefile.h"
#include "tests/support/processes.h"
#include "tests/support/programs.h"
#include "ui/job/jobcheckdialog.h"
#include "ui/shell/mainwindow.h"

using namespace Qt::StringLiterals;
using namespace Toffee;

namespace {

constexpr int kRuns = 3;
const QString kExample = QStringLiteral(TOFFEE_SOURCE_DIR "/resources/examples/example.json");

struct Timed
{
    double bestMs = 1e300;
    long peakKb = 0;
    int exitCode = -1;
};

Timed timeCli(const QString &program, const QStringList &more = { u"--no-history"_s })
{
    Timed t;
    for (int run = 0; run < kRuns; ++run) {
        QElapsedTimer clock;
        clock.start();
        const Test::MeasuredRun r
            = Test::cliWithPeak(QStringList { u"job"_s, u"check"_s, program, u"--table"_s, kExample,
                                    u"--stale-days"_s, u"3650"_s }
                    + more,
                false);
        t.bestMs = std::min(t.bestMs, double(clock.nsecsElapsed()) / 1e6);
        t.peakKb = std::max(t.peakKb, r.peakKb);
        t.exitCode = r.exitCode;
    }
    return t;
}

// rs274 -g runs a whole program and prints LinuxCNC's canonical commands, which go nowhere here; it stops at
// a tool its table lacks, so it gets the example table as a LinuxCNC tool table.
Timed timeRs274(const QString &rs274, const QString &program, const QString &toolTable)
{
    Timed t;
    for (int run = 0; run < kRuns; ++run) {
        QProcess process;
        process.setStandardOutputFile(QProcess::nullDevice());
        process.setStandardErrorFile(QProcess::nullDevice());
        QElapsedTimer clock;
        clock.start();
        process.start(rs274, { u"-t"_s, toolTable, u"-g"_s, program });
        process.waitForFinished(600000);
        t.bestMs = std::min(t.bestMs, double(clock.nsecsElapsed()) / 1e6);
        t.exitCode = process.exitCode();
    }
    return t;
}

// The window's check of the program: how long, and the longest the event loop went without turning.
void timeWindow(const QString &program, QTextStream &out)
{
    QStandardPaths::setTestModeEnabled(true);
    MainWindow window;
    window.openFile(kExample);
    window.show();
    QElapsedTimer sinceTick;
    qint64 longestGap = 0;
    QTimer ticker;
    QObject::connect(
        &ticker, &QTimer::timeout, &ticker, [&] { longestGap = std::max(longestGap, sinceTick.restart()); });
    QElapsedTimer clock;
    clock.start();
    sinceTick.start();
    ticker.start(5);
    JobCheckDialog *dialog = window.openJobCheck(program);
    while (dialog->isRunning() || !dialog->report())
        QApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    longestGap = std::max(longestGap, sinceTick.elapsed());
    out << "| the window's check (File > Check Job) | "
        << QString::number(double(clock.nsecsElapsed()) / 1e6, 'f', 0) << " ms | longest event-loop stall "
        << longestGap << " ms (aim <= 50) |\n";
}

// `changes` tool changes, each with a feed move: to `changes` distinct tools, or round six.
bool writeToolChanges(const QString &path, int changes, bool distinct)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return false;
    QByteArray chunk = "G21 G90\n";
    for (int t = 0; t < changes; ++t) {
        chunk += "T" + QByteArray::number(distinct ? t : t % 6 + 1) + " M6\nG1 X" + QByteArray::number(t % 2)
            + " F100\n";
        if (chunk.size() > (1 << 20)) {
            if (file.write(chunk) != chunk.size())
                return false;
            chunk.clear();
        }
    }
    chunk += "M30\n";
    return file.write(chunk) == chunk.size();
}

// A million changes to distinct tools against a million round six: the peak's difference is what the distinct
// tools cost; with an empty history library too, which the check reads for the listed tools only.
bool timeDistinctTools(const QTemporaryDir &dir, QTextStream &out)
{
    constexpr int kChanges = 1000000;
    const QString ordinary = dir.filePath(u"six-tools.nc"_s);
    const QString hostile = dir.filePath(u"distinct-tools.nc"_s);
    if (!writeToolChanges(ordinary, kChanges, false) || !writeToolChanges(hostile, kChanges, true))
        return false;
    const Timed six = timeCli(ordinary);
    const Timed distinct = timeCli(hostile);
    const Timed library = timeCli(hostile, { u"--library"_s, dir.filePath(u"library.sqlite"_s) });
    if (six.exitCode != 0 && six.exitCode != 1)
        return false;
    const double perTool = double(distinct.peakKb - six.peakKb) * 1024.0 / kChanges;
    out << "| toffee-cli job check, " << kChanges << " changes to distinct tools | "
        << QString::number(distinct.bestMs, 'f', 0) << " ms | peak "
        << QString::number(double(distinct.peakKb) / 1024.0, 'f', 1) << " MB against "
        << QString::number(double(six.peakKb) / 1024.0, 'f', 1) << " MB for as many changes round six tools ("
        << QString::number(six.bestMs, 'f', 0) << " ms): " << QString::number(perTool, 'f', 1)
        << " bytes per distinct tool (aim < 200) |\n"
        << "| the same, with a history library | " << QString::number(library.bestMs, 'f', 0) << " ms | peak "
        << QString::number(double(library.peakKb) / 1024.0, 'f', 1) << " MB |\n";
    return true;
}

} // namespace

int main(int argc, char *argv[])
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const qint64 lines = argc > 1 ? QByteArray(argv[1]).toLongLong() : 5000000;
    QTemporaryDir dir;
    const QString program = dir.filePath(u"job.nc"_s);
    if (!Test::writeCamProgram(program, lines)) {
        QTextStream(stderr) << "cannot write " << program << '\n';
        return 1;
    }
    QTextStream out(stdout);
    out << "Job check of a " << lines << "-line program (" << QFileInfo(program).size() / (1024 * 1024)
        << " MB), best of " << kRuns << ":\n\n| what | time | figure |\n|---|---:|---|\n";
    const Timed toffee = timeCli(program);
    if (toffee.exitCode < 0 || toffee.exitCode > 4) {
        QTextStream(stderr) << "toffee-cli job check failed (exit " << toffee.exitCode << ")\n";
        return 1;
    }
    out << "| toffee-cli job check | " << QString::number(toffee.bestMs, 'f', 0) << " ms | "
        << QString::number(double(lines) / toffee.bestMs * 1000.0, 'f', 0) << " lines/s, peak "
        << QString::number(double(toffee.peakKb) / 1024.0, 'f', 1) << " MB |\n";
    out.flush();
    const QString rs274 = QStandardPaths::findExecutable(u"rs274"_s);
    if (rs274.isEmpty()) {
        out << "| LinuxCNC rs274 | — | not installed (Debian's linuxcnc-uspace has it) |\n";
    } else {
        const QString toolTable = dir.filePath(u"tool.tbl"_s);
        const auto table = loadTableFile(kExample);
        if (!table || !saveTableFile(toolTable, table.value(), TableFormat::LinuxCnc)) {
            QTextStream(stderr) << "cannot write " << toolTable << '\n';
            return 1;
        }
        const Timed linuxcnc = timeRs274(rs274, program, toolTable);
        out << "| LinuxCNC rs274 -g (the yardstick) | " << QString::number(linuxcnc.bestMs, 'f', 0)
            << " ms | " << QString::number(double(lines) / linuxcnc.bestMs * 1000.0, 'f', 0)
            << " lines/s; Toffee is " << QString::number(linuxcnc.bestMs / toffee.bestMs, 'f', 1)
            << "x as fast"
            << (linuxcnc.exitCode == 0 ? u""_s : u" (rs274 stopped early: exit %1)"_s.arg(linuxcnc.exitCode))
            << " |\n";
    }
    out.flush();
    timeWindow(program, out);
    out.flush();
    if (!timeDistinctTools(dir, out)) {
        QTextStream(stderr) << "the distinct-tools check failed\n";
        return 1;
    }
    return 0;
}
