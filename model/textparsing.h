// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QByteArrayView>
#include <QString>

namespace Toffee {

// Strict, locale-free number parsing for files and machine replies: the whole text must be the number
// (an optional leading + or -), and the result finite. Anything else is "not a number", never 0.
[[nodiscard]] std::optional<double> parseDecimal(QByteArrayView text);
[[nodiscard]] std::optional<qint64> parseInteger(QByteArrayView text);

// UTF-8 to QString, or nothing when the bytes are not valid UTF-8 (a garbled or binary file).
[[nodiscard]] std::optional<QString> decodeUtf8(QByteArrayView bytes);

} // namespace Toffee
