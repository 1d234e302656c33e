// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>

#include <QByteArrayView>
#include <QCoreApplication>
#include <QSet>
#include <QString>

#include "model/result.h"
#include "model/textparsing.h"

namespace Toffee {

// A JSON value as read: a scalar with its value, or a list or an object, read through (every key and value in
// it checked) but not kept.
struct Scalar
{
    enum Kind { Null, Bool, Number, String, List, Object } kind = Null;
    double number = 0.0;
    QString string;
};

// The keys of one object read so far (JsonScanner::keyOnce).
using JsonKeys = QSet<QByteArray>;

// A strict streaming JSON reader (RFC 8259) that knows the line of everything it reads: errors name the
// line of the value at fault, and no document tree is built. A key given twice in any object it reads or
// reads through is refused: RFC 8259 leaves its meaning open, and a reader that took the first or the last
// would guess.
class JsonScanner
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::JsonScanner)

public:
    // No file Toffee reads nests deeper (a Fusion library: 6 levels); each level costs a little stack.
    static constexpr int kMaxDepth = 64;

    explicit JsonScanner(QByteArrayView data)
        : m_p(data.data())
        , m_end(data.data() + data.size())
        , m_lineStart(data.data())
    { }

    int line() const { return m_line; }
    bool failed() const { return m_failed; }
    const Error &error() const { return m_error; }
    // The column of the error on its line, in characters (UTF-16 code units, as an editor counts them).
    int errorColumn() const { return m_errorColumn; }

    bool fail(const QString &message) { return failAt(m_p, message); }
    bool failAt(const char *at, const QString &message);
    bool syntax(const char *expected);

    void skipSpace()
    {
        while (m_p < m_end) {
            const char c = *m_p;
            if (c == '\n') {
                ++m_line;
                m_lineStart = m_p + 1;
            } else if (c != ' ' && c != '\t' && c != '\r') {
                return;
            }
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
        m_keyAt = m_p;
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

    // Whether `key`, just read by key(), is new among `keys`, the keys read so far of the object at `depth`
    // (0: the top level), which is the value of `container` (or of none). Each key is hashed once: linear.
    bool keyOnce(JsonKeys &keys, QByteArrayView key, int depth, QByteArrayView container = {})
    {
        const qsizetype before = keys.size();
        keys.insert(key.toByteArray());
        if (keys.size() > before)
            return true;
        const QString name = excerpt(key);
        return failAt(m_keyAt,
            depth == 0
                ? tr("the key \"%1\" appears twice at the top level; Toffee will not guess which one is "
                     "meant.")
                      .arg(name)
                : container.isEmpty()
                ? tr("the key \"%1\" appears twice in one object; Toffee will not guess which one is meant.")
                      .arg(name)
                : tr("the key \"%1\" appears twice in \"%2\"; Toffee will not guess which one is meant.")
                      .arg(name, excerpt(container)));
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

    // A value at `depth` (0: the whole document), the value of `container` (a key, or none). A string is kept
    // up to kMaxTextBytes; a list or an object is read through.
    bool value(Scalar &out, int depth = 0, QByteArrayView container = {})
    {
        const char c = peek();
        out = Scalar();
        if (c == '"') {
            out.kind = Scalar::String;
            return string(out.string);
        }
        if (c == '{' || c == '[') {
            out.kind = c == '{' ? Scalar::Object : Scalar::List;
            return skipComposite(depth, container);
        }
        return literal(out);
    }

    // Any value, checked as value() checks it but kept nowhere: its strings are not copied, whatever their
    // size.
    bool skip(int depth = 0, QByteArrayView container = {})
    {
        const char c = peek();
        if (c == '"')
            return skipString();
        if (c == '{' || c == '[')
            return skipComposite(depth, container);
        Scalar ignored;
        return literal(ignored);
    }

private:
    // A number, true, false or null.
    bool literal(Scalar &out)
    {
        const char c = peek();
        if (c == '-' || (c >= '0' && c <= '9')) {
            out.kind = Scalar::Number;
            return number(out.number);
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

    // The object or list at '{' or '[', at `depth`: every key once, every value checked, nothing kept. The
    // values of a list are named by the list's own key.
    bool skipComposite(int depth, QByteArrayView container)
    {
        if (depth > kMaxDepth)
            return fail(tr("this is not JSON Toffee reads: it is nested too deeply (more than %1 levels).")
                            .arg(kMaxDepth));
        const char open = *m_p++;
        const char close = open == '{' ? '}' : ']';
        if (consume(close))
            return true;
        // Its own copy: `container` may be the key buffer, which the keys inside replace.
        const QByteArray owner = container.toByteArray();
        JsonKeys keys;
        QByteArray name;
        do {
            if (open == '{') {
                QByteArrayView raw;
                QString decoded;
                if (!key(raw, decoded) || !keyOnce(keys, raw, depth, owner))
                    return false;
                name = raw.toByteArray();
                if (!expect(':', "':' after a key"))
                    return false;
            }
            if (!skip(depth + 1, open == '{' ? QByteArrayView(name) : QByteArrayView(owner)))
                return false;
        } while (consume(','));
        return expect(close, open == '{' ? "',' or '}'" : "',' or ']'");
    }

    // A string read through: its escapes and its UTF-8 checked, nothing copied.
    bool skipString()
    {
        if (!consume('"'))
            return syntax("a string in double quotes");
        const char *run = m_p; // the bytes since the last escape
        while (m_p < m_end) {
            const char c = *m_p;
            if (c == '"' || c == '\\') {
                if (!QByteArrayView(run, m_p - run).isValidUtf8())
                    return fail(tr("a string is not valid UTF-8 text."));
                ++m_p;
                if (c == '"')
                    return true;
                if (m_p >= m_end)
                    break;
                if (!escape(nullptr))
                    return false;
                run = m_p;
            } else if (uchar(c) < 0x20) {
                return controlCharacter();
            } else {
                ++m_p;
            }
        }
        return fail(tr("this is not valid JSON: a string is never closed."));
    }

    bool controlCharacter();

    // The column of `at` on the current line: one for each character, two for one beyond the BMP.
    int columnOf(const char *at) const;

    // The rest of a string that has an escape (or a fault) at `m_p`; `start` is its first character. Only
    // such a string is copied into a buffer of its own.
    bool escapedString(const char *start, QString &out);

    // The escape after a backslash, onto `buffer` as UTF-8 (when there is one: else only checked).
    bool escape(QByteArray *buffer);

    // \uXXXX, and the low half that must follow a high surrogate: one character beyond the BMP.
    bool unicodeEscape(QByteArray *buffer);

    bool hex4(char32_t &code);

    bool decode(QByteArrayView raw, uchar high, QString &out);

    const char *m_p;
    const char *m_end;
    const char *m_lineStart;
    const char *m_keyAt = nullptr; // the opening quote of the last key read
    int m_line = 1;
    bool m_failed = false;
    Error m_error;
    int m_errorColumn = 0;
    QByteArray m_keyBuffer;
};

} // namespace Toffee
