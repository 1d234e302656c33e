// SPDX-License-Identifier: GPL-3.0-or-later
// The library's row reader (RowReader) and its outbox payloads on any values a database could return. The
// input is the first byte choosing what is read (T a tools row, E an events row, U a tool use, P an outbox's
// events, W an outbox's tool writes), then fields split by 0x1F, each a type byte (n NULL, i integer, d
// real, t text, b blob) and its text. Promised: no crash; a row is either read whole and holds what Toffee
// would write (a tool number in range that is its row's, finite lengths in range) or refused with a message.
#include <cmath>

#include "model/library/outboxpayload.h"
#include "model/library/rowreader.h"
#include "model/limits.h"
#include "model/toolvalidation.h"
#include "tests/fuzz/fuzzcheck.h"

using namespace Toffee;

namespace {

QVariant field(QByteArrayView raw)
{
    if (raw.isEmpty())
        return {};
    const QByteArray rest = raw.sliced(1).toByteArray();
    switch (raw.front()) {
    case 'i':
        return QVariant(rest.toLongLong());
    case 'd':
        return QVariant(rest.toDouble());
    case 't':
        return QVariant(QString::fromUtf8(rest));
    case 'b':
        return QVariant(rest);
    default:
        return QVariant(QMetaType::fromType<QString>()); // NULL
    }
}

QVariantList fields(QByteArrayView data)
{
    QVariantList out;
    for (const QByteArrayView part : QByteArray::fromRawData(data.data(), data.size()).split('\x1f'))
        out.append(field(part));
    return out;
}

void checkEventValues(const HistoryEvent &e)
{
    TOFFEE_FUZZ_CHECK(RowReader::checkEvent(e).ok(), e.id);
    TOFFEE_FUZZ_CHECK(e.tool >= Limits::kMinToolNumber && e.tool <= Limits::kMaxToolNumber, e.id);
    for (const auto &v : { e.tlo, e.referenceMz, e.currentMz, e.tolerance, e.oldTlo, e.newTlo })
        TOFFEE_FUZZ_CHECK(!v || (std::isfinite(*v) && std::fabs(*v) <= kMaxMachineMillimetres), e.id);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArrayView input = Fuzz::bytes(data, size);
    if (input.isEmpty())
        return 0;
    const char what = input.front();
    const QByteArrayView rest = input.sliced(1);
    if (what == 'P' || what == 'W') {
        if (what == 'P') {
            if (auto events = eventsFromPayload(rest.toByteArray())) {
                for (const HistoryEvent &e : events.value())
                    checkEventValues(e);
            } else {
                TOFFEE_FUZZ_CHECK(!events.error().message.isEmpty(), QString());
            }
        } else if (auto writes = toolsFromPayload(rest.toByteArray())) {
            for (const ToolWrite &w : writes.value().writes)
                TOFFEE_FUZZ_CHECK(!w.tool || validateTool(*w.tool, writes.value().units).ok(), QString());
        }
        return 0;
    }
    QVariantList row = fields(rest);
    if (what == 'T') {
        while (row.size() < 8)
            row.append(QVariant());
        const Units units = row.at(7).toString() == QStringLiteral("in") ? Units::Inch : Units::Millimetre;
        const auto read = RowReader::tool(
            { row.at(0), row.at(1), row.at(2), row.at(3), row.at(4), row.at(5), row.at(6) }, units);
        if (!read) {
            TOFFEE_FUZZ_CHECK(!read.error().message.isEmpty(), QString());
            return 0;
        }
        const StoredTool &stored = read.value();
        TOFFEE_FUZZ_CHECK(stored.number >= Limits::kMinToolNumber && stored.number <= Limits::kMaxToolNumber,
            QString::number(stored.number));
        TOFFEE_FUZZ_CHECK(stored.version >= 1, QString::number(stored.version));
        if (stored.tool) {
            TOFFEE_FUZZ_CHECK(stored.tool->number == stored.number, QString::number(stored.tool->number));
            TOFFEE_FUZZ_CHECK(validateTool(*stored.tool, units).ok(), QString::number(stored.number));
        }
    } else if (what == 'E') {
        const auto read = RowReader::event(row);
        if (read)
            checkEventValues(read.value());
        else
            TOFFEE_FUZZ_CHECK(!read.error().message.isEmpty(), QString());
    } else if (what == 'U') {
        const auto read = RowReader::use(row);
        if (read) {
            TOFFEE_FUZZ_CHECK(std::isfinite(read.value().cuttingSeconds) && read.value().cuttingSeconds >= 0,
                read.value().id);
            TOFFEE_FUZZ_CHECK(
                std::isfinite(read.value().feedPathMm) && read.value().feedPathMm >= 0, read.value().id);
        } else {
            TOFFEE_FUZZ_CHECK(!read.error().message.isEmpty(), QString());
        }
    }
    return 0;
}
