// SPDX-License-Identifier: GPL-3.0-or-later
// The G-code interpreter on any program, as any of the six controllers. The first byte picks the dialect and
// how many points a move is sampled at; the rest is the program, run over a table of a few offsets.
// Promised: no crash; an error has a message and the line of the program it is on; the machine ends
// somewhere real (finite), and the offset table holds only values a controller accepts.
#include <cmath>

#include "model/gcode/gcodeinterpreter.h"
#include "tests/fuzz/fuzzcheck.h"

using namespace Toffee;

namespace {

bool finite(const Position &p)
{
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    constexpr Dialect kDialects[] = { Dialect::Carvera, Dialect::Fanuc, Dialect::Fagor8055M,
        Dialect::AllenBradley9, Dialect::Aerotech, Dialect::LinuxCnc };
    const Dialect dialect = kDialects[data[0] % 6];
    const int samples = (data[0] / 6) % 4;
    const QByteArrayView program = Fuzz::bytes(data + 1, size - 1);

    OffsetTable offsets;
    offsets[1] = { 10.0, -0.5, 1.5, 0.0 };
    offsets[2] = { -190.1, 0.0, 3.0, 0.01 };
    offsets[12] = { 0.25, 0.0, 0.0, 0.0 };
    GCodeInterpreter interpreter(dialect, offsets, samples);
    const auto result = interpreter.run(program);
    if (!result.ok()) {
        const Error &error = result.error();
        TOFFEE_FUZZ_CHECK(!error.message.isEmpty(), error.text());
        TOFFEE_FUZZ_CHECK(error.line >= 1 && error.line <= program.count('\n') + 1, error.text());
    }
    TOFFEE_FUZZ_CHECK(finite(interpreter.position()), QString::fromUtf8(program));
    for (const SimulatedMove &move : interpreter.moves()) {
        TOFFEE_FUZZ_CHECK(move.line >= 1 && move.line <= program.count('\n') + 1, QString::fromUtf8(program));
        TOFFEE_FUZZ_CHECK(finite(move.end), QString::fromUtf8(program));
        TOFFEE_FUZZ_CHECK(move.points.size() == samples, QString::fromUtf8(program));
        for (const Position &point : move.points)
            TOFFEE_FUZZ_CHECK(finite(point), QString::fromUtf8(program));
    }
    for (const auto &[number, entry] : interpreter.offsets()) {
        TOFFEE_FUZZ_CHECK(number >= 1 && number <= 999, QString::number(number));
        TOFFEE_FUZZ_CHECK(std::fabs(entry.lengthGeometry) <= 999.999 + 1e-9
                && std::fabs(entry.radiusGeometry) <= 999.999 + 1e-9
                && std::fabs(entry.lengthWear) <= 99.999 + 1e-9
                && std::fabs(entry.radiusWear) <= 99.999 + 1e-9,
            QString::fromUtf8(program));
    }
    return 0;
}
