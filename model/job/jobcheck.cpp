// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/job/jobcheck.h"

#include <QFileInfo>

#include "model/formats/linereader.h"

namespace Toffee {

namespace {

// How many lines go by between two progress reports: often enough for a bar, rarely enough to cost nothing.
constexpr int kLinesPerProgress = 1 << 16;

} // namespace

Result<JobReport> checkJobFile(
    const QString &path, JobCheckSetup setup, const JobFactSource &moreFacts, const JobProgress &progress)
{
    LineReader reader;
    if (auto opened = reader.open(path); !opened)
        return opened.error();
    JobChecker checker(std::move(setup));
    bool cancelled = false;
    QByteArrayView line;
    int sinceProgress = 0;
    while (!checker.ended() && reader.next(line)) {
        checker.feed(line, reader.lineNumber());
        if (++sinceProgress == kLinesPerProgress) {
            sinceProgress = 0;
            if (progress && !progress(reader.bytesRead(), reader.size())) {
                cancelled = true;
                break;
            }
        }
    }
    if (reader.error())
        return *reader.error();
    if (auto added = checker.addFacts(moreFacts); !added)
        return added.error();
    if (progress && !cancelled)
        progress(reader.size(), reader.size());
    return checker.finish(QFileInfo(path).fileName(), cancelled);
}

} // namespace Toffee
