// SPDX-License-Identifier: GPL-3.0-or-later
// For a test that speaks for a plain-text machine: what such a machine says to the transport's first question
// (StreamTransport::firstQuestion(), asked on every opening, a protocol chosen or not): a status report for
// the '?' in it, then "ok" to the line end that follows.
#pragma once

#include <functional>

#include <QByteArray>
#include <QTest>

#include "serial/transport/streamtransport.h"

namespace Toffee::Test {

inline constexpr char kPlainStatus[] = "<Idle|MPos:0.000,0.000,0.000>\r\n";

// `read` returns what came since it was last called. False when the question or the line end after it did not
// come within `ms`.
inline bool answerFirstQuestion(const std::function<QByteArray()> &read,
    const std::function<void(const QByteArray &)> &write, int ms = 3000)
{
    const QByteArray question = StreamTransport::firstQuestion();
    QByteArray got;
    if (!QTest::qWaitFor(
            [&] {
                got += read();
                return got.contains(question);
            },
            ms))
        return false;
    got.remove(0, got.indexOf(question) + question.size());
    write(kPlainStatus);
    if (!QTest::qWaitFor(
            [&] {
                got += read();
                return got.contains('\n');
            },
            ms))
        return false;
    write("ok\r\n");
    return true;
}

} // namespace Toffee::Test
