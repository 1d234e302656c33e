// SPDX-License-Identifier: GPL-3.0-or-later
#include "textparsing.h"

#include <charconv>
#include <cmath>
#include <cstring>

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

namespace {

// Writes |n| < 1e15 in decimal, backwards from `end`; returns the first character.
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

} // namespace

void appendNumber(QByteArray &out, double value)
{
    if (value == 0.0 || !std::isfinite(value)) {
        out += '0';
        return;
    }
    char buffer[400]; // fixed notation of the largest double fits in 310 characters
    // Tool data has three to six decimals: print those directly. v == round(v * 10^k) / 10^k means the
    // k-decimal text reads back as v (division and parsing both round the same exact quotient), and no
    // shorter text can, since doubles this small hold more than 15 significant digits.
    const double magnitude = std::fabs(value);
    if (magnitude < 1e9) {
        for (const auto &[decimals, divisor] :
            { std::pair { 3, quint64(1000) }, std::pair { 6, quint64(1000000) } }) {
            const double scaled = std::round(magnitude * double(divisor));
            if (scaled / double(divisor) == magnitude) {
                out.append(buffer, writeScaled(buffer, quint64(scaled), value < 0, decimals, divisor));
                return;
            }
        }
    }
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
    out.append(buffer, ec == std::errc() ? end - buffer : 0);
}

void appendUtf8(QByteArray &out, QStringView text)
{
    const qsizetype start = out.size();
    out.resize(start + text.size());
    char *p = out.data() + start;
    for (QChar c : text) {
        if (c.unicode() >= 0x80) {
            out.resize(start);
            out += text.toUtf8();
            return;
        }
        *p++ = char(c.unicode());
    }
}

void appendIsoUtc(QByteArray &out, const QDateTime &time)
{
    const QDateTime utc = time.toUTC();
    const QDate d = utc.date();
    const QTime t = utc.time();
    if (d.year() < 0 || d.year() > 9999) {
        out += utc.toString(Qt::ISODateWithMs).toLatin1();
        return;
    }
    char b[24] = { '0', '0', '0', '0', '-', '0', '0', '-', '0', '0', 'T', '0', '0', ':', '0', '0', ':', '0',
        '0', '.', '0', '0', '0', 'Z' };
    auto put = [&b](int at, int width, int value) {
        for (int i = at + width - 1; i >= at; --i, value /= 10)
            b[i] = char('0' + value % 10);
    };
    put(0, 4, d.year());
    put(5, 2, d.month());
    put(8, 2, d.day());
    put(11, 2, t.hour());
    put(14, 2, t.minute());
    put(17, 2, t.second());
    put(20, 3, t.msec());
    out.append(b, sizeof b);
}

QDateTime parseIsoDateTime(QByteArrayView text)
{
    // The form Toffee writes, parsed by hand: QDateTime::fromString is ten times slower on big tables.
    auto digits = [&text](qsizetype at, int count, int &value) {
        value = 0;
        for (int i = 0; i < count; ++i) {
            const char c = text.at(at + i);
            if (c < '0' || c > '9')
                return false;
            value = value * 10 + (c - '0');
        }
        return true;
    };
    int y, mo, d, h, mi, s, ms = 0;
    const bool shortForm = text.size() == 20 && text.at(19) == 'Z';
    const bool msForm = text.size() == 24 && text.at(19) == '.' && text.at(23) == 'Z';
    if ((shortForm || msForm) && text.at(4) == '-' && text.at(7) == '-' && text.at(10) == 'T'
        && text.at(13) == ':' && text.at(16) == ':' && digits(0, 4, y) && digits(5, 2, mo) && digits(8, 2, d)
        && digits(11, 2, h) && digits(14, 2, mi) && digits(17, 2, s) && (!msForm || digits(20, 3, ms))) {
        const QDate date(y, mo, d);
        const QTime time(h, mi, s, ms);
        if (!date.isValid() || !time.isValid())
            return {};
        return QDateTime(date, time, Qt::UTC);
    }
    const auto string = decodeUtf8(text);
    if (!string)
        return {};
    return QDateTime::fromString(*string, Qt::ISODateWithMs).toUTC();
}

QList<QByteArrayView> splitView(QByteArrayView text, char separator)
{
    QList<QByteArrayView> parts;
    qsizetype start = 0;
    while (true) {
        const qsizetype at = text.indexOf(separator, start);
        if (at < 0) {
            parts.append(text.sliced(start));
            return parts;
        }
        parts.append(text.sliced(start, at - start));
        start = at + 1;
    }
}

std::optional<QString> decodeUtf8(QByteArrayView bytes)
{
    bool ascii = true;
    for (char c : bytes)
        ascii = ascii && uchar(c) < 0x80 && c != '\0';
    if (ascii)
        return QString::fromLatin1(bytes);
    QStringDecoder decoder(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    QString text = decoder.decode(bytes);
    if (decoder.hasError() || text.contains(QChar(0)))
        return std::nullopt;
    return text;
}

} // namespace Toffee
