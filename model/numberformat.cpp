// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/numberformat.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

#include <QLocale>

namespace Toffee {

namespace {

// Writes n in decimal, backwards from `end`; returns the first character.
char *writeDigits(char *end, quint64 n)
{
    do {
        *--end = char('0' + n % 10);
        n /= 10;
    } while (n);
    return end;
}

// Fixed point with `decimals` places, trailing zeros dropped. Exact when value == scaled / 10^decimals.
qsizetype writeScaled(char *buffer, quint64 scaled, bool negative, int decimals, quint64 divisor)
{
    char digits[32];
    char *end = digits + sizeof digits;
    quint64 fraction = scaled % divisor;
    int places = decimals;
    while (places > 0 && fraction % 10 == 0) {
        fraction /= 10;
        --places;
    }
    char *p = end;
    if (places > 0) {
        for (int i = 0; i < places; ++i) {
            *--p = char('0' + fraction % 10);
            fraction /= 10;
        }
        *--p = '.';
    }
    p = writeDigits(p, scaled / divisor);
    if (negative)
        *--p = '-';
    const qsizetype n = end - p;
    std::memcpy(buffer, p, size_t(n));
    return n;
}

// The shortest text that reads back as `value`, in fixed notation.
qsizetype writeExact(char *buffer, qsizetype size, double value)
{
    if (value == 0.0 || !std::isfinite(value)) {
        buffer[0] = '0';
        return 1;
    }
    // Tool data has three to six decimals: print those directly. v == round(v * 10^k) / 10^k means the
    // k-decimal text reads back as v (division and parsing both round the same exact quotient), and no
    // shorter text can, since doubles this small hold more than 15 significant digits.
    const double magnitude = std::fabs(value);
    if (magnitude < 1e9) {
        for (const auto &[decimals, divisor] :
            { std::pair { 3, quint64(1000) }, std::pair { 6, quint64(1000000) } }) {
            const double scaled = std::round(magnitude * double(divisor));
            if (scaled / double(divisor) == magnitude)
                return writeScaled(buffer, quint64(scaled), value < 0, decimals, divisor);
        }
    }
    const auto [end, ec] = std::to_chars(buffer, buffer + size, value, std::chars_format::fixed);
    return ec == std::errc() ? end - buffer : 0;
}

// Drops trailing zeros after the point down to `keep` decimals, and the point when none remain.
qsizetype trimZeros(const char *buffer, qsizetype n, int keep)
{
    const char *point = static_cast<const char *>(std::memchr(buffer, '.', size_t(n)));
    if (!point)
        return n;
    const qsizetype pointAt = point - buffer;
    while (n - pointAt - 1 > keep && buffer[n - 1] == '0')
        --n;
    return n == pointAt + 1 ? pointAt : n;
}

// A text such as "-0.000" names no negative number: it loses its sign.
qsizetype dropNegativeZero(char *buffer, qsizetype n)
{
    if (n < 2 || buffer[0] != '-')
        return n;
    if (std::any_of(buffer + 1, buffer + n, [](char c) { return c >= '1' && c <= '9'; }))
        return n;
    std::memmove(buffer, buffer + 1, size_t(n - 1));
    return n - 1;
}

// Pads with zeros to `decimals` places after the point.
qsizetype padZeros(char *buffer, qsizetype n, int decimals)
{
    const char *point = static_cast<const char *>(std::memchr(buffer, '.', size_t(n)));
    int have = point ? int(n - (point - buffer) - 1) : 0;
    if (have >= decimals)
        return n;
    if (!point)
        buffer[n++] = '.';
    for (; have < decimals; ++have)
        buffer[n++] = '0';
    return n;
}

} // namespace

void appendNumber(QByteArray &out, double value, NumberFormat format)
{
    // Fixed notation of the largest double is 309 digits; a maximum of up to 40 decimals and padding fit too.
    constexpr qsizetype kSize = 400;
    char buffer[kSize];
    const int maxDecimals = std::min(format.maxDecimals, 40);
    const int minDecimals = std::clamp(format.minDecimals, 0, 40);
    qsizetype n = 0;
    if (maxDecimals < 0) {
        n = writeExact(buffer, kSize - 48, value);
    } else {
        const auto [end, ec]
            = std::to_chars(buffer, buffer + kSize - 48, value, std::chars_format::fixed, maxDecimals);
        n = ec == std::errc() ? end - buffer : 0;
        n = trimZeros(buffer, n, minDecimals);
        if (std::isfinite(value))
            n = dropNegativeZero(buffer, n);
    }
    if (std::isfinite(value))
        n = padZeros(buffer, n, minDecimals);
    out.append(buffer, n);
}

QByteArray numberBytes(double value, NumberFormat format)
{
    QByteArray out;
    appendNumber(out, value, format);
    return out;
}

QString formatNumber(double value, NumberFormat format)
{
    const QByteArray text = numberBytes(value, format);
    if (!format.localized || !std::isfinite(value))
        return QString::fromLatin1(text);
    // The same digits in the user's locale: the decimals the text has, and no sign on a zero.
    const qsizetype point = text.indexOf('.');
    const int decimals = point < 0 ? 0 : int(text.size() - point - 1);
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(text.startsWith('-') ? value : std::fabs(value), 'f', decimals);
}

QString quotedNumber(double value)
{
    constexpr qsizetype kMaxDigits = 20;
    const QString plain = formatNumber(value);
    if (plain.size() <= kMaxDigits || !std::isfinite(value))
        return plain;
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

QString displayNumber(double value, Units units)
{
    return formatNumber(value, NumberFormat::display(units));
}

QString millimetres(double value, bool withUnit)
{
    const QString number = formatNumber(value, NumberFormat::fixed(3).inLocale());
    return withUnit ? number + QStringLiteral(" mm") : number;
}

} // namespace Toffee
