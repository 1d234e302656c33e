// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cmath>
#include <optional>

#include <QByteArrayView>
#include <QCoreApplication>
#include <QString>
#include <QVarLengthArray>

#include "model/limits.h"
#include "model/result.h"
#include "model/textparsing.h"

namespace Toffee {

// One word of a G-code block: a letter and the number after it.
struct GCodeWord
{
    char letter = 0; // upper case
    double value = 0.0;
    bool bare = false; // a letter with no number, as Aerotech writes "G44 X Y Z"
    QByteArrayView text; // the word as written ("z-30.5"), for messages; a view into the block
};

// Reads a block's words in order, as the controllers read them: letters in either case, blanks allowed
// between a letter and its number, '%' and blanks skipped, "( )" comments dropped, ';' and "//" ending the
// block. Two letters in a row start a function call (Aerotech's "CutterCompensationSetAxes X Y"). The one
// tokenizer of Toffee: the interpreter, the emulator and the console's check all read G-code through it.
class GCodeLexer
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::GCodeLexer)

public:
    enum class Token { Word, Call, End, Error };

    explicit GCodeLexer(QByteArrayView block)
        : m_text(block)
    { }

    // The next token; after End or Error, End again. Inline: the interpreter reads millions of words a
    // second.
    [[nodiscard]] inline Token next();
    // After Token::Word.
    [[nodiscard]] const GCodeWord &word() const { return m_word; }
    // After Token::Call: the call, to the end of the block less a trailing comment, trimmed.
    [[nodiscard]] QByteArrayView call() const { return m_call; }
    // After Token::Error: what is wrong, in a sentence an operator can act on.
    [[nodiscard]] const QString &error() const { return m_error; }

    // The message for a number no controller takes.
    [[nodiscard]] static QString tooLarge(QByteArrayView word);

private:
    static bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
    static bool isNumberChar(char c) { return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+'; }
    inline Token readWord(char letter);
    Token fail(QString message);
    Token failUnclosedComment();
    Token failUnexpected(char c);
    Token failNumber(QByteArrayView digits);

    QByteArrayView m_text;
    qsizetype m_at = 0;
    GCodeWord m_word;
    QByteArrayView m_call;
    QString m_error;
};

// A block read whole into its words, for code that looks at a few letters of a line (the emulator, the
// console's check). The words are views into the block, which must outlive them.
struct GCodeBlock
{
    QVarLengthArray<GCodeWord, 8> words;

    // The block's words; an error for what the lexer refuses and for a function call.
    [[nodiscard]] static Result<GCodeBlock> read(QByteArrayView block);

    [[nodiscard]] bool isEmpty() const { return words.isEmpty(); }
    // Whether the block has this word with this number (M491.1 is not M491).
    [[nodiscard]] bool has(char letter, double value) const;
    // The first word with this letter, or nullptr.
    [[nodiscard]] const GCodeWord *find(char letter) const;
    // The number of the first word with this letter; nothing when there is none or it has no number.
    [[nodiscard]] std::optional<double> value(char letter) const;
};

inline GCodeLexer::Token GCodeLexer::next()
{
    const qsizetype n = m_text.size();
    while (m_at < n) {
        const char c = m_text.at(m_at);
        if (c == ' ' || c == '\t' || c == '\r' || c == '%') {
            ++m_at;
        } else if (c == '(') {
            const qsizetype close = m_text.indexOf(')', m_at);
            if (close < 0)
                return failUnclosedComment();
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
            return readWord(c >= 'a' ? char(c - 'a' + 'A') : c);
        } else {
            return failUnexpected(c);
        }
    }
    m_at = n;
    return Token::End;
}

inline GCodeLexer::Token GCodeLexer::readWord(char letter)
{
    const qsizetype n = m_text.size();
    const qsizetype start = m_at;
    qsizetype j = m_at + 1;
    while (j < n && m_text.at(j) == ' ')
        ++j;
    qsizetype k = j;
    while (k < n && isNumberChar(m_text.at(k)))
        ++k;
    m_word.letter = letter;
    m_word.value = 0.0;
    m_word.bare = k == j;
    m_word.text = m_text.sliced(start, (k == j ? start + 1 : k) - start);
    m_at = k == j ? start + 1 : k;
    if (k == j)
        return Token::Word;
    const QByteArrayView digits = m_text.sliced(j, k - j);
    const auto v = parseDecimal(digits);
    if (!v)
        return failNumber(digits);
    // Controllers take at most eight digits before the point (FANUC's +-99999999). The bound also keeps every
    // position a program can reach finite: without it, two G91 moves of 1e308 end at infinity.
    if (std::fabs(*v) > Limits::kMaxWordValue)
        return fail(tooLarge(m_word.text));
    m_word.value = *v;
    return Token::Word;
}

} // namespace Toffee
