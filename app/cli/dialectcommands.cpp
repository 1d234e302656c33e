// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli export and simulate: the offset programs of each controller.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "app/cli/cli.h"
#include "model/formats/fileio.h"
#include "model/formats/linereader.h"
#include "model/formats/tablefile.h"
#include "model/gcode/dialect.h"
#include "model/gcode/gcodeinterpreter.h"
#include "model/numberformat.h"
#include "model/textparsing.h"

using namespace Qt::StringLiterals;

namespace Toffee::Cli {

namespace {

std::optional<Dialect> dialectOption(Invocation &call)
{
    return dialectFromKey(call.option(u"dialect"_s));
}

QString dialectKeys()
{
    QStringList keys;
    for (const DialectInfo &info : dialects())
        keys << info.key;
    return keys.join(u", "_s);
}

QJsonArray point(const Position &p)
{
    return { p[0], p[1], p[2] };
}

QString fixed(double v)
{
    return formatNumber(v, NumberFormat::fixed(4));
}

QJsonObject moveJson(const SimulatedMove &m)
{
    QJsonArray points;
    for (const Position &p : m.points)
        points.append(point(p));
    return { { u"line"_s, m.line }, { u"x"_s, m.end[0] }, { u"y"_s, m.end[1] }, { u"z"_s, m.end[2] },
        { u"points"_s, points } };
}

QJsonArray offsetsJson(const OffsetTable &offsets)
{
    QJsonArray table;
    for (const auto &[number, e] : offsets)
        table.append(QJsonObject { { u"number"_s, number }, { u"length_geometry"_s, e.lengthGeometry },
            { u"length_wear"_s, e.lengthWear }, { u"radius_geometry"_s, e.radiusGeometry },
            { u"radius_wear"_s, e.radiusWear } });
    return table;
}

void printMove(Invocation &call, const SimulatedMove &m)
{
    call.out << "line " << m.line << ": X" << fixed(m.end[0]) << " Y" << fixed(m.end[1]) << " Z"
             << fixed(m.end[2]) << '\n';
    for (const Position &p : m.points)
        call.out << "    " << fixed(p[0]) << ' ' << fixed(p[1]) << ' ' << fixed(p[2]) << '\n';
}

void printOffsets(Invocation &call, const OffsetTable &offsets)
{
    if (!offsets.empty()) {
        call.out << "offsets:\n";
        for (const auto &[number, e] : offsets)
            call.out << "  " << number << ": length " << fixed(e.lengthGeometry) << " wear "
                     << fixed(e.lengthWear) << ", radius " << fixed(e.radiusGeometry) << " wear "
                     << fixed(e.radiusWear) << '\n';
    }
    call.out.flush();
}

} // namespace

int exportOffsets(Invocation &call)
{
    if (call.arguments.size() != 1)
        return fail(call, u"usage: toffee-cli export --dialect D TABLE [--tool N]"_s, BadInput);
    const auto dialect = dialectOption(call);
    if (!dialect)
        return fail(call, u"--dialect must be one of %1."_s.arg(dialectKeys()), BadInput);
    std::optional<int> tool;
    if (call.has(u"tool"_s)) {
        const auto n = parseInteger(call.option(u"tool"_s).toUtf8());
        if (!n)
            return fail(call, u"--tool must be a tool number."_s, BadInput);
        tool = int(*n);
    }
    auto table = loadTableFile(call.arguments.front());
    if (!table)
        return fail(call, table.error().text(), BadInput);
    auto program = exportProgram(table.value(), *dialect, tool);
    if (!program)
        return fail(call, program.error().text(), BadInput);
    if (call.json)
        printJson(call,
            QJsonObject { { u"dialect"_s, dialectInfo(*dialect).key }, { u"program"_s, program.value() } });
    else
        call.out << program.value();
    call.out.flush();
    return Success;
}

int simulateProgram(Invocation &call)
{
    if (call.arguments.size() != 1)
        return fail(
            call, u"usage: toffee-cli simulate --dialect D [--table FILE] [--samples N] PROGRAM"_s, BadInput);
    const auto dialect = dialectOption(call);
    if (!dialect)
        return fail(call, u"--dialect must be one of %1."_s.arg(dialectKeys()), BadInput);
    int samples = 0;
    if (call.has(u"samples"_s)) {
        const auto n = parseInteger(call.option(u"samples"_s).toUtf8());
        if (!n || *n < 2 || *n > 100000)
            return fail(call, u"--samples must be a whole number from 2 up."_s, BadInput);
        samples = int(*n);
    }
    OffsetTable offsets;
    if (call.has(u"table"_s)) {
        auto table = loadTableFile(call.option(u"table"_s));
        if (!table)
            return fail(call, table.error().text(), BadInput);
        offsets = offsetTableFor(table.value(), *dialect);
    }
    // Read a line at a time and each move printed as it is made: memory does not grow with the program.
    LineReader reader;
    if (auto opened = reader.open(call.arguments.front()); !opened)
        return fail(call, opened.error().text(), BadInput);
    GCodeInterpreter interpreter(*dialect, offsets, samples);
    bool first = true;
    if (call.json) {
        call.out << "{\"dialect\":\"" << dialectInfo(*dialect).key << "\",\"moves\":[";
        interpreter.setMoveSink([&call, &first](const SimulatedMove &m) {
            call.out << (first ? "" : ",")
                     << QString::fromUtf8(QJsonDocument(moveJson(m)).toJson(QJsonDocument::Compact));
            first = false;
        });
    } else {
        interpreter.setMoveSink([&call](const SimulatedMove &m) { printMove(call, m); });
    }
    Result<void> result;
    QByteArrayView line;
    while (result.ok() && !interpreter.ended() && reader.next(line))
        result = interpreter.runLine(line, reader.lineNumber());
    if (result.ok() && reader.error())
        result = *reader.error();
    if (call.json)
        call.out << "],\"offsets\":"
                 << QString::fromUtf8(
                        QJsonDocument(offsetsJson(interpreter.offsets())).toJson(QJsonDocument::Compact))
                 << ",\"error\":"
                 << (result.ok() ? u"null"_s
                                 : QString::fromUtf8(
                                     QJsonDocument(QJsonObject { { u"line"_s, result.error().line },
                                                       { u"message"_s, result.error().message } })
                                         .toJson(QJsonDocument::Compact)))
                 << "}" << Qt::endl;
    else
        printOffsets(call, interpreter.offsets());
    if (!result) {
        call.err << "toffee-cli: " << result.error().text() << Qt::endl;
        return MachineError;
    }
    return Success;
}

} // namespace Toffee::Cli
