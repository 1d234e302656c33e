// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/job/jobprepare.h"

#include <algorithm>

#include <QFileInfo>

#include "model/formats/fileio.h"
#include "model/formats/linereader.h"
#include "model/translate.h"

namespace Toffee {

namespace {

constexpr int kLinesPerProgress = 1 << 14;
constexpr qsizetype kPieceBytes = 1024 * 1024;

// The job check the preparation runs beside it: a program with errors is not prepared.
JobCheckSetup checkSetup(const ToolTable &table, const PrepareOptions &options)
{
    JobCheckSetup setup;
    setup.dialect = options.dialect;
    setup.useTable(table);
    setup.zFloor = options.zFloor;
    setup.staleDays = options.staleDays;
    setup.rack = options.dialect == Dialect::Carvera ? std::optional(options.rack) : std::nullopt;
    setup.now = options.now;
    return setup;
}

Error checkFailed(const JobReport &report, const QString &path)
{
    const auto first = std::find_if(report.findings.cbegin(), report.findings.cend(),
        [](const Finding &f) { return f.severity() == Severity::Error; });
    const int errors = report.errors();
    return Error {
        tr("the job check finds %1; the first, on line %2: %3 Fix them before preparing the program "
           "(Check Job, or toffee-cli job check, lists them). Nothing was written.")
            .arg(errors == 1 ? tr("an error") : tr("%1 errors").arg(errors))
            .arg(first->line)
            .arg(first->message),
        first->line, path
    };
}

// Runs the whole preparation into `sink` (lines, each with its end), and the job check beside it; the
// summary, or why it stopped.
Result<PrepareSummary> run(const QString &path, const ToolTable &table, const PrepareOptions &options,
    const JobPreparer::LineSink &sink, const JobProgress &progress, const JobFactSource &moreFacts)
{
    LineReader reader;
    if (auto opened = reader.open(path); !opened)
        return opened.error();
    JobPreparer preparer(table, options);
    JobChecker checker(checkSetup(table, options));
    QByteArrayView line;
    int sinceProgress = 0;
    while (reader.next(line)) {
        checker.feed(line, reader.lineNumber());
        if (auto r = preparer.feed(line, reader.lineNumber(), sink); !r)
            return Error { r.error().message, r.error().line, path };
        if (++sinceProgress == kLinesPerProgress) {
            sinceProgress = 0;
            if (progress && !progress(reader.bytesRead(), reader.size()))
                return Error { tr("Preparing was cancelled; nothing was written.") };
        }
    }
    if (reader.error())
        return *reader.error();
    if (auto added = checker.addFacts(moreFacts); !added)
        return added.error();
    if (const JobReport report = checker.finish(QFileInfo(path).fileName(), false); report.errors() > 0)
        return checkFailed(report, path);
    auto summary = preparer.finish(sink);
    if (!summary)
        return Error { summary.error().message, summary.error().line, path };
    return summary;
}

// The file itself, links followed, for comparing two names of it.
QString realPath(const QString &path)
{
    const QFileInfo info(path);
    const QString canonical = info.canonicalFilePath();
    return canonical.isEmpty() ? info.absoluteFilePath() : canonical;
}

} // namespace

Result<PrepareSummary> prepareJobFile(const QString &path, const ToolTable &table,
    const PrepareOptions &options, const QString &output, const JobProgress &progress,
    const PrepareGuards &guards)
{
    if (auto allowed = JobPreparer::check(options); !allowed)
        return allowed.error();
    if (guards.preview)
        return run(
            path, table, options, [](QByteArrayView) { return true; }, progress, guards.moreFacts);
    if (output.trimmed().isEmpty())
        return Error { tr("Say where the prepared program goes: no file name was given.") };
    if (realPath(output) == realPath(path))
        return Error {
            tr("%1: the prepared program must go to another file than the program itself.").arg(output)
        };
    for (const QString &kept : guards.protectedFiles) {
        if (!kept.isEmpty() && realPath(output) == realPath(kept))
            return Error {
                tr("%1 is the tool table: the prepared program must go to another file.").arg(output)
            };
    }
    std::optional<Result<PrepareSummary>> result;
    QString stopped;
    const auto produce = [&](const FileSink &fileSink) {
        QByteArray piece;
        piece.reserve(kPieceBytes + 4096);
        const auto lines = [&](QByteArrayView line) {
            piece.append(line);
            piece.append('\n');
            if (piece.size() < kPieceBytes)
                return true;
            const bool written = fileSink(piece);
            piece.clear();
            return written;
        };
        result = run(path, table, options, lines, progress, guards.moreFacts);
        if (!result->ok()) {
            stopped = result->error().text();
            return false;
        }
        return piece.isEmpty() || fileSink(piece);
    };
    if (auto written = writeFileAtomically(output, produce, &stopped); !written) {
        if (result && !result->ok())
            return result->error();
        return written.error();
    }
    return *result;
}

} // namespace Toffee
