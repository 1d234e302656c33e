// SPDX-License-Identifier: GPL-3.0-or-later
// The job check and its preparation on any program. The first byte picks the controller and what to prepare;
// the rest is the program, checked against a small table and then prepared for the machine.
// Promised: no crash; every finding names a line of the program (or of a tool's load), with a message; the
// times and lengths are real numbers; a preparation either says why not or writes a program whose inserted
// lines all say why, which the controller runs through, and which, prepared again for a G43 controller, needs
// nothing more.
#include <cmath>

#include "model/job/jobchecker.h"
#include "model/job/jobpreparer.h"
#include "model/tooltable.h"
#include "tests/fuzz/fuzzcheck.h"

using namespace Toffee;

namespace {

ToolTable table()
{
    QList<Tool> tools;
    for (int n : { 1, 2, 7 }) {
        Tool t;
        t.number = n;
        t.pocket = n;
        t.lengthGeometry = 40.0 + n;
        t.measuredTlo = -2.5 * n;
        t.measuredAt = QDateTime(QDate(2026, 11, 23), QTime(12, 0), Qt::UTC);
        tools << t;
    }
    return ToolTable::fromTools(tools, Units::Millimetre).value();
}

// The lines as LineReader gives them: a last line end ends the last line, it does not start another.
QList<QByteArrayView> linesOf(QByteArrayView program)
{
    QList<QByteArrayView> lines;
    qsizetype start = 0;
    while (start < program.size()) {
        qsizetype end = program.indexOf('\n', start);
        if (end < 0)
            end = program.size();
        lines.append(program.sliced(start, end - start));
        start = end + 1;
    }
    return lines;
}

void check(const QList<QByteArrayView> &lines, Dialect dialect, const QString &detail)
{
    JobCheckSetup setup;
    setup.dialect = dialect;
    setup.useTable(table());
    setup.zFloor = -10.0;
    setup.rack = carveraRack();
    setup.now = QDateTime(QDate(2026, 11, 24), QTime(12, 0), Qt::UTC);
    JobChecker checker(setup);
    for (qsizetype i = 0; i < lines.size(); ++i)
        checker.feed(lines.at(i), int(i) + 1);
    const JobReport report = checker.finish(QStringLiteral("fuzz.nc"), false);
    TOFFEE_FUZZ_CHECK(report.lines <= lines.size(), detail);
    TOFFEE_FUZZ_CHECK(std::isfinite(report.cuttingSeconds) && report.cuttingSeconds >= 0, detail);
    TOFFEE_FUZZ_CHECK(std::isfinite(report.rapidMm) && report.rapidMm >= 0, detail);
    for (const Finding &f : report.findings) {
        TOFFEE_FUZZ_CHECK(f.line >= 1 && f.line <= lines.size(), detail);
        TOFFEE_FUZZ_CHECK(!f.message.isEmpty() && f.count >= 1 && !f.lines.isEmpty(), detail);
        TOFFEE_FUZZ_CHECK(f.lines.size() <= JobChecker::kMaxLinesPerFinding, detail);
    }
}

// The prepared program, or nothing when the preparation said why not.
std::optional<QByteArray> prepare(const QList<QByteArrayView> &lines, const PrepareOptions &options)
{
    JobPreparer preparer(table(), options);
    QByteArray out;
    const auto sink = [&out](QByteArrayView line) {
        out.append(line);
        out.append('\n');
        return true;
    };
    for (qsizetype i = 0; i < lines.size(); ++i) {
        if (auto r = preparer.feed(lines.at(i), int(i) + 1, sink); !r) {
            TOFFEE_FUZZ_CHECK(!r.error().message.isEmpty() && r.error().line >= 1, r.error().message);
            return std::nullopt;
        }
    }
    auto summary = preparer.finish(sink);
    if (!summary)
        return std::nullopt;
    return out;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    constexpr Dialect kDialects[] = { Dialect::Carvera, Dialect::Fanuc, Dialect::Fagor8055M,
        Dialect::AllenBradley9, Dialect::LinuxCnc };
    const Dialect dialect = kDialects[data[0] % 5];
    const QByteArrayView program = Fuzz::bytes(data + 1, size - 1);
    const QString detail = QString::fromUtf8(program);
    const QList<QByteArrayView> lines = linesOf(program);
    check(lines, dialect, detail);

    PrepareOptions options;
    options.dialect = dialect;
    options.useStoredTlo = dialect == Dialect::Carvera && (data[0] / 5) % 2 == 0;
    options.breakTest = dialect == Dialect::Carvera && !options.useStoredTlo ? true : (data[0] / 10) % 2 == 0;
    options.breakTest = options.breakTest && dialect == Dialect::Carvera;
    options.now = QDateTime(QDate(2026, 11, 24), QTime(12, 0), Qt::UTC);
    const auto prepared = prepare(lines, options);
    if (!prepared)
        return 0;
    const QList<QByteArrayView> original = lines;
    for (QByteArrayView line : linesOf(*prepared)) {
        if (!line.isEmpty() && !original.contains(line))
            TOFFEE_FUZZ_CHECK(line.contains("(Toffee: "), QString::fromUtf8(*prepared));
    }
    GCodeInterpreter again(dialect, offsetTableFor(table(), dialect));
    again.setRecordMoves(false);
    TOFFEE_FUZZ_CHECK(again.run(*prepared).ok(), QString::fromUtf8(*prepared));
    if (usesG43(dialect)) {
        const auto twice = prepare(linesOf(*prepared), options);
        TOFFEE_FUZZ_CHECK(twice && *twice == *prepared, QString::fromUtf8(*prepared));
    }
    return 0;
}
