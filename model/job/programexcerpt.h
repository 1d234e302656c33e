// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QString>

#include "model/result.h"

namespace Toffee {

// The lines of a program around one line, as the job check shows a finding in its place.
struct ProgramExcerpt
{
    int firstLine = 0; // the number of lines.front()
    QList<QString> lines;
};

// Lines `line - context` to `line + context` of the program at `path`, read a line at a time (LineReader);
// fewer at the program's start and end.
[[nodiscard]] Result<ProgramExcerpt> readExcerpt(const QString &path, int line, int context);

} // namespace Toffee
