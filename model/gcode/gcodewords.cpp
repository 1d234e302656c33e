// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/gcode/gcodewords.h"

#include <cmath>

#include "model/limits.h"
#include "model/textparsing.h"

namespace Toffee {

namespace {

bool isLetter(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

bool isNumberChar(char c)
{
    return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+';
}

char upper(char c)
{
    return c >= 'a' && c <= 'z' ? char(c - 'a' + 'A') : c;
}

bool same(double a, double b)
{
    return std::fabs(a - b) < 1e-6;
}

} // namespace

GCodeLexer::Token GCodeLexer::fail(QString message)
{
    m_error = std::move(message);
    m_at = m_text.size();
    return Token::Error;
}

GCodeLexer::Token GCodeLexer::next()
{
    const qsizetype n = m_text.size();
    while (m_at < n) {
        const char c = m_text.at(m_at);
        if (c == ' ' || c == '\t' || c == '\r' || c == '%') {
            ++m_at;
        } else if (c == '(') {
            const qsizetype close = m_text.indexOf(')', m_at);
            if (close < 0)
                return fail(tr("a comment \"(\" is never closed on this line."));
            m_at = close + 1;
        } else if (c == ';' || (c == '/' && m_at + 1 < n && m_text.at(m_at + 1) == '/')) {
            break;
        } else if (isLetter(c) && m_at + 1 < n && isLetter(m_text.at(m_at + 1))) {
            QByteArrayView call = m_text.sliced(m_at);
            if (const qsizetype comment = call.indexOf("//"); comment >= 0)
                call = call.first(comment);
            m_call = call.trimmed();
            m_at = n;
            return Token::Call;
        } else if (isLetter(c)) {
            return readWord(upper(c));
        } else {
            return fail(tr("unexpected \"%1\".").arg(QChar::fromLatin1(c)));
        }
    }
    m_at = n;
    return Token::End;
}

GCodeLexer::Token GCodeLexer::readWord(char letter)
{
    const qsizetype n = m_text.size();
    const qsizetype start = m_at;
    qsizetype j = m_at + 1;
    while (j < n && m_text.at(j) == ' ')
        ++j;
    qsizetype k = j;
    while (k < n && isNumberChar(m_text.at(k)))
        ++k;
    m_word = GCodeWord { letter, 0.0, k == j, m_text.sliced(start, (k == j ? start + 1 : k) - start) };
    m_at = k == j ? start + 1 : k;
    if (k == j)
        return Token::Word;
    const QByteArrayView digits = m_text.sliced(j, k - j);
    const auto v = parseDecimal(digits);
    if (!v)
        return fail(tr("\"%1\" is not a number.").arg(QString::fromUtf8(digits)));
    // Controllers take at most eight digits before the point (FANUC's +-99999999). The bound also keeps every
    // position a program can reach finite: without it, two G91 moves of 1e308 end at infinity.
    if (std::fabs(*v) > Limits::kMaxWordValue)
        return fail(tooLarge(m_word.text));
    m_word.value = *v;
    return Token::Word;
}

QString GCodeLexer::tooLarge(QByteArrayView word)
{
    return tr("%1 is too large: a controller takes at most eight digits before the decimal point.")
        .arg(QString::fromUtf8(word));
}

Result<GCodeBlock> GCodeBlock::read(QByteArrayView block)
{
    GCodeBlock out;
    GCodeLexer lexer(block);
    for (;;) {
        switch (lexer.next()) {
        case GCodeLexer::Token::End:
            return out;
        case GCodeLexer::Token::Word:
            out.words.append(lexer.word());
            break;
        case GCodeLexer::Token::Call:
            return Error { GCodeLexer::tr("\"%1\" is not G-code this controller reads.")
                               .arg(QString::fromUtf8(lexer.call())) };
        case GCodeLexer::Token::Error:
            return Error { lexer.error() };
        }
    }
}

bool GCodeBlock::has(char letter, double value) const
{
    return std::any_of(words.cbegin(), words.cend(),
        [&](const GCodeWord &w) { return w.letter == letter && !w.bare && same(w.value, value); });
}

const GCodeWord *GCodeBlock::find(char letter) const
{
    for (const GCodeWord &w : words) {
        if (w.letter == letter)
            return &w;
    }
    return nullptr;
}

std::optional<double> GCodeBlock::value(char letter) const
{
    const GCodeWord *w = find(letter);
    return w && !w->bare ? std::optional(w->value) : std::nullopt;
}

} // namespace Toffee
