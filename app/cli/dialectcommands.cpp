// SPDX-License-Identifier: GPL-3.0-or-later
// toffee-cli export and simulate: the offset programs of each controller.
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>

#include "app/cli/cli.h"
#include "model/formats/fileio.h"
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
    // A program is read whole for now; a FIFO or a device is refused by name, and a program is bounded.
    constexpr qint64 kMaxProgramBytes = 512LL * 1024 * 1024;
    const auto read = readRegularFile(call.arguments.front(), kMaxProgramBytes);
    if (!read)
        return fail(call, read.error().text(), BadInput);
    const QByteArray &program = read.value();

    GCodeInterpreter interpreter(*dialect, offsets, samples);
    const auto result = interpreter.run(program);

    if (call.json) {
        QJsonArray moves;
        for (const SimulatedMove &m : interpreter.moves()) {
            QJsonArray points;
            for (const Position &p : m.points)
                points.append(point(p));
            moves.append(QJsonObject { { u"line"_s, m.line }, { u"x"_s, m.end[0] }, { u"y"_s, m.end[1] },
                { u"z"_s, m.end[2] }, { u"points"_s, points } });
        }
        QJsonArray table;
        for (const auto &[number, e] : interpreter.offsets())
            table.append(QJsonObject { { u"number"_s, number }, { u"length_geometry"_s, e.lengthGeometry },
                { u"length_wear"_s, e.lengthWear }, { u"radius_geometry"_s, e.radiusGeometry },
                { u"radius_wear"_s, e.radiusWear } });
        const QJsonValue error = result.ok() ? QJsonValue()
                                             : QJsonValue(QJsonObject { { u"line"_s, result.error().line },
                                                 { u"message"_s, result.error().message } });
        printJson(call,
            QJsonObject { { u"dialect"_s, dialectInfo(*dialect).key }, { u"moves"_s, moves },
                { u"offsets"_s, table }, { u"error"_s, error } });
    } else {
        for (const SimulatedMove &m : interpreter.moves()) {
            call.out << "line " << m.line << ": X" << fixed(m.end[0]) << " Y" << fixed(m.end[1]) << " Z"
                     << fixed(m.end[2]) << '\n';
            for (const Position &p : m.points)
                call.out << "    " << fixed(p[0]) << ' ' << fixed(p[1]) << ' ' << fixed(p[2]) << '\n';
        }
        if (!interpreter.offsets().empty()) {
            call.out << "offsets:\n";
            for (const auto &[number, e] : interpreter.offsets())
                call.out << "  " << number << ": length " << fixed(e.lengthGeometry) << " wear "
                         << fixed(e.lengthWear) << ", radius " << fixed(e.radiusGeometry) << " wear "
                         << fixed(e.radiusWear) << '\n';
        }
        call.out.flush();
    }
    if (!result) {
        call.err << "toffee-cli: " << result.error().text() << Qt::endl;
        return MachineError;
    }
    return Success;
}

} // namespace Toffee::Cli
