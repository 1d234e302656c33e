// SPDX-License-Identifier: GPL-3.0-or-later
// Makera CAM writes one comment line per tool before the program body (FORMATS.md):
//   ;@MKR|TOOL|number=3|name=…|type=…|diameter=…|flutelength=…|sticklength=…|…
// in millimetres. Only the header is read: the first line that is neither blank nor a comment ends it.
#include <algorithm>
#include <array>

#include <QHash>

#include "model/camimport/camreaders.h"
#include "model/textparsing.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr QByteArrayView kToolLine = ";@MKR|TOOL|";
// The fields readField takes; any other is skipped.
constexpr std::array<QByteArrayView, 6> kReadFields
    = { "number", "name", "type", "diameter", "flutelength", "sticklength" };

bool isHeaderLine(QByteArrayView line)
{
    return line.isEmpty() || line.front() == ';' || line.front() == '(' || line == "%";
}

// One field: a known key with a bad value fails, naming it; unknown keys are skipped.
Result<void> readField(CamTool &tool, QByteArrayView key, QByteArrayView value, bool &hasNumber)
{
    auto text = [&value] {
        return decodeUtf8(value).value_or(QString::fromLatin1(value));
    };
    auto length = [&](std::optional<double> &out) -> Result<void> {
        if (value.trimmed().isEmpty())
            return {};
        out = parseDecimal(value.trimmed());
        if (!out)
            return Error { tr("%1=%2 is not a number.").arg(QString::fromLatin1(key), excerpt(value)) };
        return {};
    };
    if (key == "number") {
        const auto number = parseInteger(value.trimmed());
        if (!number || *number < -1'000'000'000 || *number > 1'000'000'000)
            return Error { tr("number=%1 is not a tool number.").arg(excerpt(value)) };
        tool.number = int(*number);
        hasNumber = true;
    } else if (key == "name") {
        tool.description = text();
    } else if (key == "type") {
        tool.type = text();
    } else if (key == "diameter") {
        return length(tool.diameter);
    } else if (key == "flutelength") {
        return length(tool.fluteLength);
    } else if (key == "sticklength") {
        return length(tool.stickOut);
    }
    return {};
}

Result<CamTool> readToolLine(QByteArrayView line, int lineNumber)
{
    CamTool tool;
    tool.line = lineNumber;
    tool.units = Units::Millimetre;
    bool hasNumber = false;
    // Each field Toffee reads, as first given: a second one would silently win.
    QHash<QByteArrayView, QByteArrayView> seen;
    // Field by field, not split into a list first: a 4 MB line of bars would be a list of 64 MB.
    const QByteArrayView fields = line.sliced(kToolLine.size());
    for (qsizetype from = 0; from <= fields.size();) {
        const qsizetype bar = fields.indexOf('|', from);
        const QByteArrayView field = fields.sliced(from, (bar < 0 ? fields.size() : bar) - from);
        from = bar < 0 ? fields.size() + 1 : bar + 1;
        const qsizetype equals = field.indexOf('=');
        if (equals <= 0)
            continue; // not key=value: nothing Toffee reads
        const QByteArrayView key = field.first(equals).trimmed();
        const QByteArrayView value = field.sliced(equals + 1);
        if (std::find(kReadFields.cbegin(), kReadFields.cend(), key) != kReadFields.cend()) {
            if (const auto first = seen.constFind(key); first != seen.cend())
                return Error { tr("%1 is in this tool line twice (%1=%2 and %1=%3); Toffee will not guess "
                                  "which one is meant.")
                                   .arg(QString::fromLatin1(key), excerpt(*first), excerpt(value)),
                    lineNumber };
            seen.insert(key, value);
        }
        if (auto r = readField(tool, key, value, hasNumber); !r)
            return Error { r.error().message, lineNumber };
    }
    if (!hasNumber)
        return Error { tr("this tool line has no number=…; Toffee needs the T number."), lineNumber };
    return tool;
}

} // namespace

Result<QList<CamTool>> readMakeraHeader(QByteArrayView program, bool complete)
{
    QList<CamTool> tools;
    qsizetype start = 0;
    int lineNumber = 0;
    while (start < program.size()) {
        qsizetype end = program.indexOf('\n', start);
        // A G-code program is text: a NUL byte means some other file (or a disk image's zeros), and its
        // "lines" are neither comments nor a header.
        if (program.sliced(start, (end < 0 ? program.size() : end) - start).contains('\0'))
            return Error { tr("this is not a text program: it holds binary data (a NUL byte), which a G-code "
                              "program never does."),
                lineNumber + 1 };
        if (end < 0) {
            if (!complete)
                return Error { tr("the program's first %1 MB are all comments; Toffee reads the tool header "
                                  "only from the start of a program.")
                                   .arg(kMaxProgramHeaderBytes / (1024 * 1024)) };
            end = program.size();
        }
        ++lineNumber;
        const QByteArrayView line = program.sliced(start, end - start).trimmed();
        start = end + 1;
        if (!isHeaderLine(line))
            break;
        if (!line.startsWith(kToolLine))
            continue;
        auto tool = readToolLine(line, lineNumber);
        if (!tool)
            return tool.error();
        tools.append(tool.takeValue());
    }
    if (tools.isEmpty())
        return Error { tr(
            "this program has no Makera CAM tool header (\";@MKR|TOOL|number=…\" lines before the "
            "program body); there are no tools to import from it.") };
    return checkCamTools(std::move(tools));
}

} // namespace Toffee
