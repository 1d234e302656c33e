// SPDX-License-Identifier: GPL-3.0-or-later
// The Wi-Fi beacon on any datagram a network may bring, and on any beacon its bytes make: the first four the
// address's octets, the next two the port (big-endian), the next busy (its lowest bit), the rest the name.
// Promised of a datagram: what parses has a name of 1 to kMaxNameLength printable characters, a dotted IPv4
// address of at most 15 characters and a port 1-65535; it formats to no more bytes than came, and that parses
// to the same beacon, with or without a line end after it; the datagram with a fifth field is refused. Of the
// beacon made: its format parses back to it exactly when its name is 1 to kMaxNameLength printable characters
// without a comma and its port is not 0.
#include <algorithm>

#include "serial/wire/beacon.h"
#include "tests/fuzz/fuzzcheck.h"

using namespace Toffee;
using namespace Qt::StringLiterals;

namespace {

QString shown(const Beacon &b)
{
    return b.name.left(80) + u'|' + b.address + u'|' + QString::number(b.port) + u'|'
        + (b.busy ? u'1' : u'0');
}

bool printable(QChar c)
{
    return c.unicode() >= 0x20 && c.unicode() < 0x7f;
}

void checkParsed(const Beacon &b, QByteArrayView datagram)
{
    TOFFEE_FUZZ_CHECK(!b.name.isEmpty() && b.name.size() <= Beacon::kMaxNameLength, shown(b));
    TOFFEE_FUZZ_CHECK(std::all_of(b.name.begin(), b.name.end(), printable), shown(b));
    TOFFEE_FUZZ_CHECK(!b.name.contains(u','), shown(b));
    TOFFEE_FUZZ_CHECK(
        b.address.size() >= 7 && b.address.size() <= 15 && b.address.count(u'.') == 3, shown(b));
    TOFFEE_FUZZ_CHECK(b.port >= 1, shown(b)); // quint16: never above 65535

    const QByteArray formatted = b.format();
    TOFFEE_FUZZ_CHECK(formatted.size() <= datagram.size(), QString::fromLatin1(formatted));
    const auto again = Beacon::parse(formatted);
    TOFFEE_FUZZ_CHECK(again && *again == b, QString::fromLatin1(formatted));
    TOFFEE_FUZZ_CHECK(again->format() == formatted, QString::fromLatin1(formatted));
    const auto ended = Beacon::parse(QByteArray(formatted + "\r\n"));
    TOFFEE_FUZZ_CHECK(ended && *ended == b, QString::fromLatin1(formatted));
    TOFFEE_FUZZ_CHECK(!Beacon::parse(QByteArray(datagram.toByteArray() + ",0")), shown(b));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArrayView datagram = Fuzz::bytes(data, size);
    if (const auto parsed = Beacon::parse(datagram))
        checkParsed(*parsed, datagram);

    if (size < 7)
        return 0;
    Beacon made;
    made.address = u"%1.%2.%3.%4"_s.arg(data[0]).arg(data[1]).arg(data[2]).arg(data[3]);
    made.port = quint16((data[4] << 8) | data[5]);
    made.busy = data[6] & 1;
    made.name = QString::fromLatin1(datagram.sliced(7));
    const bool valid = made.port != 0 && !made.name.isEmpty() && made.name.size() <= Beacon::kMaxNameLength
        && std::all_of(made.name.begin(), made.name.end(), printable) && !made.name.contains(u',');
    const auto back = Beacon::parse(made.format());
    TOFFEE_FUZZ_CHECK(back.has_value() == valid, shown(made));
    TOFFEE_FUZZ_CHECK(!back || *back == made, shown(made) + u" vs " + shown(*back));
    return 0;
}
