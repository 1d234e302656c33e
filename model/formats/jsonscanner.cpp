// SPDX-License-Identifier: GPL-3.0-or-later
// JsonScanner's slow paths, out of line: errors and their column, escapes and their decoding.
#include "model/formats/jsonscanner.h"

namespace Toffee {

bool JsonScanner::failAt(const char *at, const QString &message)
{
    if (!m_failed) {
        m_failed = true;
        m_error = Error { message, m_line };
        m_errorColumn = columnOf(at);
    }
    return false;
}

bool JsonScanner::syntax(const char *expected)
{
    return fail(tr("this is not valid JSON: expected %1.").arg(QLatin1StringView(expected)));
}

bool JsonScanner::controlCharacter()
{
    return fail(tr("this is not valid JSON: a line break or control character inside a string; write it as "
                   "\\n."));
}

int JsonScanner::columnOf(const char *at) const
{
    at = std::clamp(at, m_lineStart, m_end);
    qsizetype column = 1;
    for (const char *p = m_lineStart; p < at; ++p) {
        column += (uchar(*p) & 0xc0) != 0x80;
        column += uchar(*p) >= 0xf0;
    }
    return int(std::min<qsizetype>(column, INT_MAX));
}

bool JsonScanner::escapedString(const char *start, QString &out)
{
    QByteArray buffer(start, m_p - start);
    while (m_p < m_end) {
        if (buffer.size() > kMaxTextBytes)
            return tooLong(start);
        const char c = *m_p++;
        if (c == '"')
            return decode(buffer, 0x80, out);
        if (uchar(c) < 0x20) {
            --m_p;
            return controlCharacter();
        }
        if (c != '\\') {
            buffer += c;
            continue;
        }
        if (m_p >= m_end)
            break;
        if (!escape(&buffer))
            return false;
    }
    return fail(tr("this is not valid JSON: a string is never closed."));
}

bool JsonScanner::escape(QByteArray *buffer)
{
    const char e = *m_p++;
    char decoded = 0;
    switch (e) {
    case '"':
    case '\\':
    case '/':
        decoded = e;
        break;
    case 'b':
        decoded = '\b';
        break;
    case 'f':
        decoded = '\f';
        break;
    case 'n':
        decoded = '\n';
        break;
    case 'r':
        decoded = '\r';
        break;
    case 't':
        decoded = '\t';
        break;
    case 'u':
        return unicodeEscape(buffer);
    default:
        return fail(tr("this is not valid JSON: unknown escape \\%1 in a string.").arg(QLatin1Char(e)));
    }
    if (buffer)
        *buffer += decoded;
    return true;
}

bool JsonScanner::unicodeEscape(QByteArray *buffer)
{
    char32_t code = 0;
    if (!hex4(code))
        return false;
    if (code >= 0xD800 && code <= 0xDBFF) {
        char32_t low = 0;
        if (m_end - m_p < 6 || m_p[0] != '\\' || m_p[1] != 'u')
            return fail(tr("this is not valid JSON: a lone UTF-16 surrogate in a \\u escape."));
        m_p += 2;
        if (!hex4(low) || low < 0xDC00 || low > 0xDFFF)
            return fail(tr("this is not valid JSON: a lone UTF-16 surrogate in a \\u escape."));
        code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
    } else if (code >= 0xDC00 && code <= 0xDFFF) {
        return fail(tr("this is not valid JSON: a lone UTF-16 surrogate in a \\u escape."));
    }
    if (buffer)
        *buffer += QString::fromUcs4(&code, 1).toUtf8();
    return true;
}

bool JsonScanner::hex4(char32_t &code)
{
    if (m_end - m_p < 4)
        return fail(tr("this is not valid JSON: a \\u escape needs four hex digits."));
    for (int i = 0; i < 4; ++i) {
        const char h = *m_p++;
        const int v = h >= '0' && h <= '9' ? h - '0'
            : h >= 'a' && h <= 'f'         ? h - 'a' + 10
            : h >= 'A' && h <= 'F'         ? h - 'A' + 10
                                           : -1;
        if (v < 0)
            return fail(tr("this is not valid JSON: a \\u escape needs four hex digits."));
        code = code * 16 + char32_t(v);
    }
    return true;
}

bool JsonScanner::decode(QByteArrayView raw, uchar high, QString &out)
{
    if (!(high & 0x80)) {
        out = QString::fromLatin1(raw);
        return true;
    }
    auto text = decodeUtf8(raw);
    if (!text)
        return fail(tr("a string is not valid UTF-8 text."));
    out = std::move(*text);
    return true;
}

} // namespace Toffee
