// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/job/jobprepare.h"

#include <QFileInfo>

#include "model/formats/fileio.h"
#include "model/formats/linereader.h"
#include "model/translate.h"

namespace Toffee {

namespace {

constexpr int kLinesPerProgress = 1 << 14;
constexpr qsizetype kPieceBytes = 1024 * 1024;

// Runs the whole preparation into `sink` (lines, each with its end); the summary, or why it stopped.
Result<PrepareSummary> run(const QString &path, const ToolTable &table, const PrepareOptions &options,
    const JobPreparer::LineSink &sink, const JobProgress &progress)
{
    LineReader reader;
    if (auto opened = reader.open(path); !opened)
        return opened.error();
    JobPreparer preparer(table, options);
    QByteArrayView line;
    int sinceProgress = 0;
    while (reader.next(line)) {
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
    auto summary = preparer.finish(sink);
    if (!summary)
        return Error { summary.error().message, summary.error().line, path };
    return summary;
}

} // namespace

Result<PrepareSummary> prepareJobFile(const QString &path, const ToolTable &table,
    const PrepareOptions &options, const QString &output, const JobProgress &progress)
{
    if (auto allowed = JobPreparer::check(options); !allowed)
        return allowed.error();
    if (output.isEmpty())
        return run(
            path, table, options, [](QByteArrayView) { return true; }, progress);
    if (QFileInfo(output).absoluteFilePath() == QFileInfo(path).absoluteFilePath())
        return Error {
            tr("%1: the prepared program must go to another file than the program itself.").arg(output)
        };
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
        result = run(path, table, options, lines, progress);
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
