// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QByteArrayView>
#include <QCoreApplication>
#include <QString>
#include <QVarLengthArray>

#include "model/result.h"

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

    // The next token; after End or Error, End again.
    [[nodiscard]] Token next();
    // After Token::Word.
    [[nodiscard]] const GCodeWord &word() const { return m_word; }
    // After Token::Call: the call, to the end of the block less a trailing comment, trimmed.
    [[nodiscard]] QByteArrayView call() const { return m_call; }
    // After Token::Error: what is wrong, in a sentence an operator can act on.
    [[nodiscard]] const QString &error() const { return m_error; }

    // The message for a number no controller takes.
    [[nodiscard]] static QString tooLarge(QByteArrayView word);

private:
    Token fail(QString message);
    Token readWord(char letter);

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

} // namespace Toffee
