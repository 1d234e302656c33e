// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/job/programexcerpt.h"

#include "model/formats/linereader.h"

namespace Toffee {

Result<ProgramExcerpt> readExcerpt(const QString &path, int line, int context)
{
    LineReader reader;
    if (auto opened = reader.open(path); !opened)
        return opened.error();
    ProgramExcerpt excerpt;
    excerpt.firstLine = std::max(1, line - context);
    QByteArrayView text;
    while (reader.lineNumber() < line + context && reader.next(text)) {
        if (reader.lineNumber() >= excerpt.firstLine)
            excerpt.lines.append(QString::fromUtf8(text));
    }
    if (reader.error())
        return *reader.error();
    return excerpt;
}

} // namespace Toffee
