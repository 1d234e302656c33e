// SPDX-License-Identifier: GPL-3.0-or-later
// The reply parsers on whatever a port may deliver: each line is classified and offered to every parser.
// Promised: no crash; a parser takes only a line of its own kind; every number it returns is finite; a
// TLO report's values are ones a machine can have; a tool number is one a Carvera can report (-1, an empty
// spindle, to 999999); a halt reason can be named. LinuxCNC's (linuxcncrsh) the same: a line is one kind at
// most, a value read follows its keyword, a (DEBUG,…) line's fields are finite numbers, a position three
// finite ones. M491 R's summary, read from the whole reply: each pass a finite TLO a machine can have.
#include <cmath>

#include "model/textparsing.h"
#include "serial/carvera/carverareplies.h"
#include "serial/linuxcnc/linuxcncreplies.h"
#include "tests/fuzz/fuzzcheck.h"

using namespace Toffee;

namespace {

bool finite(double v)
{
    return std::isfinite(v);
}

void checkLine(QByteArrayView line)
{
    const QString shown = QString::fromUtf8(line);
    const ReplyKind kind = classifyReply(line);
    if (kind == ReplyKind::Ok)
        TOFFEE_FUZZ_CHECK(line.trimmed() == "ok" || line.trimmed().startsWith("ok - ignore: ["), shown);
    if (kind == ReplyKind::Error || kind == ReplyKind::Alarm || kind == ReplyKind::HaltError)
        (void)replyMessage(line);

    if (const auto status = parseStatusReport(line)) {
        TOFFEE_FUZZ_CHECK(kind == ReplyKind::Status, shown);
        TOFFEE_FUZZ_CHECK(!status->state.isEmpty(), shown);
        for (double v : status->mpos)
            TOFFEE_FUZZ_CHECK(finite(v), shown);
        for (double v : status->wpos)
            TOFFEE_FUZZ_CHECK(finite(v), shown);
        // A tool comes with its TLO; a T: field whose number is no tool's keeps the TLO and names no tool.
        if (status->tool)
            TOFFEE_FUZZ_CHECK(status->tlo && *status->tool >= -1 && *status->tool <= 999999, shown);
        if (status->tlo)
            TOFFEE_FUZZ_CHECK(finite(*status->tlo), shown);
        if (status->haltReason) {
            TOFFEE_FUZZ_CHECK(status->isAlarm(), shown);
            TOFFEE_FUZZ_CHECK(!haltReasonName(*status->haltReason).isEmpty(), shown);
            TOFFEE_FUZZ_CHECK(!haltRecovery(*status->haltReason).isEmpty(), shown);
        }
    }
    if (const auto tlo = parseTloReport(line)) {
        TOFFEE_FUZZ_CHECK(kind == ReplyKind::Other, shown);
        TOFFEE_FUZZ_CHECK(finite(tlo->currentMz) && finite(tlo->referenceMz), shown);
        TOFFEE_FUZZ_CHECK(std::fabs(tlo->currentMz) <= kMaxMachineMillimetres
                && std::fabs(tlo->referenceMz) <= kMaxMachineMillimetres,
            shown);
    }
    if (const auto probe = parseProbeResult(line)) {
        TOFFEE_FUZZ_CHECK(kind == ReplyKind::Other, shown);
        TOFFEE_FUZZ_CHECK(finite(probe->x) && finite(probe->y) && finite(probe->z), shown);
    }
    if (const auto test = parseBreakTest(line)) {
        TOFFEE_FUZZ_CHECK(kind == ReplyKind::Other, shown);
        TOFFEE_FUZZ_CHECK(finite(test->oldTlo) && finite(test->newTlo), shown);
    }
}

void checkLinuxCncLine(QByteArrayView line)
{
    const QString shown = QString::fromUtf8(line);
    const ReplyKind kind = LinuxCnc::classify(line);
    TOFFEE_FUZZ_CHECK(!(LinuxCnc::isHelloAck(line) && LinuxCnc::isHelloNak(line)), shown);
    if (LinuxCnc::isHelloAck(line))
        TOFFEE_FUZZ_CHECK(kind == ReplyKind::Ok, shown);
    if (const auto value = LinuxCnc::valueOf(line, "TOOL"))
        TOFFEE_FUZZ_CHECK(line.trimmed().startsWith("TOOL") && value->size() < line.size(), shown);
    if (const auto xyz = LinuxCnc::position(line)) {
        for (double v : *xyz)
            TOFFEE_FUZZ_CHECK(finite(v), shown);
    }
    const int homed = LinuxCnc::homedJoints(line);
    TOFFEE_FUZZ_CHECK(homed >= 0 && homed <= 3, shown);
    const QByteArrayView words = line.trimmed();
    const QByteArrayView marker = words.first(words.indexOf(' ') < 0 ? words.size() : words.indexOf(' '));
    if (const auto fields = LinuxCnc::displayFields(line, marker)) {
        for (const auto &[name, value] : *fields)
            TOFFEE_FUZZ_CHECK(!name.isEmpty() && finite(value), shown);
    }
    (void)LinuxCnc::inInches(line);
    (void)LinuxCnc::toolTableOfIni(line.toByteArray(), QStringLiteral("/x/y.ini"));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    // As the link sees them: lines cut at LF, a CR before it dropped by the transport.
    QList<QByteArray> reply;
    for (QByteArrayView line : splitView(Fuzz::bytes(data, size), '\n')) {
        const QByteArrayView one = line.endsWith('\r') ? line.chopped(1) : line;
        checkLine(one);
        checkLinuxCncLine(one);
        reply.append(one.toByteArray());
    }
    const RepeatedMeasurement repeated = repeatedMeasurement(reply);
    for (double tlo : repeated.tlos)
        TOFFEE_FUZZ_CHECK(
            std::isfinite(tlo) && std::fabs(tlo) <= kMaxMachineMillimetres, QString::number(tlo));
    TOFFEE_FUZZ_CHECK(repeated.tlos.size() <= reply.size(), QString::number(repeated.tlos.size()));
    if (repeated.using_)
        TOFFEE_FUZZ_CHECK(std::isfinite(*repeated.using_), QString::number(*repeated.using_));
    return 0;
}
