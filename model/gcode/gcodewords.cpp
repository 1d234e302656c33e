// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/gcode/gcodewords.h"

#include <cmath>

#include "model/textparsing.h"

namespace Toffee {

namespace {

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

GCodeLexer::Token GCodeLexer::failUnclosedComment()
{
    return fail(tr("a comment \"(\" is never closed on this line."));
}

GCodeLexer::Token GCodeLexer::failUnexpected(char c)
{
    // A byte that is not a printable character is named, not printed: it could be a terminal's control code.
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f)
        return fail(tr("unexpected byte 0x%1.").arg(byte, 2, 16, QLatin1Char('0')));
    return fail(tr("unexpected \"%1\".").arg(QChar::fromLatin1(c)));
}

GCodeLexer::Token GCodeLexer::failNumber(QByteArrayView digits)
{
    return fail(tr("\"%1\" is not a number.").arg(QString::fromUtf8(digits)));
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
