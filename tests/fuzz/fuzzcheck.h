// SPDX-License-Identifier: GPL-3.0-or-later
// What a fuzz target asserts beyond "no crash": a broken promise aborts, so libFuzzer keeps the input
// and the replay test fails on it.
#pragma once

#include <cstdio>
#include <cstdlib>

#include <QByteArrayView>
#include <QString>

namespace Toffee::Fuzz {

[[noreturn]] inline void fail(const char *condition, const QString &detail, const char *file, int line)
{
    std::fprintf(stderr, "%s:%d: broken promise: %s\n  %s\n", file, line, condition, qPrintable(detail));
    std::abort();
}

inline QByteArrayView bytes(const uint8_t *data, size_t size)
{
    return QByteArrayView(reinterpret_cast<const char *>(data), qsizetype(size));
}

} // namespace Toffee::Fuzz

#define TOFFEE_FUZZ_CHECK(condition, detail)                                                                 \
    ((condition) ? void() : ::Toffee::Fuzz::fail(#condition, (detail), __FILE__, __LINE__))
