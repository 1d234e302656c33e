// SPDX-License-Identifier: GPL-3.0-or-later
// The emulator on whatever a client may send: the bytes go in exactly as PtyServer hands them over
// (CarveraEmulator::receiveBytes splits real-time characters and lines), with every timing zero.
// Promised: no crash; every line it sends is printable ASCII (but the firmware's echo of a line it ignores),
// without line ends, and short enough for a link to take whole; a status report always parses; positions and
// offsets stay finite; and it never stops answering: afterwards an empty line still gets its "ok" and a "?"
// its status report.
#include <cmath>

#include <QCoreApplication>

#include "serial/carvera/carverareplies.h"
#include "serial/emulator/carveraemulator.h"
#include "tests/fuzz/fuzzcheck.h"

using namespace Toffee;

namespace {

void ensureApplication()
{
    static int argc = 1;
    static char name[] = "fuzz-emulator";
    static char *argv[] = { name, nullptr };
    static QCoreApplication app(argc, argv);
}

void checkLine(const QByteArray &line)
{
    const QString shown = QString::fromLatin1(line.left(200));
    TOFFEE_FUZZ_CHECK(line.size() <= CarveraEmulator::kMaxLineBytes, QString::number(line.size()));
    // "ok - ignore: [line]" echoes a line it does not read as it came, as the firmware does.
    const bool echo = line.startsWith("ok - ignore: [");
    for (char c : line)
        TOFFEE_FUZZ_CHECK(echo ? c != '\n' && c != '\r' && c != '\0' : c >= 0x20 && c <= 0x7e, shown);
    if (classifyReply(line) == ReplyKind::Status)
        TOFFEE_FUZZ_CHECK(parseStatusReport(line).has_value(), shown);
}

// Runs what is queued and due (zero timings: steps, queued commands) until the emulator is idle.
void settle(CarveraEmulator &emulator, qsizetype budget)
{
    for (qsizetype i = 0; i < budget && emulator.isBusy(); ++i)
        QCoreApplication::processEvents();
    QCoreApplication::processEvents();
    TOFFEE_FUZZ_CHECK(!emulator.isBusy(), QStringLiteral("still busy after %1 rounds").arg(budget));
}

void checkFinite(const CarveraEmulator &emulator)
{
    TOFFEE_FUZZ_CHECK(std::isfinite(emulator.referenceMz()) && std::isfinite(emulator.currentMz())
            && std::isfinite(emulator.tlo()),
        QString::fromLatin1(emulator.statusReport()));
    const auto status = parseStatusReport(emulator.statusReport());
    TOFFEE_FUZZ_CHECK(status.has_value(), QString::fromLatin1(emulator.statusReport().left(200)));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ensureApplication();
    CarveraEmulator emulator;
    QList<QByteArray> sent;
    QObject::connect(&emulator, &CarveraEmulator::lineSent, &emulator, [&sent](const QByteArray &line) {
        checkLine(line);
        sent.append(line);
        if (sent.size() > 64)
            sent.removeFirst();
    });
    const QByteArrayView input = Fuzz::bytes(data, size);
    const qsizetype budget = 1000 + 4 * input.size();
    emulator.receiveBytes(input);
    settle(emulator, budget);
    checkFinite(emulator);

    // Still answering: a line end finishes whatever half line came last, then an empty line is a command
    // like any, answered "ok" even while halted.
    emulator.receiveBytes("\n");
    settle(emulator, budget);
    sent.clear();
    emulator.receiveBytes("\n");
    settle(emulator, budget);
    TOFFEE_FUZZ_CHECK(sent.size() == 1 && sent.front() == "ok",
        QString::fromLatin1(sent.isEmpty() ? QByteArray("nothing") : sent.join('|').left(200)));
    sent.clear();
    emulator.receiveBytes("?");
    TOFFEE_FUZZ_CHECK(sent.size() == 1 && parseStatusReport(sent.front()).has_value(),
        QString::fromLatin1(sent.join('|').left(200)));
    checkFinite(emulator);
    return 0;
}
