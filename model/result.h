// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>
#include <utility>

#include <QString>

namespace Toffee {

// An operator-facing failure: what went wrong and, for files, the line it went wrong on.
struct Error
{
    Error() = default;
    Error(QString message, int line = 0, QString file = {})
        : message(std::move(message))
        , line(line)
        , file(std::move(file))
    { }

    QString message;
    int line = 0; // 1-based; 0 when the error belongs to no line
    QString file; // the file it is in, when there is one
    // What kind of failure, for the caller that acts on it (Library::kUnreachable); empty for most.
    QString code = {};

    // "file: line 3: message", leaving out what is not known.
    [[nodiscard]] QString text() const;
};

// Errors are values: a Result holds either the value or the Error, never both, never neither.
template<typename T> class [[nodiscard]] Result
{
public:
    Result(T value)
        : m_value(std::move(value))
    { }
    Result(Error error)
        : m_error(std::move(error))
    { }

    [[nodiscard]] bool ok() const { return m_value.has_value(); }
    explicit operator bool() const { return ok(); }
    [[nodiscard]] const T &value() const { return *m_value; }
    [[nodiscard]] T &value() { return *m_value; }
    [[nodiscard]] T takeValue() { return std::move(*m_value); }
    [[nodiscard]] const Error &error() const { return m_error; }

private:
    std::optional<T> m_value;
    Error m_error;
};

template<> class [[nodiscard]] Result<void>
{
public:
    Result() = default;
    Result(Error error)
        : m_failed(true)
        , m_error(std::move(error))
    { }

    [[nodiscard]] bool ok() const { return !m_failed; }
    explicit operator bool() const { return ok(); }
    [[nodiscard]] const Error &error() const { return m_error; }

private:
    bool m_failed = false;
    Error m_error;
};

} // namespace Toffee
