// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cmath>
#include <cstring>

#include <QByteArrayView>
#include <QCoreApplication>
#include <QString>

#include "model/result.h"
#include "model/textparsing.h"

namespace Toffee {

// A JSON value that is not an object or array (those are parsed and kept as "Composite").
struct Scalar
{
    enum Kind { Null, Bool, Number, String, Composite } kind = Null;
    double number = 0.0;
    QString string;
};

// A strict streaming JSON reader (RFC 8259) that knows the line of everything it reads: errors name the
// line of the value at fault, and no document tree is built.
class JsonScanner
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::JsonScanner)

public:
    explicit JsonScanner(QByteArrayView data)
        : m_p(data.data())
        , m_end(data.data() + data.size())
    { }

    int line() const { return m_line; }
    bool failed() const { return m_failed; }
    const Error &error() const { return m_error; }

    bool fail(const QString &message)
    {
        if (!m_failed) {
            m_failed = true;
            m_error = Error { message, m_line };
        }
        return false;
    }
    bool syntax(const char *expected)
    {
        return fail(tr("this is not valid JSON: expected %1.").arg(QLatin1StringView(expected)));
    }

    void skipSpace()
    {
        while (m_p < m_end) {
            const char c = *m_p;
            if (c == '\n')
                ++m_line;
            else if (c != ' ' && c != '\t' && c != '\r')
                return;
            ++m_p;
        }
    }
    char peek()
    {
        skipSpace();
        return m_p < m_end ? *m_p : '\0';
    }
    bool consume(char c)
    {
        if (peek() != c)
            return false;
        ++m_p;
        return true;
    }
    bool expect(char c, const char *what) { return consume(c) || syntax(what); }
    bool atEnd()
    {
        skipSpace();
        return m_p >= m_end;
    }

    // A key: read in place when it has no escapes (every key Toffee knows), else decoded as a string.
    bool key(QByteArrayView &raw, QString &decoded)
    {
        if (peek() != '"')
            return syntax("a key in double quotes");
        const char *start = m_p + 1;
        const char *q = start;
        while (q < m_end && *q != '"' && *q != '\\' && uchar(*q) >= 0x20 && uchar(*q) < 0x80)
            ++q;
        if (q < m_end && *q == '"') {
            raw = QByteArrayView(start, q - start);
            m_p = q + 1;
            return true;
        }
        if (!string(decoded))
            return false;
        m_keyBuffer = decoded.toUtf8();
        raw = m_keyBuffer;
        return true;
    }

    // No field of a tool table holds more (notes: 10,000 characters): a longer text is refused as it is
    // scanned, before a copy of it is made.
    static constexpr qsizetype kMaxTextBytes = 64 * 1024;
    bool tooLong(const char *start)
    {
        return fail(tr("the text \"%1\" is longer than %2 KB; no field of a tool table holds that much.")
                        .arg(excerpt(QByteArrayView(start, std::min<qsizetype>(m_end - start, 256))))
                        .arg(kMaxTextBytes / 1024));
    }

    bool string(QString &out)
    {
        if (!consume('"'))
            return syntax("a string in double quotes");
        const char *start = m_p;
        uchar high = 0;
        while (m_p < m_end && *m_p != '"' && *m_p != '\\' && uchar(*m_p) >= 0x20)
            high |= uchar(*m_p++);
        if (m_p - start > kMaxTextBytes)
            return tooLong(start);
        if (m_p < m_end && *m_p == '"') {
            const QByteArrayView raw(start, m_p - start);
            ++m_p;
            return decode(raw, high, out);
        }
        return escapedString(start, out);
    }

    bool number(double &out)
    {
        skipSpace();
        const char *start = m_p;
        auto digits = [this] {
            const char *from = m_p;
            while (m_p < m_end && *m_p >= '0' && *m_p <= '9')
                ++m_p;
            return m_p - from;
        };
        if (m_p < m_end && *m_p == '-')
            ++m_p;
        const char *intStart = m_p;
        const auto intDigits = digits();
        if (intDigits == 0 || (intDigits > 1 && *intStart == '0'))
            return syntax("a number");
        if (m_p < m_end && *m_p == '.') {
            ++m_p;
            if (digits() == 0)
                return syntax("digits after the decimal point");
        }
        if (m_p < m_end && (*m_p == 'e' || *m_p == 'E')) {
            ++m_p;
            if (m_p < m_end && (*m_p == '+' || *m_p == '-'))
                ++m_p;
            if (digits() == 0)
                return syntax("digits in the exponent");
        }
        const auto value = parseDecimal(QByteArrayView(start, m_p - start));
        if (!value)
            return fail(tr("the number %1 is too large.").arg(excerpt(QByteArrayView(start, m_p - start))));
        out = *value;
        return true;
    }

    bool value(Scalar &out, int depth = 0)
    {
        if (depth > 64)
            return fail(tr("this is not valid JSON for a tool table: nested too deeply."));
        const char c = peek();
        out = Scalar();
        if (c == '"') {
            out.kind = Scalar::String;
            return string(out.string);
        }
        if (c == '-' || (c >= '0' && c <= '9')) {
            out.kind = Scalar::Number;
            return number(out.number);
        }
        if (c == '{' || c == '[') {
            out.kind = Scalar::Composite;
            ++m_p;
            const char close = c == '{' ? '}' : ']';
            if (consume(close))
                return true;
            do {
                Scalar inner;
                if (c == '{') {
                    QString key;
                    if (!string(key) || !expect(':', "':' after a key"))
                        return false;
                }
                if (!value(inner, depth + 1))
                    return false;
            } while (consume(','));
            return expect(close, c == '{' ? "',' or '}'" : "',' or ']'");
        }
        for (const auto &[word, kind] : { std::pair { "true", Scalar::Bool },
                 std::pair { "false", Scalar::Bool }, std::pair { "null", Scalar::Null } }) {
            const qsizetype n = qsizetype(std::strlen(word));
            if (m_end - m_p >= n && QByteArrayView(m_p, n) == word) {
                m_p += n;
                out.kind = kind;
                out.number = word[0] == 't' ? 1.0 : 0.0;
                return true;
            }
        }
        return syntax("a value");
    }

private:
    // The rest of a string that has an escape (or a fault) at `m_p`; `start` is its first character. Only
    // such a string is copied into a buffer of its own.
    bool escapedString(const char *start, QString &out)
    {
        QByteArray buffer(start, m_p - start);
        while (m_p < m_end) {
            if (buffer.size() > kMaxTextBytes)
                return tooLong(start);
            const char c = *m_p++;
            if (c == '"')
                return decode(buffer, 0x80, out);
            if (uchar(c) < 0x20)
                return fail(tr("this is not valid JSON: a line break or control character inside a string; "
                               "write it as \\n."));
            if (c != '\\') {
                buffer += c;
                continue;
            }
            if (m_p >= m_end)
                break;
            if (!escape(buffer))
                return false;
        }
        return fail(tr("this is not valid JSON: a string is never closed."));
    }

    // The escape after a backslash, onto `buffer` as UTF-8.
    bool escape(QByteArray &buffer)
    {
        const char e = *m_p++;
        switch (e) {
        case '"':
        case '\\':
        case '/':
            buffer += e;
            return true;
        case 'b':
            buffer += '\b';
            return true;
        case 'f':
            buffer += '\f';
            return true;
        case 'n':
            buffer += '\n';
            return true;
        case 'r':
            buffer += '\r';
            return true;
        case 't':
            buffer += '\t';
            return true;
        case 'u':
            return unicodeEscape(buffer);
        default:
            return fail(tr("this is not valid JSON: unknown escape \\%1 in a string.").arg(QLatin1Char(e)));
        }
    }

    // \uXXXX, and the low half that must follow a high surrogate: one character beyond the BMP.
    bool unicodeEscape(QByteArray &buffer)
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
        buffer += QString::fromUcs4(&code, 1).toUtf8();
        return true;
    }

    bool hex4(char32_t &code)
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

    bool decode(QByteArrayView raw, uchar high, QString &out)
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

    const char *m_p;
    const char *m_end;
    int m_line = 1;
    bool m_failed = false;
    Error m_error;
    QByteArray m_keyBuffer;
};

} // namespace Toffee
