// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QByteArray>
#include <QByteArrayView>
#include <QDateTime>
#include <QList>
#include <QString>

namespace Toffee {

// Strict, locale-free number parsing for files and machine replies: the whole text must be the number
// (an optional leading + or -), and the result finite. Anything else is "not a number", never 0; a number too
// close to zero for a double (1e-400) is 0, as the C library reads it.
[[nodiscard]] std::optional<double> parseDecimal(QByteArrayView text);
[[nodiscard]] std::optional<qint64> parseInteger(QByteArrayView text);

// Appends `text` as UTF-8; ASCII (nearly all tool data) is copied straight, without a temporary.
void appendUtf8(QByteArray &out, QStringView text);

// ISO 8601 in UTC with milliseconds ("2026-11-22T10:15:00.125Z"), as files store times.
void appendIsoUtc(QByteArray &out, const QDateTime &time);
// ISO 8601 with or without milliseconds and with Z or an offset; invalid QDateTime when it is not one.
[[nodiscard]] QDateTime parseIsoDateTime(QByteArrayView text);

// `text` cut at every `separator`, as views into it (Qt 6.4's QByteArrayView has no split()).
[[nodiscard]] QList<QByteArrayView> splitView(QByteArrayView text, char separator);

// UTF-8 to QString, or nothing when the bytes are not valid UTF-8 (a garbled or binary file).
[[nodiscard]] std::optional<QString> decodeUtf8(QByteArrayView bytes);
// Where the first byte that is not valid UTF-8 text (or a NUL) is, or -1 when there is none.
[[nodiscard]] qsizetype firstInvalidUtf8(QByteArrayView bytes);
// The 1-based line that byte `offset` of `data` is on.
[[nodiscard]] int lineAt(QByteArrayView data, qsizetype offset);

// What a message quotes of a value: the value itself when it is short, else its first `maxChars` characters
// and an ellipsis with the length, so that a 10 MB token never becomes a 10 MB message.
inline constexpr qsizetype kMaxQuotedChars = 40;
[[nodiscard]] QString excerpt(QStringView text, qsizetype maxChars = kMaxQuotedChars);
[[nodiscard]] QString excerpt(QByteArrayView utf8, qsizetype maxChars = kMaxQuotedChars);

// Text that is all digits after an optional sign: a whole number, even one too large for any integer type.
[[nodiscard]] bool isIntegerText(QByteArrayView text);

} // namespace Toffee
