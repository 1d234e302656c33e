// SPDX-License-Identifier: GPL-3.0-or-later
// Loads, sorts and saves tool tables of 1,000 / 10,000 / 100,000 tools in each format.
// Each case runs in a child process of its own, so its peak memory (VmHWM) is its own.
//   toffee-bench-table                      all cases, a Markdown table on stdout
//   toffee-bench-table --case N FORMAT      one case, one line
#include <algorithm>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSortFilterProxyModel>
#include <QTemporaryDir>
#include <QTextStream>

#include "model/document/tooltablemodel.h"
#include "model/formats/tablefile.h"
#include "tests/support/testtables.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

constexpr int kRepeats = 5;

template<typename F> double medianMs(F &&f)
{
    QList<double> times;
    for (int i = 0; i < kRepeats; ++i) {
        QElapsedTimer timer;
        timer.start();
        f();
        times.append(double(timer.nsecsElapsed()) / 1e6);
    }
    std::sort(times.begin(), times.end());
    return times.at(kRepeats / 2);
}

double peakMegabytes()
{
    QFile status(u"/proc/self/status"_s);
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith("VmHWM:"))
            return line.mid(6).trimmed().split(' ').front().toDouble() / 1024.0;
    }
    return -1;
}

ToolTable benchTable(int count, TableFormat format)
{
    if (format != TableFormat::LinuxCnc)
        return Test::generatedTable(count);
    // LinuxCNC has no wear or TLO columns: bench what it holds, so that what loads is what was saved.
    QList<Tool> tools = Test::generatedTable(count).tools();
    for (Tool &t : tools) {
        t.lengthWear = t.radiusWear = 0;
        t.measuredTlo.reset();
        t.measuredAt = {};
    }
    return ToolTable::fromTools(tools, Units::Millimetre).takeValue();
}

// What an operator's session does with the file: open it, sort the view, save it.
int runCase(int count, TableFormat format)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"bench."_s + formatSuffix(format));
    QByteArray expected;
    {
        const ToolTable generated = benchTable(count, format);
        if (!saveTableFile(path, generated, format).ok())
            qFatal("save failed");
        expected = writeTable(generated, format);
    }

    ToolTable loaded;
    const double loadMs = medianMs([&] {
        loaded = ToolTable();
        auto r = loadTableFile(path);
        if (!r.ok())
            qFatal("load failed: %s", qPrintable(r.error().text()));
        loaded = r.takeValue();
    });
    if (loaded.size() != count || writeTable(loaded, format) != expected)
        qFatal("the loaded table differs from the saved one");

    ToolTableModel model;
    model.resetTable(loaded);
    QSortFilterProxyModel proxy;
    proxy.setSortRole(ToolTableModel::SortRole);
    proxy.setSourceModel(&model);
    bool descending = false;
    const double sortMs = medianMs([&] {
        // What a click on a column header does: sort the view of the whole table by length.
        descending = !descending;
        proxy.sort(
            ToolTableModel::LengthGeometryColumn, descending ? Qt::DescendingOrder : Qt::AscendingOrder);
    });
    const double saveMs = medianMs([&] {
        if (!saveTableFile(path, model.table(), format).ok())
            qFatal("save failed");
    });
    const qint64 bytes = QFileInfo(path).size();
    QTextStream(stdout) << count << ' ' << formatSuffix(format) << ' ' << bytes << ' ' << loadMs << ' '
                        << saveMs << ' ' << sortMs << ' ' << peakMegabytes() << Qt::endl;
    return 0;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    if (args.size() == 4 && args.at(1) == u"--case") {
        const auto format = formatFromName(args.at(3));
        if (!format)
            return 2;
        return runCase(args.at(2).toInt(), *format);
    }

    QTextStream out(stdout);
    out << "| tools | format | file size | load (ms) | save (ms) | sort view (ms) | peak memory (MB) |\n"
        << "|---:|---|---:|---:|---:|---:|---:|\n";
    for (int count : { 1000, 10000, 100000 }) {
        for (const char *format : { "json", "tbl", "csv" }) {
            QProcess child;
            child.start(QCoreApplication::applicationFilePath(),
                { u"--case"_s, QString::number(count), QString::fromLatin1(format) });
            if (!child.waitForFinished(300000) || child.exitCode() != 0) {
                QTextStream(stderr) << "case " << count << ' ' << format
                                    << " failed: " << child.readAllStandardError();
                return 1;
            }
            const QStringList f = QString::fromUtf8(child.readAllStandardOutput()).simplified().split(u' ');
            if (f.size() != 7)
                return 1;
            out << "| " << f[0] << " | " << f[1] << " | " << QString::number(f[2].toDouble() / 1024, 'f', 0)
                << " KiB | " << QString::number(f[3].toDouble(), 'f', 1) << " | "
                << QString::number(f[4].toDouble(), 'f', 1) << " | "
                << QString::number(f[5].toDouble(), 'f', 1) << " | "
                << QString::number(f[6].toDouble(), 'f', 1) << " |\n";
            out.flush();
        }
    }
    out << "\nMedian of " << kRepeats << " runs each; peak memory is the case process's VmHWM.\n";
    return 0;
}
