// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/formats/linereader.h"

#include <cstring>

namespace Toffee {

Result<void> LineReader::open(const QString &path)
{
    auto file = openRegularFile(path);
    if (!file)
        return file.error();
    m_path = path;
    std::swap(m_file.fd, file.value().fd);
    m_file.size = file.value().size;
    m_buffer.resize(kBufferBytes);
    return {};
}

// Moves what is left to the front of the buffer and reads after it; false at the end or on an error.
bool LineReader::fill()
{
    if (m_eof || m_error)
        return false;
    if (m_start > 0) {
        std::memmove(m_buffer.data(), m_buffer.constData() + m_start, size_t(m_end - m_start));
        m_end -= m_start;
        m_start = 0;
    }
    const auto n = readSome(m_file, m_buffer.data() + m_end, m_buffer.size() - m_end, m_path);
    if (!n) {
        m_error = n.error();
        return false;
    }
    if (n.value() == 0)
        m_eof = true;
    m_end += qsizetype(n.value());
    return n.value() > 0;
}

// A text line: a UTF-8 byte-order mark before the first is dropped; a NUL byte is no text's.
bool LineReader::checked(QByteArrayView &line)
{
    if (m_line == 1 && line.startsWith("\xEF\xBB\xBF"))
        line = line.sliced(3);
    if (std::memchr(line.data(), '\0', size_t(line.size()))) {
        m_error = Error {
            tr("line %1 holds a NUL byte: this is not a text program (UTF-16, or not text at all?). "
               "Save it as plain text (UTF-8 or ASCII).")
                .arg(m_line),
            m_line, m_path
        };
        return false;
    }
    return true;
}

bool LineReader::next(QByteArrayView &line)
{
    if (m_file.fd < 0 || m_error)
        return false;
    for (;;) {
        const char *begin = m_buffer.constData() + m_start;
        const auto available = size_t(m_end - m_start);
        if (const auto *newline = static_cast<const char *>(std::memchr(begin, '\n', available))) {
            qsizetype length = newline - begin;
            m_start += length + 1;
            m_consumed += length + 1;
            if (length > 0 && begin[length - 1] == '\r')
                --length;
            if (length > kMaxLineBytes)
                break;
            ++m_line;
            line = QByteArrayView(begin, length);
            return checked(line);
        }
        if (qsizetype(available) > kMaxLineBytes)
            break;
        if (!fill()) {
            if (m_error || m_start == m_end)
                return false;
            // The last line, with no end of its own.
            qsizetype length = m_end - m_start;
            line = QByteArrayView(m_buffer.constData() + m_start, length);
            m_consumed += length;
            m_start = m_end;
            ++m_line;
            if (line.endsWith('\r'))
                line.chop(1);
            return checked(line);
        }
    }
    m_error = Error {
        tr("line %1 is longer than %2 KB; no program line is.").arg(m_line + 1).arg(kMaxLineBytes / 1024),
        m_line + 1, m_path
    };
    return false;
}

} // namespace Toffee
