// SPDX-License-Identifier: GPL-3.0-or-later
// One table reader (TOFFEE_FUZZ_FORMAT: Json, LinuxCnc or Csv) on any bytes. Promised: no crash; either the
// whole table, valid, which its own writer writes and reads back unchanged, or an error with a message and a
// line inside the file, never part of a file.
#include "model/formats/tablefile.h"
#include "tests/fuzz/fuzzcheck.h"

using namespace Toffee;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    constexpr TableFormat kFormat = TableFormat::TOFFEE_FUZZ_FORMAT;
    const QByteArray file = Fuzz::bytes(data, size).toByteArray();
    const auto read = readTable(file, kFormat);
    if (!read.ok()) {
        const Error &error = read.error();
        TOFFEE_FUZZ_CHECK(!error.message.isEmpty(), error.text());
        TOFFEE_FUZZ_CHECK(error.line >= 0 && error.line <= file.count('\n') + 1, error.text());
        return 0;
    }
    const ToolTable &table = read.value();
    const auto valid = ToolTable::fromTools(table.tools(), table.units());
    TOFFEE_FUZZ_CHECK(valid.ok() && valid.value() == table, valid.ok() ? QString() : valid.error().text());

    const QByteArray written = writeTable(table, kFormat);
    const auto again = readTable(written, kFormat, table.units());
    TOFFEE_FUZZ_CHECK(again.ok(), again.ok() ? QString() : again.error().text());
    TOFFEE_FUZZ_CHECK(again.value() == table, QString::fromUtf8(written));
    TOFFEE_FUZZ_CHECK(writeTable(again.value(), kFormat) == written, QString::fromUtf8(written));
    return 0;
}
