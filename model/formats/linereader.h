// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <QByteArray>
#include <QByteArrayView>
#include <QCoreApplication>
#include <QString>

#include "model/formats/fileio.h"
#include "model/result.h"

namespace Toffee {

// Reads a file a line at a time through a buffer of its own, so that memory follows the longest line and not
// the file: a program of five million lines is read in the same megabyte as one of five. Lines end at "\n"
// ("\r\n" too); the last one needs no end. Only regular files are opened (openRegularFile).
class LineReader
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::LineReader)
    Q_DISABLE_COPY_MOVE(LineReader)

public:
    // No line is longer (a G-code block is a few dozen bytes): a longer one is an error, not a reason to
    // grow.
    static constexpr qsizetype kMaxLineBytes = 64 * 1024;

    LineReader() = default;
    [[nodiscard]] Result<void> open(const QString &path);

    // The next line, valid until the next call; false at the end or on an error (see error()).
    [[nodiscard]] bool next(QByteArrayView &line);
    [[nodiscard]] const std::optional<Error> &error() const { return m_error; }
    // The line next() gave last, 1-based.
    [[nodiscard]] int lineNumber() const { return m_line; }
    [[nodiscard]] qint64 bytesRead() const { return m_consumed; }
    [[nodiscard]] qint64 size() const { return m_file.size; }
    [[nodiscard]] const QString &path() const { return m_path; }

private:
    [[nodiscard]] bool fill();
    [[nodiscard]] bool checked(QByteArrayView &line);

    static constexpr qsizetype kBufferBytes = 1024 * 1024;
    QString m_path;
    OpenFile m_file;
    QByteArray m_buffer;
    qsizetype m_start = 0; // the first byte not yet given out
    qsizetype m_end = 0; // the end of what the buffer holds
    bool m_eof = false;
    int m_line = 0;
    qint64 m_consumed = 0; // bytes of the file given out as lines
    std::optional<Error> m_error;
};

} // namespace Toffee
