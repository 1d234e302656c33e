// SPDX-License-Identifier: GPL-3.0-or-later
#include "textparsing.h"

#include <charconv>
#include <cmath>

#include <QStringDecoder>

namespace Toffee {

namespace {

// from_chars takes no leading '+'; controllers and LinuxCNC write one.
QByteArrayView withoutPlus(QByteArrayView text)
{
    if (text.size() > 1 && text.front() == '+' && text.at(1) != '-' && text.at(1) != '+')
        return text.sliced(1);
    return text;
}

} // namespace

std::optional<double> parseDecimal(QByteArrayView text)
{
    text = withoutPlus(text);
    if (text.isEmpty())
        return std::nullopt;
    // from_chars also reads "inf", "nan" and hex; only digits, sign, point and exponent are numbers here.
    for (char c : text) {
        if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == 'e' || c == 'E' || c == '+'))
            return std::nullopt;
    }
    double value = 0.0;
    const char *end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value))
        return std::nullopt;
    return value;
}

std::optional<qint64> parseInteger(QByteArrayView text)
{
    text = withoutPlus(text);
    if (text.isEmpty())
        return std::nullopt;
    qint64 value = 0;
    const char *end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end)
        return std::nullopt;
    return value;
}

std::optional<QString> decodeUtf8(QByteArrayView bytes)
{
    QStringDecoder decoder(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    QString text = decoder.decode(bytes);
    if (decoder.hasError() || text.contains(QChar(0)))
        return std::nullopt;
    return text;
}

} // namespace Toffee
