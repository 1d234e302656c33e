// SPDX-License-Identifier: GPL-3.0-or-later
// A pseudo-terminal as a program's input, as when an operator types toffee-cli's command at the machine: a
// step that waits for a person (a manual tool change) is then allowed, Enter typed here is the person's "the
// tool is in", and hanging up is a terminal that closed. Without one (QProcess's pipe) nobody counts as
// there.
#pragma once

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <QByteArray>
#include <QProcess>

namespace Toffee::Test {

class Terminal
{
public:
    Terminal()
    {
        m_master = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
        if (m_master >= 0 && ::grantpt(m_master) == 0 && ::unlockpt(m_master) == 0)
            m_slave = QByteArray(::ptsname(m_master));
    }
    ~Terminal() { hangUp(); }
    Terminal(const Terminal &) = delete;
    Terminal &operator=(const Terminal &) = delete;

    [[nodiscard]] bool isOpen() const { return m_master >= 0 && !m_slave.isEmpty(); }
    // The process's standard input becomes this terminal (set before it starts).
    void attach(QProcess &process) const
    {
        const QByteArray slave = m_slave;
        process.setChildProcessModifier([slave] {
            const int fd = ::open(slave.constData(), O_RDWR | O_NOCTTY);
            if (fd >= 0) {
                ::dup2(fd, STDIN_FILENO);
                ::close(fd);
            }
        });
    }
    void type(const QByteArray &text) const
    {
        if (m_master >= 0)
            (void)!::write(m_master, text.constData(), size_t(text.size()));
    }
    // The terminal closes: the program reads end of input.
    void hangUp()
    {
        if (m_master >= 0)
            ::close(m_master);
        m_master = -1;
    }

private:
    int m_master = -1;
    QByteArray m_slave;
};

} // namespace Toffee::Test
