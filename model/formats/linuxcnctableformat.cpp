// SPDX-License-Identifier: GPL-3.0-or-later
// LinuxCNC tool.tbl: `T<n> P<pocket> [X..W <float>] [D<dia>] [I<front>] [J<back>] [Q<0-9>] [;comment]`.
// T and P are required, lines starting with ';' are ignored, any other token makes the line invalid.
// Z is the tool length and D the diameter; the table has no wear, TLO or notes columns.
#include "model/formats/tablefile.h"

#include <cmath>
#include <cstring>

#include <QCoreApplication>

#include "model/formats/tablereading.h"
#include "model/numberformat.h"
#include "model/textparsing.h"
#include "model/toolvalidation.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

// The fields Toffee keeps verbatim, in the order LinuxCNC writes them.
constexpr char kExtraLetters[] = "XYABCUVWIJQ";

// What a line's fields say, read one by one before the line is checked as a whole.
struct ParsedLine
{
    std::optional<qint64> number;
    std::optional<qint64> pocket;
    std::optional<double> z;
    std::optional<double> diameter;
    std::optional<double> extra[sizeof kExtraLetters - 1];
    QByteArray seen; // the letters read so far: each field may appear once
};

// The comment after ';' is the description; `fields` is the line before it.
Result<void> splitComment(QByteArrayView line, QByteArrayView &fields, QString &comment)
{
    fields = line;
    const qsizetype semicolon = line.indexOf(';');
    if (semicolon < 0)
        return {};
    fields = line.first(semicolon);
    // The comment is the description: at most 255 characters, so at most four times as many bytes.
    if (line.size() - semicolon - 1 > 4 * Limits::kMaxDescriptionLength)
        return Error { tr("the comment \"%1\" is longer than a description may be (%2 characters).")
                           .arg(excerpt(line.sliced(semicolon + 1)))
                           .arg(Limits::kMaxDescriptionLength) };
    const auto text = decodeUtf8(line.sliced(semicolon + 1));
    if (!text)
        return Error { tr("the comment is not valid UTF-8 text.") };
    comment = text->trimmed();
    return {};
}

// T, P and Q, whose values are whole numbers.
Result<void> readWholeNumberField(char letter, QByteArrayView token, ParsedLine &parsed)
{
    const QByteArrayView value = token.sliced(1);
    const auto n = parseInteger(value);
    if (!n && isIntegerText(value) && letter == 'T')
        return Error { tr("tool number %1 is out of range; use %2 to %3.")
                           .arg(excerpt(value))
                           .arg(Limits::kMinToolNumber)
                           .arg(Limits::kMaxToolNumber) };
    if (!n && isIntegerText(value) && letter == 'P')
        return Error { tr("pocket %1 is out of range; use %2 to %3.")
                           .arg(excerpt(value))
                           .arg(Limits::kMinPocket)
                           .arg(Limits::kMaxPocket) };
    if (!n)
        return Error {
            tr("\"%1\": %2 needs a whole number.").arg(excerpt(token), QChar::fromLatin1(letter))
        };
    if (letter == 'T')
        parsed.number = n;
    else if (letter == 'P')
        parsed.pocket = n;
    else if (*n < 0 || *n > 9)
        return Error { tr("\"%1\": the orientation Q must be 0 to 9.").arg(excerpt(token)) };
    else
        parsed.extra[std::strchr(kExtraLetters, 'Q') - kExtraLetters] = double(*n);
    return {};
}

// Z, D and the fields kept verbatim, whose values are decimal numbers; any other letter is no field.
Result<void> readDecimalField(char letter, QByteArrayView token, ParsedLine &parsed)
{
    const char *slot = letter ? std::strchr(kExtraLetters, letter) : nullptr;
    if (letter != 'Z' && letter != 'D' && !slot)
        return Error { tr(
            "\"%1\" is not a tool table field; a line holds T, P, X, Y, Z, A, B, C, U, V, W, D, I, "
            "J, Q and a ;comment.")
                           .arg(excerpt(token)) };
    const auto v = parseDecimal(token.sliced(1));
    if (!v)
        return Error { tr("\"%1\": %2 needs a number.").arg(excerpt(token), QChar::fromLatin1(letter)) };
    if (letter == 'Z')
        parsed.z = v;
    else if (letter == 'D')
        parsed.diameter = v;
    else
        parsed.extra[slot - kExtraLetters] = v;
    return {};
}

// One field: a letter (either case) and its value, such as "T12" or "z-30.5".
Result<void> readField(QByteArrayView token, ParsedLine &parsed)
{
    const char letter = char(QChar::toUpper(uchar(token.front())));
    if (parsed.seen.contains(letter))
        return Error {
            tr("\"%1\": the field %2 appears twice.").arg(excerpt(token), QChar::fromLatin1(letter))
        };
    parsed.seen += letter;
    if (letter == 'T' || letter == 'P' || letter == 'Q')
        return readWholeNumberField(letter, token, parsed);
    return readDecimalField(letter, token, parsed);
}

// The fields between blanks, each read as it is split off.
Result<void> readFields(QByteArrayView fields, ParsedLine &parsed)
{
    qsizetype i = 0;
    while (i < fields.size()) {
        while (i < fields.size() && isSpace(fields.at(i)))
            ++i;
        if (i >= fields.size())
            break;
        qsizetype end = i;
        while (end < fields.size() && !isSpace(fields.at(end)))
            ++end;
        if (auto read = readField(fields.sliced(i, end - i), parsed); !read)
            return read;
        i = end;
    }
    return {};
}

// T and P are required, and must fit a tool and a pocket before they are made ints.
Result<void> checkNumbers(const ParsedLine &parsed)
{
    if (!parsed.number)
        return Error { tr("the line has no tool number (T)."), 0 };
    const qint64 number = *parsed.number;
    if (!parsed.pocket)
        return Error { tr("T%1 has no pocket (P).").arg(number) };
    if (number < Limits::kMinToolNumber || number > Limits::kMaxToolNumber)
        return Error { tr("tool number %1 is out of range; use %2 to %3.")
                           .arg(number)
                           .arg(Limits::kMinToolNumber)
                           .arg(Limits::kMaxToolNumber) };
    const qint64 pocket = *parsed.pocket;
    if (pocket < Limits::kMinPocket || pocket > Limits::kMaxPocket)
        return Error { tr("T%1: pocket %2 is out of range; use %3 to %4.")
                           .arg(number)
                           .arg(pocket)
                           .arg(Limits::kMinPocket)
                           .arg(Limits::kMaxPocket) };
    return {};
}

// The fields Toffee keeps verbatim, as LinuxCNC writes them: "X0.5 Q2".
QString extraText(const ParsedLine &parsed)
{
    QStringList kept;
    for (size_t k = 0; k < sizeof kExtraLetters - 1; ++k) {
        if (parsed.extra[k]) {
            const char letter = kExtraLetters[k];
            kept << QChar::fromLatin1(letter)
                    + (letter == 'Q' ? QString::number(int(*parsed.extra[k]))
                                     : formatNumber(*parsed.extra[k]));
        }
    }
    return kept.join(u' ');
}

Result<Tool> parseLine(QByteArrayView line)
{
    QByteArrayView fields;
    QString comment;
    if (auto split = splitComment(line, fields, comment); !split)
        return split.error();
    ParsedLine parsed;
    if (auto read = readFields(fields, parsed); !read)
        return read.error();
    if (auto checked = checkNumbers(parsed); !checked)
        return checked.error();
    Tool tool;
    tool.number = int(*parsed.number);
    tool.pocket = int(*parsed.pocket);
    tool.lengthGeometry = parsed.z.value_or(0.0);
    tool.radiusGeometry = parsed.diameter.value_or(0.0) / 2.0;
    tool.description = std::move(comment);
    tool.linuxCncExtra = extraText(parsed);
    return tool;
}

// Folding wear into geometry can leave binary noise (100 - 0.1); LinuxCNC works in 1e-6 steps anyway.
void appendFolded(QByteArray &out, double geometry, double wear)
{
    appendNumber(out, wear == 0.0 ? geometry : std::round((geometry + wear) * 1e6) / 1e6);
}

} // namespace

Result<ToolTable> readLinuxCncTable(const QByteArray &data, Units units)
{
    ToolCollector tools(data);
    const QByteArrayView all(data);
    qsizetype start = 0;
    int lineNumber = 0;
    while (start < all.size()) {
        qsizetype end = all.indexOf('\n', start);
        if (end < 0)
            end = all.size();
        const QByteArrayView line = all.sliced(start, end - start).trimmed();
        start = end + 1;
        ++lineNumber;
        if (line.isEmpty() || line.front() == ';')
            continue;
        if (line.contains('\0'))
            return Error { tr("the file holds binary data; it is not a LinuxCNC tool table."), lineNumber };
        auto tool = parseLine(line);
        if (!tool)
            return Error { tool.error().message, lineNumber };
        if (auto added = tools.add(tool.takeValue(), lineNumber, units); !added)
            return added.error();
    }
    return tools.build(units);
}

bool writeLinuxCncTable(const ToolTable &table, const ByteSink &sink)
{
    ChunkedWriter w(sink);
    QByteArray &out = w.out;
    for (const Tool &tool : table.tools()) {
        out += 'T';
        out += QByteArray::number(tool.number);
        out += " P";
        out += QByteArray::number(tool.pocket);
        out += " Z";
        appendFolded(out, tool.lengthGeometry, tool.lengthWear);
        if (tool.radiusGeometry + tool.radiusWear != 0.0) {
            out += " D";
            appendFolded(out, 2.0 * tool.radiusGeometry, 2.0 * tool.radiusWear);
        }
        if (!tool.linuxCncExtra.isEmpty()) {
            out += ' ';
            out += tool.linuxCncExtra.toLatin1();
        }
        if (!tool.description.isEmpty()) {
            out += " ;";
            out += tool.description.toUtf8();
        }
        out += '\n';
        if (!w.next())
            return false;
    }
    return w.finish();
}

QByteArray writeLinuxCncTable(const ToolTable &table)
{
    return collect(table, [](const ToolTable &t, const ByteSink &s) { return writeLinuxCncTable(t, s); });
}

} // namespace Toffee
