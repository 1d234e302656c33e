// SPDX-License-Identifier: GPL-3.0-or-later
// The CAM library readers on hostile files (issue 26): an .hsmlib with 1,000,000 attributes on one element
// (refused by the reader's bound) and spread over ordinary tools (read: linear?), and the peak memory of
// reading 32 MB Fusion libraries beside the file's size and beside a whole QJsonDocument of the same file.
// Each case runs in a child process of its own, so its peak memory (VmHWM) is its own.
//   toffee-bench-camimport                         all cases, Markdown tables on stdout
//   toffee-bench-camimport --case read|qjson FILE  one case, one line: milliseconds, peak MB, tools or
//   message
#include <algorithm>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QProcess>
#include <QTemporaryDir>
#include <QTextStream>

#include "model/camimport/camlibrary.h"
#include "model/camimport/camreaders.h"
#include "tests/support/camfiles.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

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

// In the child: the file read as Toffee reads it (or parsed whole by QJsonDocument, the reader before issue
// 26).
int runCase(const QString &kind, const QString &path)
{
    QTextStream out(stdout);
    QElapsedTimer timer;
    timer.start();
    QString outcome;
    if (kind == u"qjson") {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly))
            return 1;
        const QJsonDocument document = QJsonDocument::fromJson(file.readAll());
        outcome = QString::number(document.object().value(u"data"_s).toArray().size());
    } else {
        const auto library = loadCamLibrary(path);
        outcome = library ? QString::number(library.value().tools.size()) : library.error().text();
    }
    const double ms = double(timer.nsecsElapsed()) / 1e6;
    out << ms << '\t' << peakMegabytes() << '\t' << outcome << '\n';
    return 0;
}

struct Measured
{
    double ms = 0;
    double peakMb = 0;
    QString outcome;
};

// The best time of `runs` children, and their largest peak.
Measured measure(const QString &kind, const QString &path, int runs = 3)
{
    Measured best { 1e300, 0, {} };
    for (int i = 0; i < runs; ++i) {
        QProcess child;
        child.start(QCoreApplication::applicationFilePath(), { u"--case"_s, kind, path });
        child.waitForFinished(600000);
        const QStringList fields = QString::fromUtf8(child.readAllStandardOutput()).trimmed().split(u'\t');
        if (fields.size() < 3)
            return { -1, -1, u"the child failed: "_s + QString::fromUtf8(child.readAllStandardError()) };
        best.ms = std::min(best.ms, fields.at(0).toDouble());
        best.peakMb = std::max(best.peakMb, fields.at(1).toDouble());
        best.outcome = fields.at(2);
    }
    return best;
}

bool write(const QString &path, const QByteArray &data)
{
    return Test::writeFile(path, data);
}

QString attributes(int count, int from = 1)
{
    QString out;
    out.reserve(count * 14);
    for (int i = from; i < from + count; ++i)
        out += u" a"_s + QString::number(i) + u"=\"1\""_s;
    return out;
}

// An .hsmlib of ordinary tools, each with 20 attributes, up to `count` attributes in all: UTF-8, as 1,000,000
// of them in UTF-16 would be over the 32 MB a library may have.
QByteArray spreadLibrary(int count)
{
    QString tools;
    const int perTool = 20;
    for (int i = 1; i <= count / perTool; ++i)
        tools += Test::hsmTool(i);
    return u"<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<tool-library xmlns=\"%1\">\n%2</tool-library>\n"_s
        .arg(QLatin1StringView(Test::kHsmNamespace), tools)
        .toUtf8();
}

// Fusion libraries of `tool(n)` for n = 1, 2, … up to just under 32 MB.
template<typename Tool> QByteArray fusionLibraryUpToTheLimit(Tool tool, int *count)
{
    QByteArray json = "{\n  \"version\": 14,\n  \"data\": [\n";
    json.reserve(kMaxCamLibraryBytes);
    for (*count = 0;;) {
        const QByteArray next = tool(*count + 1);
        if (json.size() + next.size() + 16 > kMaxCamLibraryBytes)
            break;
        json += (*count > 0 ? ",\n    " : "    ") + next;
        ++*count;
    }
    return json + "\n  ]\n}\n";
}

QString megabytes(qint64 bytes)
{
    return QString::number(double(bytes) / (1024.0 * 1024.0), 'f', 1) + u" MB"_s;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() == 4 && args.at(1) == u"--case")
        return runCase(args.at(2), args.at(3));

    QTextStream out(stdout);
    QTemporaryDir dir;
    out << "## .hsmlib: attributes (best of 3, each in a process of its own, the file read from disk)\n\n"
        << "| file | size | time (ms) | ns per attribute | outcome |\n|---|---:|---:|---:|---|\n";
    {
        const QString path = dir.filePath(u"one-element.hsmlib"_s);
        const QString tool = QString(Test::hsmTool(1))
                                 .replace(u"<tool guid"_s, u"<tool"_s + attributes(1'000'000) + u" guid"_s);
        write(path, Test::hsmLibrary(tool));
        const Measured m = measure(u"read"_s, path);
        out << "| 1,000,000 attributes on one element (UTF-16, refused) | "
            << megabytes(QFileInfo(path).size()) << " | " << QString::number(m.ms, 'f', 1) << " | "
            << QString::number(m.ms * 1e6 / 1'000'000, 'f', 1) << " | "
            << m.outcome.section(u": "_s, 1).left(70) << "… |\n";
    }
    for (const int count : { 100'000, 1'000'000 }) {
        const QString path = dir.filePath(u"spread-%1.hsmlib"_s.arg(count));
        write(path, spreadLibrary(count));
        const Measured m = measure(u"read"_s, path);
        out << "| " << QLocale(QLocale::English).toString(count) << " attributes over "
            << QLocale(QLocale::English).toString(count / 20) << " tools (UTF-8, read) | "
            << megabytes(QFileInfo(path).size()) << " | " << QString::number(m.ms, 'f', 1) << " | "
            << QString::number(m.ms * 1e6 / count, 'f', 1) << " | " << m.outcome << " tools |\n";
    }

    out << "\n## Fusion JSON: peak memory of reading a 32 MB library (VmHWM of the process, best time of "
           "3)\n\n"
        << "| library | size | tools | time (ms) | peak (MB) | a whole QJsonDocument of it: peak (MB) |\n"
        << "|---|---:|---:|---:|---:|---:|\n";
    {
        const QString path = dir.filePath(u"tiny.json"_s);
        write(path, Test::fusionLibrary({ Test::fusionTool(1) }));
        const Measured m = measure(u"read"_s, path);
        out << "| one tool (the process itself) | " << QFileInfo(path).size() << " B | " << m.outcome << " | "
            << QString::number(m.ms, 'f', 1) << " | " << QString::number(m.peakMb, 'f', 1) << " | — |\n";
    }
    const auto fusion = [](int n) {
        return Test::fusionTool(n);
    };
    const auto minimal = [](int n) -> QByteArray {
        return R"({"unit": "mm", "post-process": {"number": )" + QByteArray::number(n) + "}}";
    };
    for (const auto &[name, library] : { std::pair { "Fusion's own tools (holder, presets, …)", 0 },
             std::pair { "the smallest tools (unit and number only)", 1 } }) {
        int count = 0;
        const QByteArray json = library == 0 ? fusionLibraryUpToTheLimit(fusion, &count)
                                             : fusionLibraryUpToTheLimit(minimal, &count);
        const QString path = dir.filePath(u"library-%1.json"_s.arg(library));
        write(path, json);
        const Measured m = measure(u"read"_s, path);
        const Measured whole = measure(u"qjson"_s, path, 1);
        out << "| " << name << " | " << megabytes(json.size()) << " | " << m.outcome << " | "
            << QString::number(m.ms, 'f', 1) << " | " << QString::number(m.peakMb, 'f', 1) << " | "
            << QString::number(whole.peakMb, 'f', 1) << " |\n";
    }
    return 0;
}
