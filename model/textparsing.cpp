// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/textparsing.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>

#include <QCoreApplication>
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

// For a number from_chars found out of range: whether it is too small rather than too large, from the
// decimal exponent of its first significant digit.
bool underflows(QByteArrayView text)
{
    qsizetype i = text.front() == '-' || text.front() == '+' ? 1 : 0;
    qint64 magnitude = 0; // the power of ten of the first significant digit
    bool found = false;
    qint64 integerDigits = 0;
    for (; i < text.size() && text.at(i) >= '0' && text.at(i) <= '9'; ++i) {
        if (found || text.at(i) != '0')
            ++integerDigits, found = true;
    }
    if (found) {
        magnitude = integerDigits - 1;
    } else if (i < text.size() && text.at(i) == '.') {
        qint64 place = 0;
        for (++i; i < text.size() && text.at(i) >= '0' && text.at(i) <= '9'; ++i) {
            --place;
            if (text.at(i) != '0') {
                found = true;
                magnitude = place;
                break;
            }
        }
    }
    if (!found)
        return true; // all zeros: zero
    while (i < text.size() && text.at(i) != 'e' && text.at(i) != 'E')
        ++i;
    qint64 exponent = 0;
    if (i < text.size()) {
        ++i;
        const bool negative = i < text.size() && text.at(i) == '-';
        if (i < text.size() && (text.at(i) == '-' || text.at(i) == '+'))
            ++i;
        for (; i < text.size(); ++i)
            exponent = std::min<qint64>(exponent * 10 + (text.at(i) - '0'), qint64(1) << 40);
        if (negative)
            exponent = -exponent;
    }
    return magnitude + exponent < 0;
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
    if (ec == std::errc::result_out_of_range && ptr == end && underflows(text))
        return text.front() == '-' ? -0.0 : 0.0;
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

qsizetype firstInvalidUtf8(QByteArrayView bytes)
{
    const auto *p = reinterpret_cast<const uchar *>(bytes.data());
    const qsizetype n = bytes.size();
    qsizetype i = 0;
    while (i < n) {
        const uchar c = p[i];
        if (c == 0)
            return i;
        if (c < 0x80) {
            ++i;
            continue;
        }
        // The shortest form only, no surrogates, nothing above U+10FFFF (RFC 3629).
        int extra = 0;
        uint lowest = 0;
        uint code = 0;
        if ((c & 0xE0) == 0xC0)
            extra = 1, lowest = 0x80, code = c & 0x1F;
        else if ((c & 0xF0) == 0xE0)
            extra = 2, lowest = 0x800, code = c & 0x0F;
        else if ((c & 0xF8) == 0xF0)
            extra = 3, lowest = 0x10000, code = c & 0x07;
        else
            return i;
        if (i + extra >= n)
            return i;
        for (int k = 1; k <= extra; ++k) {
            if ((p[i + k] & 0xC0) != 0x80)
                return i;
            code = (code << 6) | (p[i + k] & 0x3F);
        }
        if (code < lowest || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
            return i;
        i += extra + 1;
    }
    return -1;
}

int lineAt(QByteArrayView data, qsizetype offset)
{
    offset = std::clamp<qsizetype>(offset, 0, data.size());
    return int(std::min<qsizetype>(std::count(data.begin(), data.begin() + offset, '\n') + 1, INT_MAX));
}

QString excerpt(QStringView text, qsizetype maxChars)
{
    if (text.size() <= maxChars)
        return text.toString();
    qsizetype cut = maxChars;
    if (text.at(cut - 1).isHighSurrogate())
        --cut;
    return QCoreApplication::translate("Toffee", "%1… (%2 characters)").arg(text.first(cut)).arg(text.size());
}

QString excerpt(QByteArrayView utf8, qsizetype maxChars)
{
    // Decoding a 10 MB token to quote 40 characters of it would be the very cost this avoids.
    const qsizetype bytes = std::min(utf8.size(), maxChars * 4);
    QString head = QString::fromUtf8(utf8.first(bytes));
    if (utf8.size() <= bytes && head.size() <= maxChars)
        return head;
    qsizetype cut = std::min(head.size(), maxChars);
    if (cut > 0 && head.at(cut - 1).isHighSurrogate())
        --cut;
    return QCoreApplication::translate("Toffee", "%1… (%2 bytes)").arg(head.first(cut)).arg(utf8.size());
}

bool isIntegerText(QByteArrayView text)
{
    if (!text.isEmpty() && (text.front() == '-' || text.front() == '+'))
        text = text.sliced(1);
    return !text.isEmpty()
        && std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

} // namespace Toffee
